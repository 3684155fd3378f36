"""Figures of chapter 4: the configurations at full displacement (figure 4.12), predicted
against measured markers (4.13), the error per step (4.14) and normalised (4.15), and
workspace maps.

Functions draw into a given Matplotlib axes (or a new figure) and return the axes or the
figure; they never call ``plt.show``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from kresling.manipulator.forward import forward_kinematics, to_plot_plane
from kresling.manipulator.markers import MarkerComparison, MarkerData
from kresling.manipulator.model import Manipulator, configuration_name
from kresling.manipulator.protocol import protocol_tendon_lengths, pseudo_linkage

__all__ = ["plot_configurations", "plot_marker_comparison", "plot_marker_errors",
           "plot_workspaces", "plot_arm"]


def _grid(count: int, width: float = 3.0, height: float = 3.4):
    columns = min(count, 4)
    rows = -(-count // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(width * columns, height * rows),
                             squeeze=False, constrained_layout=True)
    for ax in axes.flat[count:]:
        ax.set_visible(False)
    return fig, axes.flat[:count]


def plot_arm(model: Manipulator, configuration, tendon_lengths=None, ax=None, *, color="k",
             label=None):
    """Draw the backbone and markers of one arm in the thesis's plot plane ``(-x, -z)``.

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = plt.figure(figsize=(3.5, 4)).gca() if ax is None else ax
    state = forward_kinematics(model, configuration, tendon_lengths)
    backbone = to_plot_plane(state.backbone())
    ax.plot(*backbone.T, color=color, lw=2.5, label=label)
    ax.plot(*state.plot_markers.T, "o", color="tab:green", ms=5, mec="k", mew=0.5)
    ax.set_aspect("equal")
    return ax


def plot_configurations(model: Manipulator, k: float = 10):
    """Figure 4.12: every configuration at protocol step ``k`` (flexible modules red, rigid
    blue, markers green), in the thesis's plot plane.

    Returns
    -------
    matplotlib.figure.Figure
    """
    configurations = model.configurations
    fig, axes = _grid(len(configurations))
    lengths = protocol_tendon_lengths(k, model.rest_tendon_length)
    reach = model.modules * model.extended_length
    for ax, configuration in zip(axes, configurations):
        state = forward_kinematics(model, configuration, lengths if 0 in configuration else None)
        points = to_plot_plane(state.backbone(24))
        for j, s in enumerate(configuration):
            part = points[24 * j: 24 * (j + 1) + 1]
            ax.plot(*part.T, color="tab:red" if s == 0 else "tab:blue", lw=3)
        ax.plot(*state.plot_markers.T, "o", color="tab:green", mec="k", mew=0.5, ms=5)
        ax.set_title(f"({configuration_name(configuration)})")
        ax.set_xlim(-0.75 * reach, 0.25 * reach), ax.set_ylim(-1.05 * reach, 0.05 * reach)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]"), ax.set_ylabel("y [mm]")
    fig.suptitle(f"Configurations at step k = {k:g} (red: contracted, blue: extended)")
    return fig


def plot_marker_comparison(model: Manipulator, measured: MarkerData):
    """Figure 4.13: predicted (lines) and measured (crosses) markers of every configuration
    over the protocol's steps.

    Returns
    -------
    matplotlib.figure.Figure
    """
    configurations = measured.configurations
    fig, axes = _grid(len(configurations))
    for ax, config in zip(axes, configurations):
        part = measured.select(config)
        run = pseudo_linkage(model, config, np.unique(part.step))
        predicted = run.plot_markers
        for j in range(predicted.shape[1]):
            ax.plot(*predicted[:, j].T, "-o", ms=2.5, lw=1, color=f"C{j}")
            rows = part.marker == j + 1
            ax.plot(*part.xy[rows].T, "x", ms=4, color=f"C{j}")
        ax.set_title(f"({config})")
        ax.set_aspect("equal", adjustable="datalim")  # keep the panels' boxes equal
        ax.set_xlabel("x [mm]"), ax.set_ylabel("y [mm]")
    fig.suptitle("Predicted (lines) and measured (x) markers, steps 0-10")
    return fig


def plot_marker_errors(comparison: MarkerComparison, normalized: bool = False):
    """Figure 4.14 (error [mm]) or 4.15 (error / predicted length from the base) per step,
    one line per marker.

    Returns
    -------
    matplotlib.figure.Figure
    """
    configurations = sorted(set(comparison.config.tolist()))
    fig, axes = _grid(len(configurations), height=2.6)
    for ax, config in zip(axes, configurations):
        steps, errors = comparison.grid(config, normalized)
        for j in range(1 if normalized else 0, errors.shape[1]):
            ax.plot(steps, errors[:, j], "-o", ms=3, label=f"position {j + 1}")
        ax.set_title(f"({config})")
        ax.set_xlabel("step k")
        ax.set_ylabel("normalised error" if normalized else "error [mm]")
    axes[0].legend(fontsize=7)
    fig.suptitle("Normalised position error" if normalized else "Position error")
    return fig


def plot_workspaces(workspaces: dict, ax=None):
    """Workspace samples of several configurations in the thesis's plot plane (projected).

    Parameters
    ----------
    workspaces : dict of str to Workspace

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = plt.figure(figsize=(5, 5.5), layout="constrained").gca() if ax is None else ax
    for i, (name, space) in enumerate(workspaces.items()):
        points = to_plot_plane(space.points)
        ax.plot(*points.T, ".", ms=2 if len(points) > 1 else 8, color=f"C{i % 10}",
                label=f"({name})")
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]"), ax.set_ylabel("y [mm]")
    ax.legend(fontsize=7, markerscale=3)
    ax.set_title("Tip workspace per configuration")
    return ax
