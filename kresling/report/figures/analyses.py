"""Figures of the analyses section of the report (see :mod:`kresling.report.sections.analyses`):
3.5-3.7 and 3.15, 3.14, 3.16, A-1 and 3D views of the optimal specimen, plus its FOLD file,
and two interactive views of the optimum (its bending test in both states, its
snap-through), saved as plotly JSON and drawn in the page.

Figures are drawn on ``matplotlib.figure.Figure`` objects (no pyplot state)."""

from __future__ import annotations

from pathlib import Path

from matplotlib.figure import Figure

from kresling.analyses.bending import bending_stiffness, bending_test
from kresling.analyses.plots import (plot_orientation_study, plot_snap_through,
                                     plot_stiffness_by_n, plot_table3_design)
from kresling.analyses.snap_through import snap_through
from kresling.analyses.specimen_views import plot_specimen, write_specimen_fold
from kresling.data.tables import merlin2_model_curves
from kresling.geometry import Design
from kresling.model.kresling_specimen import kresling_specimen
from kresling.report.section import Section
from kresling.view import view_bending, view_snap_through

__all__ = ["draw_figures", "VIEW_FRAMES"]

#: Frames of the interactive views (quick, full): the page stays a few MB and the views take
#: well under a second to build; the curves keep every increment.
VIEW_FRAMES = {True: 36, False: 71}

#: Thesis figure of each Table 3 design's curves.
FIGURES = {(8, 30.0, 0.8): "3.5", (8, 15.0, 0.8): "3.6", (4, 30.0, 0.7): "3.7",
           (10, 15.0, 0.9): "3.15"}


def _save(figure, section: Section, path: Path, caption: str) -> None:
    figure.savefig(path, dpi=100)
    section.add_figure(path, caption)


def draw_figures(section: Section, out_dir: Path, table, studies, quick: bool) -> None:
    """Draw every figure into ``out_dir`` and add it to ``section``: ``table`` from
    :func:`~kresling.analyses.table3.table3_comparison`, ``studies`` the orientation studies
    of figure A-1."""
    curves = merlin2_model_curves()
    figure = Figure(figsize=(11.0, 8.5), layout="constrained")
    for ax, entry in zip(figure.subplots(2, 2).ravel(), table):
        d = entry.design
        plot_table3_design(entry, ax, curves.get((d.n, d.Lc, d.lam)))
        ax.set_title(f"figure {FIGURES.get((d.n, d.Lc, d.lam), '')}: " + ax.get_title(),
                     fontsize=8)
    _save(figure, section, out_dir / "figures_3_5_to_3_7.png",
          "Figures 3.5-3.7 and 3.15: moment against deflection angle of the four Table 3 "
          "designs in both states (5 mm protocol). Solid: ours; dotted black: the MERLIN2 "
          "reference runs (indistinguishable); dash-dot with a band: the thesis's measured K_B "
          "± 1 SD as lines M = K delta (it publishes no raw curves).")

    by_n = {n: bending_stiffness(Design(n, 0.9, 15)) for n in (4, 6, 8, 10)}
    figure = Figure(figsize=(10.0, 4.0), layout="constrained")
    plot_stiffness_by_n(by_n, figure.subplots(1, 2))
    ratios = ", ".join(f"n={n}: {c.ratio:.2f}" for n, c in by_n.items())
    _save(figure, section, out_dir / "figure_3_14.png",
          f"Figure 3.14: Lc = 15 mm, lambda = 0.9, 5 mm protocol. (a) Moment-angle curves by "
          f"n; (b) the K_B ratio by n ({ratios}): it rises with n while both K_B fall.")

    figure = Figure(figsize=(6.0, 4.2), layout="constrained")
    result = snap_through(Design(8, 0.8, 30), steps=100 if quick else 400)
    plot_snap_through(result, figure.add_subplot())
    _save(figure, section, out_dir / "figure_3_16.png",
          "Figure 3.16: force against the drive's travel from the extended state, n = 8, "
          "Lc = 30 mm, lambda = 0.8 (one cell, bottom fixed, top driven to Lc and free to "
          "twist). The snap force is the first local maximum. Our curve dips slightly below "
          "zero (the thesis's did not): the unstable state and a second stable state follow.")

    figure = Figure(figsize=(10.0, 4.0), layout="constrained")
    plot_orientation_study(studies, figure.subplots(1, 2))
    _save(figure, section, out_dir / "figure_A_1.png",
          "Figure A-1: linearised K_B ratio (left) and each state's K_B relative to beta = 0 "
          "(right) against the bending axis angle over one period 2 pi/n, Lc = 15 mm, "
          "lambda = 0.9: axisymmetric to within 0.4 %.")

    _specimen_figure(section, out_dir)
    _interactive_views(section, out_dir, quick)


def _interactive_views(section: Section, out_dir: Path, quick: bool) -> None:
    """The optimum's bending test (both states, one slider) and its snap-through, as
    interactive views beside the static figures."""
    optimum = Design(10, 0.9, 15)
    frames = VIEW_FRAMES[bool(quick)]
    path = out_dir / "optimal_bending_view.json"
    view_bending(optimum, "5mm", max_frames=frames).write_json(path)
    section.add_view(path, "Interactive: the optimum's bending test (5 mm in 350 increments) "
                           f"in both stable states, {frames} increments shown; drag to turn, "
                           "the slider or play to move through the test; right, both "
                           "moment-angle curves with the increment shown (the axes of figures 3.5-3.7).")
    path = out_dir / "optimal_snap_through_view.json"
    view_snap_through(optimum, steps=100, max_frames=frames).write_json(path)
    section.add_view(path, "Interactive: the optimum's snap-through test (one cell driven "
                           f"from Le to Lc in 100 increments, {frames} shown) beside its "
                           "force-travel curve (figure 3.16's axes).")


def _specimen_figure(section: Section, out_dir: Path) -> None:
    d = Design(10, 0.9, 15)
    figure = Figure(figsize=(12.0, 6.0), layout="constrained")
    # The tall extended column needs less width than the squat contracted stack.
    grid = figure.add_gridspec(1, 3, width_ratios=[0.8, 1.1, 1.1])
    contracted = kresling_specimen(d, [0] * 4)
    plot_specimen(kresling_specimen(d, [1] * 4), ax=figure.add_subplot(grid[0], projection="3d"))
    plot_specimen(contracted, ax=figure.add_subplot(grid[1], projection="3d"))
    bent = bending_test(d, 0)
    plot_specimen(contracted, bent.final_displacement, scale=2, view=(10, 0),
                  ax=figure.add_subplot(grid[2], projection="3d"),
                  title="contracted, end of the 5 mm bending test\n(seen along x) "
                        "displacements × 2")
    _save(figure, section, out_dir / "optimal_specimen.png",
          "The optimal bending specimen (n=10, lambda=0.9, Lc=15 mm, two modules) as the "
          "model builds it: extended, contracted, and contracted at the end of the 5 mm "
          "bending test, seen along the pin lines (displacements magnified twice; grey: as built). Valley creases "
          "blue, cut mountain creases dashed red, polygon edges black, polygon spokes dotted. "
          "The same model is in optimal_specimen.fold (FOLD 1.1, with the bent shape as a "
          "second frame).")
    write_specimen_fold(out_dir / "optimal_specimen.fold", contracted,
                        frames=[("end of the 5 mm bending test", bent.final_displacement)])
