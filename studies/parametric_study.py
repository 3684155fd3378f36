"""Sections 3.4-3.5 of the thesis: the parametric study over n x Lc x lambda, its optimum,
and beyond it (continuous optimisation under constraints, sensitivity at the optimum).

--quick (default) runs the 20 x 20 x 4 study that ``make demo`` shows through the report
(``kresling.report.sections.sweeps``); --full the thesis's 100 x 100 x 4 (resumable: run it again
with the same --out after an interruption). Prints the checks, the maxima per n and the
optimum; writes the figures and the sweep's results.csv under --out.

Run: ``python studies/parametric_study.py [--full] [--workers W] [--out out/parametric_study]``
"""

import argparse
import time
from pathlib import Path

import matplotlib

from kresling.sweeps import conclusions
from kresling.sweeps.optimize import optimize_design
from kresling.report.sections.sweeps import reproduce
from kresling.sweeps.table import SweepTable

matplotlib.use("Agg")


def print_section(section) -> None:
    print(section.summary.replace(". ", ".\n"))
    print(f"\n{sum(c.passed for c in section.checks)}/{len(section.checks)} checks pass:")
    for check in section.checks:
        mark = "ok  " if check.passed else "FAIL"
        print(f"  {mark} {check.name}: {check.value:.6g} (reference {check.reference:.6g}, "
              f"{check.source})")


def print_maxima(table: SweepTable) -> None:
    print("\nmaximum per n (value at Lc [mm], lambda; * on the edge of the grid)")
    for metric in [m for m in ("kb_ratio", "psi_ratio", "snap_force") if m in table]:
        cells = [f"n={n}: {r[metric]:.4g} at ({r['Lc']:.4g}, {r['lam']:.4g})"
                 + ("*" if r["boundary"] else "")
                 for n, r in conclusions.maxima_by_n(table, metric).items()]
        print(f"  {metric:10s} " + "; ".join(cells))


def print_constrained_optima(workers) -> None:
    print("\nbeyond the grid: best K_B ratio of each n under designer's constraints")
    cases = {"free (thesis bounds)": {}, "lambda <= 0.85 (less tearing)": {"lam": (0.7, 0.85)},
             "K_con >= 0.3 N*m/rad (joint not too soft)": {"constraints": {"kb_con": (0.3, None)}},
             "K_con >= 0.3 N*m/rad and snap force >= 8.6 N":
                 {"constraints": {"kb_con": (0.3, None), "snap_force": (8.6, None)}},
             "K_ext >= 3.5 N*m/rad (stiff link)": {"constraints": {"kb_ext": (3.5, None)}}}
    for name, options in cases.items():
        cells = []
        for n in (4, 6, 8, 10):
            r = optimize_design(n, workers=workers, **options)
            cells.append(f"n={n}: {r.value:.3g} at ({r.design.Lc:.3g}, {r.design.lam:.3g})"
                         + ("" if r.success else " [infeasible]"))
        print(f"  {name}\n    " + "; ".join(cells))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--full", action="store_true", help="100 x 100 per n (the thesis's)")
    parser.add_argument("--workers", type=int, help="parallel workers (default: every core)")
    parser.add_argument("--out", default="out/parametric_study", type=Path)
    args = parser.parse_args()
    start = time.perf_counter()
    section = reproduce(args.out, quick=not args.full, workers=args.workers)
    print_section(section)
    size = 100 if args.full else 20
    print_maxima(SweepTable.read_csv(args.out / f"sweep_{size}" / "results.csv"))
    print_constrained_optima(args.workers)
    print(f"\n{time.perf_counter() - start:.1f} s; figures and tables in {args.out}")


if __name__ == "__main__":
    main()
