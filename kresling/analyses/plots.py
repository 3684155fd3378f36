"""Figures of chapter 3's analyses: moment-angle curves (figures 3.5-3.7, 3.14) and the
snap-through force path (figure 3.16).

Functions draw into given Matplotlib axes (or a new figure) and return them; they never call
``plt.show``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from kresling.plots import label_moment_angle_axes

__all__ = ["plot_moment_angle", "plot_table3_design", "plot_stiffness_by_n", "plot_snap_through",
           "plot_orientation_study"]

_COLORS = {"extended": "tab:blue", "contracted": "tab:orange"}
_LABELS = {"extended": "state (1), extended", "contracted": "state (0), contracted"}
#: The bending stiffness K_B as Matplotlib sets it (mathtext: K with a subscript B).
_KB = "$K_B$"


def _axes(ax, size=(5.5, 4.0)):
    if ax is not None:
        return ax
    return plt.figure(figsize=size, layout="constrained").add_subplot()


def _axes_pair(axes, size=(9.5, 3.8)):
    if axes is not None:
        return axes
    return plt.figure(figsize=size, layout="constrained").subplots(1, 2)


def plot_moment_angle(comparison, ax=None, *, reference=None, experiment=None, title=""):
    """Moment against deflection angle in both states, as in figures 3.5-3.7.

    Parameters
    ----------
    comparison : BendingComparison
        Our bending test in both states (solid lines, slope K_B in the legend).
    ax : matplotlib.axes.Axes, optional
    reference : dict, optional
        State name to a reference curve ``(angle, moment)`` (rad, N*m), drawn dashed (the
        MERLIN2 runs).
    experiment : dict, optional
        State name to ``(mean, sd)`` of a measured K_B [N*m/rad]: drawn as the line
        M = K delta with a band for ±1 SD of the slope (the thesis prints no raw curves).
    title : str

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = _axes(ax)
    for name, result in (("extended", comparison.extended), ("contracted", comparison.contracted)):
        color = _COLORS[name]
        # A run that stopped early is marked in its label: its K_B is fitted to part of the
        # travel.
        partial = (f" (PARTIAL: stopped at {result.travel_fraction:.0%} of the travel)"
                   if result.partial else "")
        ax.plot(result.angle, result.moment, color=color, lw=1.8,
                label=f"{_LABELS[name]}: model, {_KB} = {result.stiffness:.3f} N·m/rad{partial}")
        if reference and name in reference:
            angle, moment = reference[name]
            ax.plot(angle, moment, color="k", ls=(0, (2, 3)), lw=1.0,
                    label="MERLIN2 reference run" if name == "extended" else None)
        if experiment and name in experiment:
            mean, sd = experiment[name]
            top = float(result.angle.max())
            delta = np.array([0.0, top])
            ax.plot(delta, mean * delta, color=color, ls="-.", lw=1.0,
                    label=f"{_LABELS[name]}: experiment, {_KB} = {mean:.2f}" +
                          (f" ± {sd:.2f}" if np.isfinite(sd) else ""))
            if np.isfinite(sd):
                ax.fill_between(delta, (mean - sd) * delta, (mean + sd) * delta, color=color,
                                alpha=0.15, lw=0)
    return label_moment_angle_axes(ax, title)


def plot_table3_design(entry, ax=None, reference_curves=None):
    """Figures 3.5-3.7 (and 3.15) for one :class:`~kresling.analyses.table3.Table3Comparison`:
    our curves, the MERLIN2 reference curves (``reference_curves``: state name to
    ``(angle, moment)``) and the thesis's experimental K_B ± SD."""
    e = entry.experiment
    experiment = {name: (e[name], e[f"{name}_sd"]) for name in ("extended", "contracted")
                  if name in e}
    d = entry.design
    return plot_moment_angle(entry.ours, ax, reference=reference_curves, experiment=experiment,
                             title=f"n = {d.n}, Lc = {d.Lc:g} mm, λ = {d.lam:g}: {_KB} ratio "
                                   f"{entry.ours.ratio:.2f} (thesis model "
                                   f"{entry.thesis_model['ratio']:.2f})")


def plot_stiffness_by_n(comparisons: dict, axes=None):
    """Figure 3.14: (a) moment-angle curves of both states for each n, (b) K_B ratio by n.

    Parameters
    ----------
    comparisons : dict
        n to BendingComparison (same Lc and lambda).
    axes : pair of matplotlib.axes.Axes, optional

    Returns
    -------
    pair of matplotlib.axes.Axes
    """
    left, right = _axes_pair(axes)
    ns = sorted(comparisons)
    for n in ns:
        c = comparisons[n]
        line, = left.plot(c.extended.angle, c.extended.moment, label=f"n = {n}")
        left.plot(c.contracted.angle, c.contracted.moment, ls="--", color=line.get_color())
    left.set_xlabel("deflection angle δ [rad]")
    left.set_ylabel("moment M [N·m]")
    left.set_title("solid: extended, dashed: contracted", fontsize=8)
    left.legend(fontsize=8)
    right.plot(ns, [comparisons[n].ratio for n in ns], "o-", color="tab:red")
    right.set_xticks(ns)
    right.set_xlabel("number of sides n")
    right.set_ylabel(f"{_KB} ratio")
    return left, right


def plot_snap_through(result, ax=None, *, title=""):
    """Figure 3.16: force against the drive's travel, the snap force and the equilibria.

    Parameters
    ----------
    result : SnapThroughResult
    ax : matplotlib.axes.Axes, optional
    title : str

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = _axes(ax)
    ax.plot(result.displacement, result.force, color="tab:blue", lw=1.6, label="model")
    ax.axhline(0.0, color="k", lw=0.6)
    if result.has_peak:
        ax.plot(result.snap_displacement, result.snap_force, "v", color="tab:red",
                label=f"snap force {result.snap_force:.2f} N at {result.snap_displacement:.2f} mm")
    if np.isfinite(result.unstable_displacement):
        ax.plot(result.unstable_displacement, 0.0, "o", mfc="white", color="k",
                label=f"unstable state (barrier {result.energy_barrier:.1f} N·mm)")
    if result.bistable:
        ax.plot(result.stable_displacement, 0.0, "o", color="k",
                label=f"second stable state ({result.stable_height:.1f} mm high)")
    ax.set_xlabel("drive travel from the extended state [mm]")
    ax.set_ylabel("force F [N]")
    ax.legend(fontsize=7)
    d = result.design
    title = title or (f"n = {d.n}, Lc = {d.Lc:g} mm, λ = {d.lam:g}: "
                      f"{'bistable' if result.bistable else 'not bistable'}")
    if result.partial:  # the features come from part of the path: say so on the figure
        title += f" (PARTIAL: stopped at {result.travel_fraction:.0%} of the travel)"
    ax.set_title(title, fontsize=9)
    return ax


def plot_orientation_study(studies, axes=None):
    """Figure A-1: the K_B ratio (left) and each state's K_B relative to its value at
    beta = 0 (right) against the bending axis angle, one line per
    :class:`~kresling.analyses.orientation.OrientationStudy` of ``studies``; returns the pair
    of axes (``axes``, or a new figure's)."""
    left, right = _axes_pair(axes)
    for study in studies:
        d = study.design
        line, = left.plot(study.angles, study.ratio, label=f"n={d.n}")
        for values, style in ((study.extended, "-"), (study.contracted, "--")):
            right.plot(study.angles, 100 * (values / values[0] - 1), style, color=line.get_color())
    left.set_xlabel("bending axis angle β [rad]")
    left.set_ylabel(f"{_KB} ratio (linearised)")
    left.legend(fontsize=8)
    right.set_xlabel("bending axis angle β [rad]")
    right.set_ylabel(r"$K_B(\beta)\,/\,K_B(0) - 1$ [%]")
    right.set_title("solid: extended, dashed: contracted", fontsize=8)
    return left, right
