"""Appendix A's orientation study with the linearised model: K_B against the bending axis
angle (figure A-1), and the effect of turning only the pin line against the load.

Run: ``python studies/orientation.py [--out out/orientation] [--points 25]``
"""

import argparse
import math
from pathlib import Path

from kresling import Design
from kresling.analyses import linear_bending_stiffness
from kresling.analyses.orientation import orientation_study
from kresling.analyses.plots import plot_orientation_study


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="out/orientation", help="folder for the PNG file")
    parser.add_argument("--points", type=int, default=25, help="angles over one period 2 pi/n")
    args = parser.parse_args(argv)
    studies = [orientation_study(Design(n, 0.9, 15), points=args.points) for n in (4, 6, 8, 10)]
    print("Spread (max - min) / mean over the bending axis angle, Lc = 15, lambda = 0.9")
    for s in studies:
        print(f"  n={s.design.n:<2d}  K_ext {100 * s.variation('extended'):.4f} %  K_con "
              f"{100 * s.variation('contracted'):.4f} %  ratio {100 * s.variation():.4f} %  "
              f"(ratio {s.ratio.mean():.3f})")
    print("\nTurning only the pin line by pi/n against the load (docs/thesis_equations.md, 'Bending test': 4-65 %)")
    for s in studies:
        d = s.design
        changes = [linear_bending_stiffness(d, state, pin_offset=math.pi / d.n) /
                   linear_bending_stiffness(d, state) - 1 for state in (1, 0)]
        print(f"  n={d.n:<2d}  K_ext {100 * changes[0]:+6.1f} %  K_con {100 * changes[1]:+6.1f} %")
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    figure = Figure(figsize=(10.0, 4.0), layout="constrained")
    plot_orientation_study(studies, figure.subplots(1, 2))
    figure.savefig(out / "figure_A_1.png", dpi=150)
    print(f"\nfigure A-1 -> {out / 'figure_A_1.png'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
