"""Figures of a single cell (its two stable states in 3D and the truss kinematic path) and
the plotting helpers the packages above share (the moment-angle axes of the thesis's
figures 3.5-3.7, drawn by both the bending analyses and the experimental fits).

Functions draw into a given Matplotlib axes (or a new figure) and return the axes; they
never call ``plt.show``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from kresling.geometry import Design, state_index

__all__ = ["plot_cell", "plot_kinematic_path", "label_moment_angle_axes"]


def plot_cell(design: Design, state, ax=None, *, color="tab:blue", alpha=0.35):
    """Draw the folded cell in a stable state: valley and mountain creases and the facets.

    Parameters
    ----------
    design : Design
    state : {0, 1, "contracted", "extended"}
    ax : mpl_toolkits.mplot3d.Axes3D, optional
        Axes to draw into; a new 3D figure when omitted.

    Returns
    -------
    Axes3D
    """
    if ax is None:
        ax = plt.figure(figsize=(4.5, 4.5)).add_subplot(projection="3d")
    bottom, top = design.vertices(state)
    n = design.n
    step = 1 if design.chirality > 0 else -1
    facets, valleys, mountains = [], [], []
    for i in range(n):
        j = (i + 1) % n
        if step > 0:  # valley b_i - t_{i+1}
            facets += [[bottom[i], bottom[j], top[j]], [bottom[i], top[j], top[i]]]
            valleys.append([bottom[i], top[j]])
        else:  # valley b_{i+1} - t_i
            facets += [[bottom[i], bottom[j], top[i]], [bottom[j], top[j], top[i]]]
            valleys.append([bottom[j], top[i]])
        mountains.append([bottom[i], top[i]])
    ax.add_collection3d(Poly3DCollection(facets, facecolor=color, alpha=alpha, edgecolor="none"))
    for polygon in (bottom, top):
        closed = np.vstack([polygon, polygon[:1]])
        ax.plot(*closed.T, color="k", lw=1.2)
    for segment in valleys:
        ax.plot(*np.array(segment).T, color="tab:blue", lw=1.0)
    for segment in mountains:
        ax.plot(*np.array(segment).T, color="tab:red", lw=1.0, ls="--")
    name = "extended" if state_index(state) == 1 else "contracted"
    ax.set_title(f"n={n}, lam={design.lam:g}, Lc={design.Lc:g} mm: {name}")
    ax.set_xlabel("x [mm]"), ax.set_ylabel("y [mm]"), ax.set_zlabel("z [mm]")
    ax.set_box_aspect((1, 1, max(design.Le / (2 * design.R), 0.2)))
    return ax


def plot_kinematic_path(design: Design, ax=None, samples: int = 200):
    """Plot the truss path between the states: height L, mountain bar m and Psi vs twist.

    Parameters
    ----------
    design : Design
    ax : matplotlib.axes.Axes, optional
    samples : int
        Points along alpha in [alpha_e, alpha0].

    Returns
    -------
    matplotlib.axes.Axes
        The axes of L and m; Psi is on a twin axis (``ax.right_ax``).
    """
    if ax is None:
        ax = plt.figure(figsize=(6, 3.5)).add_subplot()
    alpha = np.linspace(design.alpha_e, design.alpha0, samples)
    ax.plot(np.degrees(alpha), design.height_at(alpha), label="height L(alpha)")
    ax.plot(np.degrees(alpha), design.mountain_length_at(alpha), label="mountain bar m(alpha)")
    ax.axhline(design.Mg, color="0.5", ls=":", lw=1, label="Mg (stress-free)")
    ax.set_xlabel("twist alpha [deg]")
    ax.set_ylabel("length [mm]")
    right = ax.twinx()
    right.plot(np.degrees(alpha), np.degrees(design.facet_angle_at(alpha)), color="tab:green",
               label="facet angle Psi")
    right.set_ylabel("Psi [deg]", color="tab:green")
    ax.right_ax = right
    ax.legend(loc="center left", fontsize=8)
    ax.set_title("truss kinematics between the stable states (eqns 8-9)")
    return ax


def label_moment_angle_axes(ax, title: str = ""):
    """Axis labels, limits from the origin, legend and title of a moment-angle plot (the
    style of the thesis's figures 3.5-3.7); returns ``ax``."""
    ax.set_xlabel("deflection angle δ [rad]")
    ax.set_ylabel("moment M [N·m]")
    ax.set_xlim(left=0.0)
    ax.set_ylim(bottom=0.0)
    ax.legend(fontsize=7, loc="upper left")
    if title:
        ax.set_title(title, fontsize=9)
    return ax
