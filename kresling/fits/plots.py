"""Figures of the experimental fits, in the style of the thesis's figures 3.5-3.7, 3.15
and 4.4 (mean curve of three trials with a ±1 SD band, against the model's curve).

Functions draw into a given Matplotlib axes (or a new figure) and return the axes; they
never call ``plt.show``. A model enters as data, so any source can supply it: for each
state either a curve ``(angle, moment)`` (arrays in rad and N*m, e.g. from a bending
analysis) or a single K_B (N*m/rad), drawn as the line M = K_B delta.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from kresling.fits.bending import STATES, BendingStiffness, mean_curve, state_name
from kresling.fits.crease import CreaseStiffness
# Shared with the bending analyses' figures; still importable from here.
from kresling.plots import label_moment_angle_axes

__all__ = ["plot_bending_test", "plot_crease_runs", "label_moment_angle_axes"]

_COLORS = {"extended": "tab:blue", "contracted": "tab:orange"}
_LABELS = {"extended": "state (1), extended", "contracted": "state (0), contracted"}


def _new_axes(ax, size):
    if ax is not None:
        return ax
    return plt.figure(figsize=size).add_subplot()


def _model_curve(model, angle_max: float):
    """(angle, moment) arrays of a model given as a curve or as one K_B."""
    if np.isscalar(model):
        angle = np.array([0.0, angle_max])
        return angle, float(model) * angle
    angle, moment = (np.asarray(a, dtype=float) for a in model)
    if angle.shape != moment.shape or angle.ndim != 1:
        raise ValueError(f"a model curve is (angle, moment), two 1-D arrays of one length; "
                         f"got shapes {angle.shape} and {moment.shape}")
    return angle, moment


def plot_bending_test(result: BendingStiffness, model=None, ax=None, *, title: str = "",
                      points: int = 200):
    """Mean moment-angle curve of each state's trials, ±1 SD, beside the model.

    Parameters
    ----------
    result : BendingStiffness
        From :func:`~kresling.fits.bending.fit_bending`.
    model : dict, optional
        State (``"extended"``/``"contracted"`` or 1/0) to a curve ``(angle, moment)``
        (arrays, shape (m,), rad and N*m) or a K_B (N*m/rad). States left out have no model.
    ax : matplotlib.axes.Axes, optional
    title : str
    points : int
        Points of the mean curve.

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = _new_axes(ax, (5.5, 4.0))
    model = {state_name(k): v for k, v in (model or {}).items()}
    for state in STATES:
        if state not in result.fits:
            continue
        color = _COLORS[state]
        angle, mean, sd = mean_curve(result.fits[state], points)
        n = len(result.fits[state])
        ax.plot(angle, mean, color=color, lw=1.6,
                label=f"{_LABELS[state]}: experiment, mean of {n}")
        ax.fill_between(angle, mean - sd, mean + sd, color=color, alpha=0.25, lw=0,
                        label="±1 SD" if state == STATES[0] else None)
        if state in model:
            model_angle, model_moment = _model_curve(model[state], float(angle.max()))
            ax.plot(model_angle, model_moment, color=color, ls="--", lw=1.2,
                    label=f"{_LABELS[state]}: model")
    return label_moment_angle_axes(ax, title)


def plot_crease_runs(result: CreaseStiffness, ax=None, *, title: str = ""):
    """Stiffness of every run by sample, with the overall mean, ±1 SD band and the
    confidence interval of the mean; flagged outliers in red. The legend is to the right of
    the axes (``figure.tight_layout()`` makes room for it).

    Parameters
    ----------
    result : CreaseStiffness
    ax : matplotlib.axes.Axes, optional
    title : str

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = _new_axes(ax, (5.5, 3.5))
    labels = list(result.per_sample)
    position = {label: i for i, label in enumerate(labels)}
    x = np.array([position[s] for s in result.samples], dtype=float)
    jitter = (np.arange(len(x)) % 3 - 1) * 0.08  # keep equal values of a sample apart
    colors = np.where(result.outliers, "tab:red", "tab:blue")
    ax.scatter(x + jitter, result.k, c=colors, s=22, zorder=3, label="runs")
    ax.scatter(range(len(labels)), [result.per_sample[s].mean for s in labels], marker="_",
               s=300, color="k", zorder=4, label="sample mean")
    overall = result.overall
    ax.axhline(overall.mean, color="k", lw=1, label=f"mean {overall.mean:.4f} N/rad")
    ax.axhspan(overall.mean - overall.sd, overall.mean + overall.sd, color="0.85",
               label=f"±1 SD ({overall.sd:.4f})")
    ax.axhspan(*overall.ci, color="tab:green", alpha=0.25,
               label=f"{overall.confidence:.0%} CI of the mean")
    ax.set_xticks(range(len(labels)), labels)
    ax.set_xlabel("sample")
    ax.set_ylabel("crease stiffness k [N/rad]")
    # Beside the axes, not on them: inside, every placement hides runs or the bands.
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    if title:
        ax.set_title(title, fontsize=9)
    return ax
