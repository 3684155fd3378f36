"""Figures of the arm as a structure: load capacity, actuation against the kinematic model,
module lengths against Table 5."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

__all__ = ["plot_load_capacity"]

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
