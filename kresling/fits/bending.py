"""Bending stiffness from three-point bending trials (thesis section 3.3, eqns 20-22).

Each trial's record of downward displacement y (mm) and force F (N) becomes moment and
deflection angle with the module length Lm (mm)::

    M = F Lm            (20)        delta = atan(y / Lm)        (21)

and the bending stiffness K_B is the least-squares slope of M against delta (22), N*m/rad.
Two slopes, used in different places:

- ``method="intercept"``: M = K delta + b, what a laboratory fit does. Used for experimental
  records (the default here): a trial's moment need not start at zero.
- ``method="origin"``: M = K delta, MATLAB's ``theta \\ M`` in the thesis's model code. Used
  for model curves (:func:`model_stiffness`), which start at the origin by construction.

In the contracted state the thesis fits only past an offset angle (0.03 rad): forcing a
specimen to its designed contracted height leaves residual stress, seen as a sharp initial
rise of the moment. Past the offset the curve is straight again but does not pass through
the origin, which is why experimental fits take the intercept.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kresling.fits.statistics import Ratio, fit_line, ratio_of_means, summarize

__all__ = ["STATES", "CONTRACTED_OFFSET", "state_name", "moment_and_angle",
           "slope_through_origin", "model_stiffness", "BendingTrial",
           "BendingTrialFit", "fit_bending_trial", "BendingStiffness", "fit_bending",
           "mean_curve"]

#: The two stable states, in the order of the K_B ratio's numerator and denominator.
STATES = ("extended", "contracted")

#: Angle past which the thesis fits the contracted state, rad.
CONTRACTED_OFFSET = 0.03

_STATE_NAMES = {"1": "extended", "extended": "extended", "ext": "extended",
                "0": "contracted", "contracted": "contracted", "con": "contracted"}


def state_name(state) -> str:
    """``"extended"`` or ``"contracted"`` from 1/0, ``"1"``/``"0"`` or a (short) name."""
    name = _STATE_NAMES.get(str(state).strip().lower())
    if name is None:
        raise ValueError(f"state = {state!r} is invalid: must be 'extended' (1) or "
                         "'contracted' (0)")
    return name


def moment_and_angle(displacement, force, module_length):
    """Eqns 20-21: deflection angle (rad) and moment (N*m) of a trial.

    Parameters
    ----------
    displacement : array_like, shape (m,)
        Downward displacement of the middle, mm.
    force : array_like, shape (m,)
        Force, N.
    module_length : float
        Lm, mm (> 0).

    Returns
    -------
    angle : ndarray, shape (m,)
        ``atan(y / Lm)``, rad.
    moment : ndarray, shape (m,)
        ``F Lm``, converted to N*m.
    """
    if not module_length > 0:
        raise ValueError(f"module_length = {module_length!r} mm is invalid: must be > 0")
    y, f = np.asarray(displacement, dtype=float), np.asarray(force, dtype=float)
    return np.arctan(y / module_length), f * module_length * 1e-3


def slope_through_origin(x, y) -> float:
    """Least-squares ``y = K x`` (MATLAB ``x \\ y``): ``K = sum(x y) / sum(x^2)``."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    norm = float(x @ x)
    if x.size < 1 or norm == 0:
        raise ValueError("no nonzero angle to fit a slope through the origin")
    return float(x @ y) / norm


def model_stiffness(angle, moment) -> float:
    """K_B of a model curve: slope through the origin, as the thesis's model code, N*m/rad.

    Parameters
    ----------
    angle : array_like, shape (m,)
        rad.
    moment : array_like, shape (m,)
        N*m.
    """
    return slope_through_origin(angle, moment)


@dataclass(frozen=True)
class BendingTrial:
    """One bending trial: state, module length Lm (mm), displacement (mm) and force (N),
    arrays of shape (m,); ``source`` names where it came from, for messages."""

    state: str
    module_length: float
    displacement: np.ndarray
    force: np.ndarray
    source: str = ""


@dataclass(frozen=True)
class BendingTrialFit:
    """K_B of one trial (N*m/rad), the intercept (N*m, 0 for ``method="origin"``), the
    offset angle (rad) and number of points the fit used, and the whole converted curve
    (``angle`` rad, ``moment`` N*m, shape (m,))."""

    state: str
    K: float
    intercept: float
    method: str
    offset: float
    points: int
    angle: np.ndarray = field(repr=False)
    moment: np.ndarray = field(repr=False)
    source: str = ""

    def as_dict(self) -> dict:
        return {"source": self.source, "K": self.K, "intercept": self.intercept,
                "offset": self.offset, "points": self.points}


def fit_bending_trial(trial: BendingTrial, *, method: str = "intercept",
                      offset: float | None = None) -> BendingTrialFit:
    """K_B of one trial (eqns 20-22).

    Parameters
    ----------
    trial : BendingTrial
    method : {"intercept", "origin"}
        Least-squares line with an intercept (laboratory fit) or through the origin.
    offset : float, optional
        Fit only points with angle >= offset (rad); default :data:`CONTRACTED_OFFSET` for
        the contracted state and 0 (every point) for the extended one.
    """
    if method not in ("intercept", "origin"):
        raise ValueError(f"method = {method!r} is invalid: must be 'intercept' or 'origin'")
    state = state_name(trial.state)
    if offset is None:
        offset = CONTRACTED_OFFSET if state == "contracted" else 0.0
    label = trial.source or f"{state} trial"
    # Overflow in the sums is not warned about: a non-finite fit is refused below, naming
    # the record.
    with np.errstate(over="ignore", invalid="ignore"):
        try:
            angle, moment = moment_and_angle(trial.displacement, trial.force, trial.module_length)
            used = angle >= offset if offset > 0 else np.ones(angle.shape, dtype=bool)
            if used.sum() < 2:
                raise ValueError(f"{int(used.sum())} point(s) at or past the offset angle "
                                 f"{offset} rad (largest angle {angle.max():.4g} rad): a line "
                                 "needs 2")
            if method == "origin":
                K, intercept = slope_through_origin(angle[used], moment[used]), 0.0
            else:
                K, intercept = fit_line(angle[used], moment[used], "angle")
            if not (np.isfinite(K) and np.isfinite(intercept)):
                raise ValueError(f"the fitted K_B = {K!r} is not finite: the values are too "
                                 f"large for the fit's sums (force up to "
                                 f"{np.abs(trial.force).max():.3g} N, displacement up to "
                                 f"{np.abs(trial.displacement).max():.3g} mm)")
        except ValueError as error:
            raise ValueError(f"{label}: {error}") from None
    return BendingTrialFit(state, K, intercept, method, float(offset), int(used.sum()),
                           angle, moment, trial.source)


@dataclass
class BendingStiffness:
    """K_B over the trials of each state and their ratio.

    Attributes
    ----------
    fits : dict of str to tuple of BendingTrialFit
    summaries : dict of str to Summary
        Mean, SD, SE, CI of K_B per state, N*m/rad.
    ratio : Ratio or None
        K_B(extended) / K_B(contracted) (eqn 23) with first-order uncertainty; None unless
        both states have trials.
    method : str
    skipped : list of SkippedRow
    """

    fits: dict
    summaries: dict
    ratio: Ratio | None
    method: str
    skipped: list = field(default_factory=list)

    @property
    def K(self) -> dict:
        """Mean K_B per state, N*m/rad."""
        return {state: s.mean for state, s in self.summaries.items()}

    def as_dict(self) -> dict:
        """Everything as plain data (what ``kresling fit bending --json`` prints)."""
        ratio = self.ratio.as_dict() if self.ratio else {}
        return {
            "unit": "N*m/rad", "method": self.method, "K": self.K,
            "states": {state: {**summary.as_dict(),
                               "trials": [f.as_dict() for f in self.fits[state]]}
                       for state, summary in self.summaries.items()},
            "ratio": ratio.get("value"), "ratio_sd": ratio.get("sd"),
            "ratio_se": ratio.get("se"), "ratio_method": ratio.get("method"),
            "skipped": {"count": len(self.skipped), "rows": [str(s) for s in self.skipped]},
        }


def fit_bending(trials, *, method: str = "intercept",
                contracted_offset: float = CONTRACTED_OFFSET, confidence: float = 0.95,
                skipped=()) -> BendingStiffness:
    """Fit every trial and summarize K_B per state, with the K_B ratio.

    Parameters
    ----------
    trials : sequence of BendingTrial
    method : {"intercept", "origin"}
        See the module docstring; experimental records want ``"intercept"``.
    contracted_offset : float
        Offset angle of the contracted-state fits, rad (the extended state uses every point).
    confidence : float
        Level of the per-state confidence intervals.
    skipped : list of SkippedRow
        Lines the readers passed over, carried into the result for reporting.
    """
    fits = {}
    for trial in trials:
        offset = contracted_offset if state_name(trial.state) == "contracted" else 0.0
        fit = fit_bending_trial(trial, method=method, offset=offset)
        fits.setdefault(fit.state, []).append(fit)
    if not fits:
        raise ValueError("no bending trials given")
    fits = {state: tuple(fits[state]) for state in STATES if state in fits}
    summaries = {state: summarize([f.K for f in group], confidence)
                 for state, group in fits.items()}
    ratio = (ratio_of_means(summaries["extended"], summaries["contracted"])
             if len(summaries) == 2 else None)
    return BendingStiffness(fits, summaries, ratio, method, list(skipped))


def mean_curve(fits, points: int = 200):
    """Mean and SD of several trials' moment-angle curves on a common angle grid.

    The grid spans the angles every trial reaches; each trial is interpolated onto it.

    Parameters
    ----------
    fits : sequence of BendingTrialFit (or objects with ``angle`` and ``moment`` arrays)
    points : int
        Grid size.

    Returns
    -------
    angle : ndarray, shape (points,)
        rad.
    mean, sd : ndarray, shape (points,)
        N*m; ``sd`` is the sample SD across trials (0 for a single trial).
    """
    curves = [(np.asarray(f.angle), np.asarray(f.moment)) for f in fits]
    if not curves:
        raise ValueError("no curves to average")
    low = max(a.min() for a, _ in curves)
    high = min(a.max() for a, _ in curves)
    if not high > low:
        raise ValueError("the trials' angle ranges do not overlap")
    grid = np.linspace(max(low, 0.0), high, points)
    # Displacement noise can make a recorded angle step back; sort before interpolating.
    stack = np.array([np.interp(grid, a[np.argsort(a)], m[np.argsort(a)]) for a, m in curves])
    sd = stack.std(axis=0, ddof=1) if len(curves) > 1 else np.zeros(points)
    return grid, stack.mean(axis=0), sd
