"""The parametric study's figures and tables for the report (figures 3.9-3.13, 3.17, the
sensitivity at the optimum, the maxima by n)."""

from __future__ import annotations

import csv
import shutil
from pathlib import Path

import matplotlib.pyplot as plt

from kresling.report.section import Section
from kresling.sweeps import conclusions as c
from kresling.sweeps.designs import THESIS_N
from kresling.sweeps.plots import plot_maps, plot_max_by_n, plot_ratio_maps

__all__ = ["add_figures"]

_THESIS_FIGURE = dict(zip(THESIS_N, ("3.9", "3.10", "3.11", "3.12")))


def add_figures(section: Section, table, out_dir: Path, sensitivity_figure) -> None:
    """Write every figure and table of the section into ``out_dir`` and list them."""
    for n in THESIS_N:
        figure = plot_ratio_maps(table, n)
        _save(section, figure, out_dir / f"figure_{_THESIS_FIGURE[n].replace('.', '_')}_n{n}.png",
              f"Figure {_THESIS_FIGURE[n]}: (a) K_B ratio (0.001 rad) and (b) facet-angle ratio "
              f"Psi_ext/Psi_con over Lc x lambda for n = {n}; the star marks each map's maximum.")
    ax = plot_max_by_n(table, "kb_ratio")
    _save(section, ax.figure, out_dir / "figure_3_13_max_ratio_by_n.png",
          "Figure 3.13: the largest K_B ratio (0.001 rad) of each n, and where it is.")
    _save(section, plot_maps(table, "snap_force"), out_dir / "figure_3_17_snap_force.png",
          "Figure 3.17: snap-through force (first local maximum of the force driving one cell "
          "from extended to contracted) over Lc x lambda for each n; blank where the force "
          "has no maximum.")
    _save(section, plot_maps(table, "energy_barrier"), out_dir / "energy_barrier.png",
          "Beyond the thesis: the energy barrier (strain energy at the unstable state) over "
          "Lc x lambda for each n; blank where the cell is monostable.")
    _save(section, sensitivity_figure, out_dir / "sensitivity_at_optimum.png",
          "Beyond the thesis: the K_B ratio along Lc and along lambda from the optimum "
          "(n = 10, Lc = 15 mm, lambda = 0.9), relative to its value there; dots mark where "
          "it has fallen to 90 %, 75 % and 50 %.")
    plt.close("all")
    _tables(section, table, out_dir)


def _tables(section: Section, table, out_dir: Path) -> None:
    path = out_dir / "maxima_by_n.csv"
    metrics = [m for m in ("kb_ratio", "psi_ratio", "snap_force") if m in table]
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["metric", "n", "max", "Lc_mm", "lam", "on_boundary"])
        for metric in metrics:
            for n, row in c.maxima_by_n(table, metric).items():
                writer.writerow([metric, n, f"{row[metric]:.6g}", f"{row['Lc']:.6g}",
                                 f"{row['lam']:.6g}", "; ".join(row["boundary"])])
    section.add_table(path, "The largest value of each metric for each n and where it is; "
                            "on_boundary names the edges of the searched grid it lies on (a "
                            "maximum there may be beaten just outside the grid).")
    source = Path(table.attrs["out"]) / "results.csv"
    results = out_dir / "sweep_results.csv"
    shutil.copyfile(source, results)
    section.add_table(results, "Every design of the sweep: parameters, K_B of each state and "
                               "their ratio (0.001 rad), Psi of each state and their ratio, "
                               "snap force and its travel, energy barrier, bistable, status, "
                               "Newton iterations and compute time.")


def _save(section: Section, figure, path: Path, caption: str) -> None:
    figure.savefig(path, dpi=100)
    section.add_figure(path, caption)
