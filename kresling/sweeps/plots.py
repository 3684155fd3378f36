"""Figures of a sweep: heat maps over Lc x lambda (thesis figures 3.9-3.12 and 3.17), the
maximum against n (figure 3.13), with the optimum marked.

Functions draw into given Matplotlib axes (or a new figure) and return them; they never
call ``plt.show``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from kresling.sweeps.metrics import METRICS
from kresling.sweeps.table import SweepTable

__all__ = ["plot_map", "plot_maps", "plot_ratio_maps", "plot_max_by_n", "metric_label"]


def metric_label(column: str) -> str:
    """A plot label for a table column (a metric's label, else the column's name)."""
    metric = METRICS.get(column)
    return metric.label if metric is not None and metric.label else column


def plot_map(table: SweepTable, metric: str, n: int, ax=None, *, mark_best=True, cmap="viridis"):
    """Heat map of ``metric`` over Lc x lambda for one n; the maximum marked with a star.

    Parameters
    ----------
    table : SweepTable
        A sweep over a grid (several Lc and lambda values for this n).
    metric : str
        Column to map.
    n : int
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib Axes
        With a colour bar; failed designs are left blank.
    """
    if ax is None:
        ax = plt.figure(figsize=(4.8, 3.8), layout="constrained").add_subplot()
    Lc, lam, values = table.grid(metric, n)
    if len(Lc) < 2 or len(lam) < 2:
        raise ValueError(f"the table has {len(Lc)} Lc x {len(lam)} lambda values for n = {n}: "
                         f"a map needs at least 2 x 2")
    mesh = ax.pcolormesh(Lc, lam, np.ma.masked_invalid(values), shading="nearest", cmap=cmap)
    ax.figure.colorbar(mesh, ax=ax, label=metric_label(metric))
    if mark_best and np.isfinite(values).any():
        best = table.best(metric, n=n)
        ax.plot(best["Lc"], best["lam"], marker="*", ms=14, mec="k", mfc="w", clip_on=False)
        ax.annotate(f"max {best[metric]:.3g}\nLc = {best['Lc']:.3g} mm, lam = {best['lam']:.3g}",
                    (best["Lc"], best["lam"]), xytext=(8, -8), textcoords="offset points",
                    va="top", fontsize=8, color="w",
                    bbox={"boxstyle": "round", "fc": "k", "alpha": 0.45, "lw": 0})
    ax.set_xlabel("contracted height Lc [mm]")
    ax.set_ylabel("angle ratio lambda")
    ax.set_title(f"n = {n}")
    return ax


def plot_maps(table: SweepTable, metric: str, ns=None):
    """One heat map of ``metric`` per n, side by side (figure 3.17 for ``snap_force``).

    Returns
    -------
    matplotlib Figure
    """
    ns = sorted({int(n) for n in table["n"]}) if ns is None else list(ns)
    columns = min(len(ns), 2)
    rows = -(-len(ns) // columns)
    figure, axes = plt.subplots(rows, columns, figsize=(4.8 * columns, 3.8 * rows),
                                layout="constrained", squeeze=False)
    for ax, n in zip(axes.flat, ns):
        plot_map(table, metric, n, ax)
    for ax in axes.flat[len(ns):]:
        ax.set_visible(False)
    figure.suptitle(metric_label(metric))
    return figure


def plot_ratio_maps(table: SweepTable, n: int, metrics=("kb_ratio", "psi_ratio")):
    """Figures 3.9-3.12 for one n: (a) the K_B ratio, (b) the facet-angle ratio.

    Returns
    -------
    matplotlib Figure
    """
    figure, axes = plt.subplots(1, len(metrics), figsize=(4.8 * len(metrics), 3.8),
                                layout="constrained", squeeze=False)
    for k, (ax, metric) in enumerate(zip(axes.flat, metrics)):
        plot_map(table, metric, n, ax)
        ax.set_title(f"({chr(ord('a') + k)}) {metric_label(metric)}, n = {n}")
    return figure


def plot_max_by_n(table: SweepTable, metric: str = "kb_ratio", ax=None):
    """Figure 3.13: the largest ``metric`` of each n, with where it is.

    Returns
    -------
    matplotlib Axes
    """
    if ax is None:
        ax = plt.figure(figsize=(4.8, 3.6), layout="constrained").add_subplot()
    ns = sorted({int(n) for n in table["n"]})
    best = [table.best(metric, n=n) for n in ns]
    ax.plot(ns, [b[metric] for b in best], "o-", color="tab:blue")
    for n, b in zip(ns, best):
        ax.annotate(f"{b[metric]:.3g}\n(Lc {b['Lc']:.3g}, lam {b['lam']:.3g})", (n, b[metric]),
                    xytext=(0, -10), textcoords="offset points", ha="center", va="top",
                    fontsize=7)
    ax.set_xticks(ns)
    ax.set_xlabel("sides of the base polygon n")
    ax.set_ylabel(f"maximum {metric_label(metric)}")
    ax.margins(y=0.25)
    return ax
