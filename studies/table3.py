"""Table 3 side by side: our bending test, the MERLIN2 reference runs, the thesis's model and
experimental columns; the linearised K_B beside the 0.001 rad protocol; and how much
MERLIN2's duplicated topology moves K_B.

Run: ``python studies/table3.py [--protocol 5mm|0.001rad] [--csv table3.csv]``
"""

import argparse
import csv
import math

from kresling.analyses import bending_test, linear_bending_stiffness
from kresling.analyses.table3 import table3_comparison, topology_effect


def _cell(value, digits=4):
    return "-" if value is None or (isinstance(value, float) and math.isnan(value)) \
        else f"{value:.{digits}f}"


def print_table3(rows) -> None:
    print("Table 3, K_B in N*m/rad: ours | MERLIN2 reference | thesis model | thesis experiment")
    for quantity in ("extended", "contracted", "ratio"):
        print(f"\n  {quantity}")
        print(f"  {'design':24s} {'ours':>9s} {'MERLIN2':>9s} {'rel diff':>9s} "
              f"{'thesis':>7s} {'exp':>7s} {'exp SD':>7s}")
        for entry in rows:
            d, ours = entry.design, entry.ours_values[quantity]
            ref = entry.reference[quantity]
            e = entry.experiment
            sd = e.get(f"{quantity}_sd", math.nan)
            print(f"  n={d.n:<2d} Lc={d.Lc:<4g} lam={d.lam:<4g}      {ours:9.5f} {ref:9.5f} "
                  f"{ours / ref - 1:9.1e} {_cell(entry.thesis_model[quantity], 2):>7s} "
                  f"{_cell(e.get(quantity), 2):>7s} {_cell(sd, 2):>7s}")
    print("\n  experimental ratio as printed vs recomputed from the printed means:")
    for entry in rows:
        d, e = entry.design, entry.experiment
        print(f"  n={d.n:<2d} Lc={d.Lc:<4g} lam={d.lam:<4g}  printed {e['ratio']:6.2f}  "
              f"of means {e['ratio_of_means']:6.2f}  model {entry.ours.ratio:6.2f}")


def print_linear(rows) -> None:
    print("\nLinearised K_B (Appendix A's model) vs the nonlinear 0.001 rad protocol")
    for entry in rows:
        d = entry.design
        for state in (1, 0):
            nonlinear = bending_test(d, state, "0.001rad").stiffness
            linear = linear_bending_stiffness(d, state)
            print(f"  n={d.n:<2d} Lc={d.Lc:<4g} lam={d.lam:<4g} state {state}: linear "
                  f"{linear:.6f}  nonlinear {nonlinear:.6f}  rel diff {linear / nonlinear - 1:.1e}")


def print_topology() -> None:
    print("\nOne bar and hinge per edge instead of MERLIN2's duplicates (5 mm): relative change")
    for row in topology_effect():
        print(f"  n={row['n']:<2d} Lc={row['Lc_mm']:<4g} lam={row['lambda']:<4g}  "
              f"K_ext {100 * row['extended']:+6.2f} %  K_con {100 * row['contracted']:+6.2f} %  "
              f"ratio {100 * row['ratio']:+6.2f} %")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--protocol", default="5mm", choices=("5mm", "0.001rad"))
    parser.add_argument("--csv", help="also write the side-by-side table here")
    parser.add_argument("--skip-extras", action="store_true",
                        help="only Table 3 (no linear model, no topology comparison)")
    args = parser.parse_args(argv)
    rows = table3_comparison(args.protocol)
    print_table3(rows)
    if args.csv:
        with open(args.csv, "w", newline="") as handle:
            writer = csv.DictWriter(handle, fieldnames=list(rows[0].row()), lineterminator="\n")
            writer.writeheader()
            writer.writerows(entry.row() for entry in rows)
    if not args.skip_extras:
        print_linear(rows)
        print_topology()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
