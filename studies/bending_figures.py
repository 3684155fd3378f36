"""Figures 3.5-3.7 and 3.15 (moment-angle curves of the Table 3 designs, both states, with
the MERLIN2 reference runs and the thesis's measured K_B) and figure 3.14 (the optimum's
family: n = 4-10 at Lc = 15 mm, lambda = 0.9, 5 mm protocol).

Run: ``python studies/bending_figures.py [--out out/bending]``
"""

import argparse
from pathlib import Path

from kresling import Design
from kresling.analyses import bending_stiffness
from kresling.analyses.plots import plot_stiffness_by_n, plot_table3_design
from kresling.analyses.table3 import table3_comparison
from kresling.fits.thesis_tables import merlin2_model_curves

FIGURES = {(8, 30.0, 0.8): "3.5", (8, 15.0, 0.8): "3.6", (4, 30.0, 0.7): "3.7",
           (10, 15.0, 0.9): "3.15"}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="out/bending", help="folder for the PNG files")
    args = parser.parse_args(argv)
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    curves = merlin2_model_curves()
    for entry in table3_comparison():
        d = entry.design
        key = (d.n, d.Lc, d.lam)
        figure = Figure(figsize=(6.0, 4.4), layout="constrained")
        plot_table3_design(entry, figure.add_subplot(), curves.get(key))
        path = out / f"figure_{FIGURES[key].replace('.', '_')}.png"
        figure.savefig(path, dpi=150)
        print(f"figure {FIGURES[key]}: n={d.n} Lc={d.Lc:g} lam={d.lam:g}  K_ext "
              f"{entry.ours.extended.stiffness:.4f}  K_con {entry.ours.contracted.stiffness:.4f}  "
              f"ratio {entry.ours.ratio:.3f}  -> {path}")
    by_n = {n: bending_stiffness(Design(n, 0.9, 15)) for n in (4, 6, 8, 10)}
    figure = Figure(figsize=(10.0, 4.0), layout="constrained")
    plot_stiffness_by_n(by_n, figure.subplots(1, 2))
    path = out / "figure_3_14.png"
    figure.savefig(path, dpi=150)
    print("figure 3.14 (Lc=15, lam=0.9, 5 mm): " + ", ".join(
        f"n={n}: {c.extended.stiffness:.3f}/{c.contracted.stiffness:.3f} ratio {c.ratio:.2f}"
        for n, c in by_n.items()) + f"  -> {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
