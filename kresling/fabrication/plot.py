"""Figures of the fabrication data: a cut sheet, and a crease pattern folded onto a state.

Functions draw into a given Matplotlib axes (or a new figure) and return the axes; they
never call ``plt.show``.
"""

from __future__ import annotations

import textwrap

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

from kresling.fabrication.layers import CutSheet
from kresling.fabrication.pattern import CreasePattern
from kresling.geometry import state_index

__all__ = ["plot_sheet", "plot_folded"]

#: Line colour of each crease kind in :func:`plot_folded`.
CREASE_COLOURS = {"mountain": "tab:red", "valley": "tab:blue", "tab": "tab:green",
                  "seam": "tab:purple", "boundary": "k"}
FACE_COLOURS = {"facet": "tab:blue", "tab": "tab:green", "closing tab": "tab:purple",
                "base polygon": "tab:gray"}


def plot_sheet(sheet: CutSheet, ax=None, *, linewidth: float = 0.8):
    """Draw a cut sheet: every path in its layer's colour, in mm, with a legend of the passes.

    Parameters
    ----------
    sheet : CutSheet
    ax : matplotlib.axes.Axes, optional
    linewidth : float
        Points.

    Returns
    -------
    matplotlib.axes.Axes
    """
    if ax is None:
        ax = plt.figure(figsize=(7, 5)).add_subplot()
    for layer in sheet.layers:
        for k, path in enumerate(layer.paths):
            points = np.vstack([path.points, path.points[:1]]) if path.closed else path.points
            ax.plot(*points.T, color=layer.colour, lw=linewidth,
                    label=layer.name if k == 0 else None)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]"), ax.set_ylabel("y [mm]")
    ax.set_title(_wrapped(sheet.title), fontsize=9)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), fontsize=8, frameon=False)
    return ax


def plot_folded(pattern: CreasePattern, state, ax=None, *, alpha: float = 0.3):
    """Draw the crease pattern folded onto a stable state: faces and lines coloured by kind.

    Every face of the flat pattern (facets, tabs, closing tab, base polygon) is drawn where
    :meth:`CreasePattern.folded` puts it.

    Parameters
    ----------
    pattern : CreasePattern
    state : {0, 1, "contracted", "extended"}
    ax : mpl_toolkits.mplot3d.Axes3D, optional

    Returns
    -------
    Axes3D
    """
    if ax is None:
        ax = plt.figure(figsize=(4.5, 4.5)).add_subplot(projection="3d")
    xyz = pattern.folded(state)
    for kind, colour in FACE_COLOURS.items():
        faces = [xyz[list(f)] for f, k in zip(pattern.faces, pattern.face_kinds) if k == kind]
        ax.add_collection3d(Poly3DCollection(faces, facecolor=colour, alpha=alpha,
                                             edgecolor="none"))
    for kind, colour in CREASE_COLOURS.items():
        segments = xyz[pattern.edges_of_kind(kind)]
        ax.add_collection3d(Line3DCollection(segments, colors=colour, lw=1.0, label=kind))
    d = pattern.design
    ax.auto_scale_xyz(*[(xyz[:, k].min(), xyz[:, k].max()) for k in range(3)])
    ax.set_box_aspect(tuple(np.ptp(xyz, axis=0) + 1e-9))
    name = "extended" if state_index(state) == 1 else "contracted"
    ax.set_title(_wrapped(f"n={d.n}, lam={d.lam:g}, Lc={d.Lc:g} mm, {d.chirality:+d}: {name}"),
                 fontsize=9)
    ax.set_xlabel("x [mm]"), ax.set_ylabel("y [mm]"), ax.set_zlabel("z [mm]")
    ax.zaxis.set_major_locator(MaxNLocator(3))   # a flat contracted cell has little room
    return ax


def _wrapped(title: str, width: int = 40) -> str:
    """``title`` on lines of at most ``width`` characters (a number stays with its unit), so
    that titles of axes side by side in one figure do not run into each other."""
    kept = title.replace(" mm", "\u00a0mm")  # textwrap does not break at a no-break space
    return textwrap.fill(kept, width, break_long_words=False, break_on_hyphens=False)
