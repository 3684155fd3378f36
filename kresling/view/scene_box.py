"""The 3D scene's frame: the box around every frame's nodes, its axes and camera, and the
checks of a path's displacements (no plotly objects: the compact page uses these too).

A flat pattern's box would be a thin slab (its height a few per cent of its sides), whose
z axis then piles its ticks on top of each other; every side of the box is at least
:data:`MIN_SIDE` of the longest one, and each axis asks for ticks in proportion to its
side.
"""

from __future__ import annotations

import numpy as np

from kresling.view.surface import rounded

__all__ = ["MIN_SIDE", "node_points", "box", "scene_layout", "describe", "check_path"]

#: Smallest side of the scene's box as a fraction of its longest side.
MIN_SIDE = 0.25

#: Ticks on the longest axis (shorter axes get proportionally fewer, at least 3).
_TICKS = 8


def node_points(model, u) -> np.ndarray:
    """Node positions (N, 3) [mm] of ``model`` displaced by ``u`` (3N,) [mm]."""
    return np.asarray(model.nodes, dtype=float) + np.asarray(u, dtype=float).reshape(-1, 3)


def box(points_list) -> tuple:
    """Corners ``(low, high)`` (each (3,), mm) of the box around every frame's nodes,
    padded by 3 % of its largest side, no side shorter than :data:`MIN_SIDE` of the
    longest (centred on the nodes)."""
    stacked = np.vstack(points_list)
    low, high = stacked.min(axis=0), stacked.max(axis=0)
    longest = max(float((high - low).max()), 1e-9)
    low, high = low - 0.03 * longest, high + 0.03 * longest
    side = high - low
    grow = np.maximum(MIN_SIDE * float(side.max()) - side, 0.0) / 2
    return low - grow, high + grow


def scene_layout(points_list, distance=2.5) -> dict:
    """Equal scales on x, y, z (``aspectmode="data"``), axes fixed to :func:`box`; the
    camera at least ``distance`` from the centre (in plotly's scene units)."""
    low, high = box(points_list)
    span = np.maximum(high - low, 1e-12)
    axes = {}
    for k, a in enumerate("xyz"):
        ticks = max(3, int(round(_TICKS * span[k] / span.max())))
        axes[f"{a}axis"] = dict(title=dict(text=f"{a} [mm]"),
                                range=rounded([low[k], high[k]], 4), nticks=ticks)
    # plotly scales the box to sides span / (geometric mean of the spans); the camera
    # steps back by the longest side so that a tall or wide model fits.
    longest = float(span.max() / np.exp(np.log(span).mean()))
    eye = np.array([1.0, 1.0, 0.7]) / np.linalg.norm([1.0, 1.0, 0.7]) * max(1.6 * longest,
                                                                              distance)
    return dict(aspectmode="data", camera=dict(eye=dict(zip("xyz", rounded(eye, 3)))), **axes)


def describe(model) -> str:
    """"N nodes, B bars, H hinges"."""
    return f"{len(model.nodes)} nodes, {len(model.bars)} bars, {len(model.hinges)} hinges"


def check_path(model, path) -> np.ndarray:
    """The path's displacement as (S, 3N) [mm], or a ValueError naming what is wrong."""
    displacement = np.asarray(path.displacement, dtype=float)
    if len(displacement) == 0:
        raise ValueError("path has no increments: nothing to show")
    if displacement.ndim != 2 or displacement.shape[1] != 3 * len(model.nodes):
        raise ValueError(f"path.displacement has shape {displacement.shape}: must be "
                         f"(S, {3 * len(model.nodes)}) for this model")
    return displacement
