"""Snap-through (section 3.5): figure 3.16, the Table 3 designs, and figure 3.17's trends
along lines through the design space, with the bistability verdict of each design.

Run: ``python studies/snap_through.py [--out out/snap] [--steps 100]``
"""

import argparse
from pathlib import Path

import numpy as np

from kresling import Design
from kresling.analyses import SnapThroughTester, snap_through
from kresling.analyses.plots import plot_snap_through
from kresling.analyses.table3 import TABLE3_DESIGNS


def print_designs(steps: int) -> None:
    print("Table 3 designs (one cell, Le -> Lc): snap force [N] at travel [mm], energy barrier "
          "[N*mm], bistability")
    for n, Lc, lam in TABLE3_DESIGNS:
        r = snap_through(Design(n, lam, Lc), steps=steps)
        print(f"  n={n:<2d} Lc={Lc:<4g} lam={lam:<4g}  {r.snap_force:6.3f} N at "
              f"{r.snap_displacement:5.2f} mm  barrier {r.energy_barrier:7.2f}  "
              f"min force {r.minimum_force:6.3f} N  {r.bistability}")


def print_trends(steps: int) -> None:
    print("\nFigure 3.17's trends: snap force [N] along lambda (Lc = 20) and along Lc "
          "(lambda = 0.85); * = bistable")
    lams, Lcs = np.linspace(0.7, 0.9, 5), np.linspace(15, 60, 5)
    for n in (4, 6, 8, 10):
        tester = SnapThroughTester(n, steps=steps)
        along_lam = [tester.run(Design(n, lam, 20)) for lam in lams]
        along_Lc = [tester.run(Design(n, 0.85, Lc)) for Lc in Lcs]
        text = lambda rs: "  ".join(f"{r.snap_force:5.2f}{'*' if r.bistable else ' '}" for r in rs)
        print(f"  n={n:<2d} lambda {lams[0]:.2f}..{lams[-1]:.2f}: {text(along_lam)}")
        print(f"       Lc {Lcs[0]:.0f}..{Lcs[-1]:.0f} mm:       {text(along_Lc)}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="out/snap", help="folder for the PNG file")
    parser.add_argument("--steps", type=int, default=100, help="increments from Le to Lc")
    args = parser.parse_args(argv)
    print_designs(args.steps)
    print_trends(args.steps)
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    figure = Figure(figsize=(6.0, 4.2), layout="constrained")
    plot_snap_through(snap_through(Design(8, 0.8, 30), steps=args.steps), figure.add_subplot())
    figure.savefig(out / "figure_3_16.png", dpi=150)
    print(f"\nfigure 3.16 -> {out / 'figure_3_16.png'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
