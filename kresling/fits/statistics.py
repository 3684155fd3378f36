"""Summaries of repeated measurements: mean, sample SD, standard error, a Student-t
confidence interval, outlier flags, and first-order propagation to a ratio.

Conventions, stated once: the SD is the *sample* SD (``ddof=1``); the standard error is
``sd / sqrt(n)``; the confidence interval is ``mean ± t_{(1+c)/2, n-1} se`` (Student t, which
assumes roughly normal, independent values); outliers are flagged, never removed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import stats

__all__ = ["fit_line", "Summary", "summarize", "modified_z_scores", "flag_outliers", "Ratio",
           "ratio_of_means", "OUTLIER_THRESHOLD"]

#: |modified z| above which a value is flagged (Iglewicz & Hoaglin, 1993).
OUTLIER_THRESHOLD = 3.5

CI_METHOD = "Student t interval: mean ± t(n-1) · sd/√n"


def _plain(x: float):
    """A float for JSON, or None for NaN (e.g. an SD of one value)."""
    return float(x) if math.isfinite(x) else None


def fit_line(x, y, x_name: str = "x") -> tuple[float, float]:
    """Least-squares line ``y = slope x + intercept``.

    Parameters
    ----------
    x, y : array_like, shape (m,)
        m >= 2, ``x`` not constant.
    x_name : str
        What ``x`` is, for messages.

    Returns
    -------
    (slope, intercept) : floats
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if x.shape != y.shape or x.ndim != 1:
        raise ValueError(f"{x_name} {x.shape} and its values {y.shape} must be 1-D, same length")
    if x.size < 2:
        raise ValueError(f"{x.size} point(s): a line needs at least 2")
    dx = x - x.mean()
    spread = float(dx @ dx)
    if spread == 0:
        raise ValueError(f"the {x_name} never changes: no slope")
    slope = float(dx @ (y - y.mean())) / spread
    return slope, float(y.mean() - slope * x.mean())


@dataclass(frozen=True)
class Summary:
    """Mean and spread of ``n`` repeated measurements (all in the unit of the values).

    Attributes
    ----------
    n : int
    mean : float
    sd : float
        Sample standard deviation (``ddof=1``); NaN when ``n == 1``.
    se : float
        Standard error of the mean, ``sd / sqrt(n)``; NaN when ``n == 1``.
    ci : (float, float)
        Confidence interval of the mean (:data:`CI_METHOD`); NaN when ``n == 1``.
    confidence : float
        Level of ``ci``, e.g. 0.95.
    """

    n: int
    mean: float
    sd: float
    se: float
    ci: tuple
    confidence: float

    def as_dict(self) -> dict:
        """Plain numbers for JSON; NaN (undefined for ``n == 1``) becomes None."""
        return {"n": self.n, "mean": _plain(self.mean), "sd": _plain(self.sd),
                "se": _plain(self.se), "ci": [_plain(self.ci[0]), _plain(self.ci[1])],
                "confidence": self.confidence, "ci_method": CI_METHOD}


def summarize(values, confidence: float = 0.95) -> Summary:
    """Summarize repeated measurements.

    Parameters
    ----------
    values : array_like, shape (n,)
        Finite values, n >= 1.
    confidence : float
        Level of the confidence interval, 0 < confidence < 1.

    Returns
    -------
    Summary

    Examples
    --------
    >>> s = summarize([1.0, 2.0, 3.0])
    >>> s.mean, s.sd, round(s.ci[1], 4)
    (2.0, 1.0, 4.4841)
    """
    x = np.asarray(values, dtype=float).ravel()
    if x.size == 0 or not np.all(np.isfinite(x)):
        raise ValueError(f"values must be finite and non-empty, got {x.tolist()}")
    if not 0.0 < confidence < 1.0:
        raise ValueError(f"confidence = {confidence!r} is invalid: must be in (0, 1)")
    n, mean = x.size, float(x.mean())
    if n == 1:
        return Summary(1, mean, math.nan, math.nan, (math.nan, math.nan), confidence)
    sd = float(x.std(ddof=1))
    se = sd / math.sqrt(n)
    half = float(stats.t.ppf(0.5 + confidence / 2.0, n - 1)) * se
    return Summary(n, mean, sd, se, (mean - half, mean + half), confidence)


def modified_z_scores(values) -> np.ndarray:
    """Robust z-scores ``0.6745 (x - median) / MAD`` (Iglewicz & Hoaglin).

    Median and MAD are not pulled by the outliers they are meant to find, unlike mean and
    SD. When the MAD is 0 (over half the values equal), the mean absolute deviation times
    1.2533 takes its place; when that is 0 too, every score is 0.

    Parameters
    ----------
    values : array_like, shape (n,)

    Returns
    -------
    ndarray, shape (n,)
    """
    x = np.asarray(values, dtype=float).ravel()
    deviation = x - np.median(x)
    mad = float(np.median(np.abs(deviation)))
    if mad > 0:
        return 0.6745 * deviation / mad
    mean_ad = float(np.mean(np.abs(deviation)))
    if mean_ad > 0:
        return deviation / (1.253314 * mean_ad)
    return np.zeros_like(x)


def flag_outliers(values, threshold: float = OUTLIER_THRESHOLD) -> np.ndarray:
    """Boolean mask of values whose absolute modified z-score exceeds ``threshold``.

    Flagged values are for a person to look at; no summary in this package drops them.

    Parameters
    ----------
    values : array_like, shape (n,)
    threshold : float
        3.5 by default, the cut Iglewicz & Hoaglin recommend.

    Returns
    -------
    ndarray of bool, shape (n,)
    """
    return np.abs(modified_z_scores(values)) > threshold


@dataclass(frozen=True)
class Ratio:
    """``numerator.mean / denominator.mean`` with first-order (delta-method) uncertainty.

    Attributes
    ----------
    value : float
    sd : float
        Propagated from the two SDs: ``|r| sqrt((sd_a/a)^2 + (sd_b/b)^2)``, the scatter a
        ratio of single trials would show (comparable with the thesis's "mean ± SD").
    se : float
        The same from the two standard errors: the uncertainty of the ratio of the means.
    """

    value: float
    sd: float
    se: float

    def as_dict(self) -> dict:
        """Plain numbers for JSON (NaN becomes None)."""
        return {"value": _plain(self.value), "sd": _plain(self.sd), "se": _plain(self.se),
                "method": "first-order propagation, numerator and denominator independent"}


def ratio_of_means(numerator: Summary, denominator: Summary) -> Ratio:
    """Ratio of two summarized means with propagated uncertainty.

    First order in the relative uncertainties, numerator and denominator independent (they
    come from different specimens' states); good while each relative SD is well under ~20 %.
    """
    if denominator.mean == 0:
        raise ValueError("the denominator's mean is 0: the ratio is undefined")
    value = numerator.mean / denominator.mean

    def propagate(a, b):
        return abs(value) * math.hypot(a / numerator.mean, b / denominator.mean)

    return Ratio(value, propagate(numerator.sd, denominator.sd),
                 propagate(numerator.se, denominator.se))
