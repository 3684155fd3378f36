"""Figures of the arm as a structure: load capacity, actuation against the kinematic model,
module lengths against Table 5."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

__all__ = ["plot_load_capacity", "plot_actuation"]

_COLOURS = {"-z": "tab:blue", "+x": "tab:orange", "-x": "tab:green", "+y": "tab:red"}


def plot_load_capacity(table, *, title: str | None = None):
    """Two panels: (a) sideways stiffness against the arm's length, one labelled point per
    configuration (the trade-off: the longest arm is not the stiffest); (b) the largest tip
    load per direction and configuration (hatched: ended by a snap, not by a slack tendon).

    Parameters
    ----------
    table : list of CapacityRow
        From :func:`kresling.arm.capacity.load_capacity_table`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    lengths = [row.tip_height for row in table]
    stiffness = [row.sideways_stiffness for row in table]
    a.scatter(lengths, stiffness, color="k")
    for row, x, y in zip(table, lengths, stiffness):
        a.annotate(f"({row.configuration})", (x, y), textcoords="offset points", xytext=(4, 4))
    a.set_xlabel("arm length, base to tip [mm]")
    a.set_ylabel("sideways tip stiffness 1 / C_xx [N/mm]")
    a.set_title("(a) stiffness against length")
    a.grid(alpha=0.3)

    names = list(table[0].capacity)
    width = 0.8 / len(names)
    x = np.arange(len(table))
    for k, name in enumerate(names):
        loads = [row.capacity[name].load for row in table]
        bars = b.bar(x + (k - (len(names) - 1) / 2) * width, loads, width,
                     color=_COLOURS.get(name), label=f"tip load along {name}")
        for bar, row in zip(bars, table):
            if row.capacity[name].limit == "snap":
                bar.set_hatch("//")
            elif row.capacity[name].limit == "none":
                bar.set_alpha(0.4)
    b.set_xticks(x, [f"({row.configuration})" for row in table])
    b.set_yscale("log")
    b.set_ylabel("largest tip load [N]")
    b.set_title("(b) largest tip load (hatched: a module snaps; else a tendon slackens)",
                fontsize="medium")
    b.legend(fontsize="small")
    b.grid(alpha=0.3, axis="y")
    if title:
        fig.suptitle(title)
    return fig


def plot_actuation(run, *, title: str | None = None):
    """The structure's markers (base and module ends) beside the constant-curvature model's at
    every step of an actuation run, in the plane of tendon 1 (x, z), and the tip error per
    step (like thesis figures 4.13-4.15, with a mechanical model beside the kinematic one).

    Parameters
    ----------
    run : kresling.arm.actuation.ActuationRun

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.6), constrained_layout=True)
    colours = plt.cm.viridis(np.linspace(0, 1, len(run.changes)))
    for k, colour in enumerate(colours):
        a.plot(run.kinematic_markers[k, :, 0], run.kinematic_markers[k, :, 2], "--o",
               color=colour, markersize=3, linewidth=0.8,
               label="kinematic (constant curvature)" if k == 0 else None)
        if np.isfinite(run.markers[k]).all():
            a.plot(run.markers[k, :, 0], run.markers[k, :, 2], "-s", color=colour,
                   markersize=3, label="structure (bar and hinge)" if k == 0 else None)
    a.set_aspect("equal")
    a.set_xlabel("x (towards tendon 1) [mm]")
    a.set_ylabel("z [mm]")
    a.set_title(f"({run.configuration}): markers at each step")
    a.legend(fontsize="small")
    a.grid(alpha=0.3)
    steps = np.arange(len(run.changes))
    b.plot(steps, run.tip_error, "-o", color="k", label="tip")
    for j in range(1, run.markers.shape[1] - 1):
        b.plot(steps, run.marker_error[:, j], "-", alpha=0.6, label=f"end of module {j}")
    b.set_xlabel("protocol step k")
    b.set_ylabel("distance between the models' markers [mm]")
    b.set_title("disagreement per step")
    b.legend(fontsize="small")
    b.grid(alpha=0.3)
    if title:
        fig.suptitle(title)
    return fig
