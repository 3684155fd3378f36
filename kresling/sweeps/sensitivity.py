"""How fast a metric falls away from a design (the optimum): local derivatives, and profiles
along Lc and lambda to the far end of their ranges with where the metric drops to a given
fraction of its value.

The thesis notes a sharp rise of the K_B ratio towards high lambda and low Lc; this puts
numbers on it, which is what a designer needs to know about manufacturing tolerances.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.geometry import Design
from kresling.sweeps.designs import THESIS_LAM
from kresling.sweeps.sweep import sweep

__all__ = ["Sensitivity", "sensitivity", "plot_sensitivity"]

_AXES = ("Lc", "lam")
_UNITS = {"Lc": " mm", "lam": ""}


@dataclass(frozen=True)
class Sensitivity:
    """A metric's behaviour around one design.

    Attributes
    ----------
    design : Design
    metric : str
    value : float
        The metric at ``design``.
    gradient : dict
        ``{"Lc": d metric / d Lc [1/mm], "lam": d metric / d lambda}`` by finite
        differences (one-sided into the range at a bound).
    elasticity : dict
        ``d ln(metric) / d ln(x)`` for x = Lc, lambda: % change per % change.
    profiles : dict
        ``{"Lc": (x, values), "lam": (x, values)}``: arrays of shape (P,) from the design
        along one variable to the far end of its range (the other held).
    drop : dict
        ``{"Lc": {level: x}, "lam": {level: x}}``: where along each profile the metric first
        falls to ``level`` times its value (NaN if it does not within the range).
    """

    design: Design
    metric: str
    value: float
    gradient: dict
    elasticity: dict
    profiles: dict
    drop: dict

    def summary(self) -> str:
        """A few lines of text for reports."""
        d = self.design
        lines = [f"{self.metric} = {self.value:.4g} at n = {d.n}, Lc = {d.Lc:.4g} mm, "
                 f"lam = {d.lam:.4g}"]
        for axis in _AXES:
            x0 = getattr(d, axis)
            drops = ", ".join(f"{level:.0%} at {axis} = {x:.4g} ({x - x0:+.3g}{_UNITS[axis]})"
                              for level, x in self.drop[axis].items() if np.isfinite(x))
            lines.append(f"  along {axis}: d{self.metric}/d{axis} = {self.gradient[axis]:.4g}"
                         f"{' per mm' if axis == 'Lc' else ''}, elasticity "
                         f"{self.elasticity[axis]:.3g}; falls to {drops or 'no level given'}")
        return "\n".join(lines)


def sensitivity(design: Design, metric="kb_ratio", *, Lc=None, lam=THESIS_LAM, points=41,
                levels=(0.9, 0.75, 0.5), workers=None, parameters=None) -> Sensitivity:
    """Derivatives and profiles of ``metric`` around ``design``.

    Parameters
    ----------
    design : Design
        Typically the optimum.
    metric : str, default "kb_ratio"
        A registered metric (its main column is profiled).
    Lc, lam : (float, float), optional
        Ranges the profiles run to (defaults: R/2 to 2R, and 0.7 to 0.9); each profile goes
        from the design towards the end of its range farther from it.
    points : int, default 41
        Designs per profile (spaced more finely near the design).
    levels : sequence of float
        Fractions of the value whose crossing points are reported.
    workers : int, optional
    parameters : SpecimenParameters, optional
        The specimens' material and model (the thesis's by default).

    Returns
    -------
    Sensitivity
    """
    Lc = (design.R / 2, 2 * design.R) if Lc is None else Lc
    ranges = {"Lc": Lc, "lam": lam}
    steps = {"Lc": 1e-3, "lam": 1e-5}  # well above the solver's noise (about 1e-9)
    x0 = {axis: getattr(design, axis) for axis in _AXES}
    lines, columns = {}, {"n": [], "Lc": [], "lam": [], "R": []}
    for axis in _AXES:
        low, high = ranges[axis]
        far = high if abs(high - x0[axis]) >= abs(low - x0[axis]) else low
        t = np.linspace(0.0, 1.0, points) ** 2  # finer near the design
        direction = np.sign(far - x0[axis])
        xs = np.concatenate([[x0[axis] + direction * steps[axis]], x0[axis] + t * (far - x0[axis])])
        lines[axis] = xs
        for x in xs:
            point = dict(x0, **{axis: x})
            for key, value in (("n", design.n), ("Lc", point["Lc"]), ("lam", point["lam"]),
                               ("R", design.R)):
                columns[key].append(value)
    table = sweep(columns, [metric], workers=workers, progress=False, parameters=parameters)
    values = np.where(table.ok, table[metric], np.nan)
    value = values[1]
    gradient, elasticity, profiles, drop = {}, {}, {}, {}
    for k, axis in enumerate(_AXES):
        part = values[k * (points + 1):(k + 1) * (points + 1)]
        xs = lines[axis]
        gradient[axis] = (part[0] - part[1]) / (xs[0] - xs[1])
        elasticity[axis] = gradient[axis] * x0[axis] / value
        profiles[axis] = (xs[1:], part[1:])
        drop[axis] = {level: _crossing(xs[1:], part[1:] / value, level) for level in levels}
    return Sensitivity(design, metric, value, gradient, elasticity, profiles, drop)


def _crossing(x, y, level) -> float:
    """First x where y falls to ``level`` (linear interpolation), NaN if it never does."""
    below = np.flatnonzero(y <= level)
    if len(below) == 0 or below[0] == 0:
        return float("nan")
    i = below[0]
    return float(x[i - 1] + (level - y[i - 1]) * (x[i] - x[i - 1]) / (y[i] - y[i - 1]))


def plot_sensitivity(result: Sensitivity):
    """The two profiles, relative to the value at the design, with the drop levels.

    Returns
    -------
    matplotlib Figure
    """
    # Here, not at the top: kresling.sweeps imports this module, and the command line imports
    # kresling.sweeps for every command (Matplotlib would add ~0.3 s to 'kresling --help').
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(1, 2, figsize=(9, 3.6), layout="constrained", sharey=True)
    for ax, axis in zip(axes, _AXES):
        x, y = result.profiles[axis]
        ax.plot(x, y / result.value, color="tab:blue")
        for level, at in result.drop[axis].items():
            ax.axhline(level, color="0.7", lw=0.8, ls=":")
            if np.isfinite(at):
                ax.plot(at, level, "o", color="tab:red", ms=4)
                ax.annotate(f"{at:.3g}", (at, level), xytext=(4, 4), textcoords="offset points",
                            fontsize=8)
        ax.set_xlabel(f"{'contracted height Lc [mm]' if axis == 'Lc' else 'angle ratio lambda'}")
        ax.set_title(f"{result.metric} along {axis}, other variable held")
    axes[0].set_ylabel(f"{result.metric} / value at the design")
    d = result.design
    figure.suptitle(f"Sensitivity at n = {d.n}, Lc = {d.Lc:.3g} mm, lam = {d.lam:.3g} "
                    f"({result.metric} = {result.value:.4g})")
    return figure
