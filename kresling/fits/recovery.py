"""Recovery experiments: run the pipelines on synthetic records of known truth and measure
how close, and how honestly uncertain, their answers are."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.fits.bending import fit_bending_trial
from kresling.fits.crease import fit_crease_runs
from kresling.fits.synthetic import BendingRig, CreaseRig, synthetic_bending_trials, \
    synthetic_crease_runs

__all__ = ["CreaseRecovery", "crease_recovery", "bending_recovery"]


@dataclass(frozen=True)
class CreaseRecovery:
    """Repeated synthetic crease experiments of one true kf (N/rad).

    Attributes
    ----------
    kf : float
        The truth.
    estimates : ndarray, shape (repetitions,)
        Overall mean of each repetition's runs.
    ci : ndarray, shape (repetitions, 2)
        Its confidence interval (over runs).
    ci_between_samples : ndarray, shape (repetitions, 2)
        The interval over sample means.
    confidence : float
    """

    kf: float
    estimates: np.ndarray
    ci: np.ndarray
    ci_between_samples: np.ndarray
    confidence: float

    @property
    def coverage(self) -> float:
        """Fraction of repetitions whose interval (over runs) contains the truth."""
        return float(np.mean((self.ci[:, 0] <= self.kf) & (self.kf <= self.ci[:, 1])))

    @property
    def coverage_between_samples(self) -> float:
        """The same for the interval over sample means."""
        low, high = self.ci_between_samples.T
        return float(np.mean((low <= self.kf) & (self.kf <= high)))

    @property
    def relative_errors(self) -> np.ndarray:
        """``estimate / kf - 1`` of each repetition."""
        return self.estimates / self.kf - 1.0


def crease_recovery(kf: float = 0.047, repetitions: int = 200, seed: int = 0, *,
                    confidence: float = 0.95, rig: CreaseRig = CreaseRig(),
                    **generator_options) -> CreaseRecovery:
    """Fit ``repetitions`` independent synthetic data sets of the thesis's size.

    Parameters
    ----------
    kf : float
        True stiffness, N/rad.
    repetitions : int
    seed : int
        Seeds one :class:`numpy.random.Generator` that draws every repetition.
    confidence : float
    rig : CreaseRig
    **generator_options
        ``samples``, ``runs``, ``sample_cv``, ``run_cv`` of
        :func:`~kresling.fits.synthetic.synthetic_crease_runs`.
    """
    rng = np.random.default_rng(seed)
    estimates, ci, ci_between = [], [], []
    for _ in range(repetitions):
        runs, _truth = synthetic_crease_runs(kf, rng, rig=rig, **generator_options)
        result = fit_crease_runs(runs, confidence=confidence)
        estimates.append(result.overall.mean)
        ci.append(result.overall.ci)
        ci_between.append(result.between_samples.ci if result.between_samples
                          else (np.nan, np.nan))
    return CreaseRecovery(kf, np.array(estimates), np.array(ci), np.array(ci_between),
                          confidence)


def bending_recovery(K: float, state, module_length: float, seed: int = 0, *,
                     method: str = "intercept", offset: float | None = None,
                     rise: bool | None = None, trials: int = 3,
                     rig: BendingRig = BendingRig()) -> np.ndarray:
    """Relative error ``K_fit / K_true - 1`` of each of ``trials`` synthetic trials.

    Parameters
    ----------
    K : float
        True K_B, N*m/rad.
    state : {"extended", "contracted"}
    module_length : float
        mm.
    seed : int
    method, offset
        As in :func:`~kresling.fits.bending.fit_bending_trial`.
    rise : bool, optional
        Residual-stress rise in the records (default: contracted state only).
    trials : int
    rig : BendingRig

    Returns
    -------
    ndarray, shape (trials,)
    """
    records, truth = synthetic_bending_trials(K, state, module_length,
                                              np.random.default_rng(seed), trials=trials,
                                              rig=rig, rise=rise)
    fitted = [fit_bending_trial(r, method=method, offset=offset).K for r in records]
    return np.array(fitted) / truth - 1.0
