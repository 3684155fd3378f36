"""Crease torsional stiffness from a folding test (thesis section 3.2, eqns 17-19).

A sample is two facets joined by the crease under test; the lower facet is taped to the
machine's base plate and a wedge pushes the upper one down at a distance ``Lp`` from the
crease (the vertex, seen edge-on by a camera)::

              upper marker
             /
            /  <- upper facet, pushed down at distance Lp along it
           / beta
    vertex o-------------o lower marker      (lower facet on the base plate)

Per run: a straight line fitted to the force-displacement record gives the forces F1, F2 at
the first and last video frames (the first and last samples of the record: the video spans
the test); three markers in each of those frames give the panel angles beta1, beta2 by the
cosine rule (17); the lever arm is d = Lp cos(beta1) (18); and

    k = (F2 - F1) d / (|beta2 - beta1| W)                          (19)

is the stiffness per unit crease length W, in N*mm/(rad*mm) = N/rad.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass

import numpy as np

from kresling.fits.statistics import (OUTLIER_THRESHOLD, Summary, fit_line, modified_z_scores,
                                      summarize)

__all__ = ["MARKERS", "panel_angle", "lever_arm", "end_forces", "stiffness_per_length",
           "panel_angles", "CreaseRun", "CreaseRunFit", "fit_crease_run", "CreaseStiffness",
           "summarize_crease", "fit_crease_runs"]

logger = logging.getLogger(__name__)

#: Order of the marker points in a frame's ``(3, 2)`` coordinate array.
MARKERS = ("vertex", "upper", "lower")

# Panel angles closer than this are "equal": far below what a camera resolves (1 px at
# 1000 px from the vertex is 1e-3 rad), and eqn 19 would divide by (almost) zero.
_ANGLE_RESOLUTION = 1e-9


def panel_angle(vertex, upper, lower) -> np.ndarray:
    """Angle between the panels at the vertex by the cosine rule (eqn 17).

    ``beta = acos((L_vu^2 + L_vl^2 - L_ul^2) / (2 L_vl L_vu))``.

    Parameters
    ----------
    vertex, upper, lower : array_like, shape (..., 2)
        Marker coordinates in any one length unit (pixels are fine: only ratios matter).

    Returns
    -------
    ndarray, shape (...)
        beta in rad, in [0, pi].
    """
    vertex, upper, lower = (np.asarray(p, dtype=float) for p in (vertex, upper, lower))
    L_vu = np.linalg.norm(upper - vertex, axis=-1)
    L_vl = np.linalg.norm(lower - vertex, axis=-1)
    L_ul = np.linalg.norm(upper - lower, axis=-1)
    if np.any(L_vu == 0) or np.any(L_vl == 0):
        raise ValueError("a panel marker coincides with the vertex: the angle is undefined")
    cosine = (L_vu**2 + L_vl**2 - L_ul**2) / (2.0 * L_vl * L_vu)
    # Rounding can push the cosine of a (nearly) flat or closed fold past ±1.
    return np.arccos(np.clip(cosine, -1.0, 1.0))


def lever_arm(Lp, beta1):
    """Horizontal distance from the vertex to the load, ``d = Lp cos(beta1)`` (eqn 18), mm."""
    return Lp * np.cos(beta1)


def end_forces(displacement, force) -> tuple[float, float]:
    """Forces at the first and last sample from a least-squares line through the record.

    Parameters
    ----------
    displacement : array_like, shape (m,)
        Machine displacement, mm; m >= 2 and not all equal.
    force : array_like, shape (m,)
        Force, N.

    Returns
    -------
    (F1, F2) : floats, N
        The fitted line at ``displacement[0]`` and ``displacement[-1]``.
    """
    x = np.asarray(displacement, dtype=float)
    slope, intercept = fit_line(x, force, "displacement")
    at = intercept + slope * x[[0, -1]]
    return float(at[0]), float(at[1])


def stiffness_per_length(F1, F2, beta1, beta2, d, W):
    """Crease stiffness per unit length ``(F2 - F1) d / (|beta2 - beta1| W)`` (eqn 19), N/rad.

    Forces in N, angles in rad, lever arm ``d`` and crease length ``W`` in mm.
    """
    return (F2 - F1) * d / (np.abs(beta2 - beta1) * W)


def panel_angles(markers_first, markers_last) -> tuple[float, float]:
    """beta1 and beta2 from the markers of the first and last frames, checked.

    Parameters
    ----------
    markers_first, markers_last : array_like, shape (3, 2)
        Rows in the order of :data:`MARKERS` (vertex, upper, lower), columns x, y.

    Raises
    ------
    ValueError
        Markers not shaped (3, 2), a panel marker on the vertex, or beta1 == beta2 (eqn 19
        would divide by zero).
    """
    angles = []
    for name, markers in (("markers_first", markers_first), ("markers_last", markers_last)):
        points = np.asarray(markers, dtype=float)
        if points.shape != (3, 2) or not np.all(np.isfinite(points)):
            raise ValueError(f"{name} must be 3 finite (x, y) points {MARKERS}, got "
                             f"{points.tolist()}")
        try:
            angles.append(float(panel_angle(*points)))
        except ValueError as error:
            raise ValueError(f"{name}: {error}") from None
    beta1, beta2 = angles
    if abs(beta2 - beta1) <= _ANGLE_RESOLUTION:
        raise ValueError(f"the first and last frames give the same panel angle "
                         f"(beta1 = {beta1:.6g} rad, beta2 = {beta2:.6g} rad): eqn 19 divides "
                         "by |beta2 - beta1|")
    return beta1, beta2


@dataclass(frozen=True)
class CreaseRun:
    """The raw data of one run of the crease test.

    Attributes
    ----------
    sample, run : str
        Labels.
    displacement, force : ndarray, shape (m,)
        The machine record, mm and N.
    markers_first, markers_last : ndarray, shape (3, 2)
        Vertex, upper and lower marker in the first and last video frames (any one unit).
    Lp : float
        Measured distance from the vertex to the load along the upper facet, mm.
    W : float
        Crease length, mm.
    source : str
        Where the run came from (file and line), for messages; may be empty.
    """

    sample: str
    run: str
    displacement: np.ndarray
    force: np.ndarray
    markers_first: np.ndarray
    markers_last: np.ndarray
    Lp: float
    W: float
    source: str = ""


@dataclass(frozen=True)
class CreaseRunFit:
    """Result of one run: forces F1, F2 (N), angles beta1, beta2 (rad), lever arm d (mm),
    stiffness per unit length k (N/rad)."""

    sample: str
    run: str
    F1: float
    F2: float
    beta1: float
    beta2: float
    d: float
    k: float
    source: str = ""

    def as_dict(self) -> dict:
        return {"sample": self.sample, "run": self.run, "F1": self.F1, "F2": self.F2,
                "beta1": self.beta1, "beta2": self.beta2, "d": self.d, "k": self.k}


def fit_crease_run(run: CreaseRun) -> CreaseRunFit:
    """Eqns 17-19 for one run.

    Raises
    ------
    ValueError
        Lp or W not > 0, a record of fewer than two points or constant displacement, or
        markers that give no angle or equal angles; the message starts with ``run.source``.
    """
    label = run.source or f"sample {run.sample} run {run.run}"
    try:
        for name in ("Lp", "W"):
            value = getattr(run, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} = {value!r} mm is invalid: must be > 0")
        beta1, beta2 = panel_angles(run.markers_first, run.markers_last)
        F1, F2 = end_forces(run.displacement, run.force)
    except ValueError as error:
        raise ValueError(f"{label}: {error}") from None
    d = float(lever_arm(run.Lp, beta1))
    k = float(stiffness_per_length(F1, F2, beta1, beta2, d, run.W))
    if not math.isfinite(k):
        raise ValueError(f"{label}: the crease stiffness k = {k!r} N/rad is not finite: the "
                         f"values are too large for eqns 17-19 (F1 = {F1:.3g} N, F2 = {F2:.3g} "
                         f"N, Lp = {run.Lp:.3g} mm, W = {run.W:.3g} mm)")
    if k <= 0:
        logger.warning("%s: k = %.4g N/rad is not positive (F2 - F1 = %.4g N, d = %.4g mm): "
                       "check the sign of force and displacement", label, k, F2 - F1, d)
    return CreaseRunFit(run.sample, run.run, F1, F2, beta1, beta2, d, k, run.source)


@dataclass
class CreaseStiffness:
    """Crease stiffness over runs and samples, N/rad.

    Attributes
    ----------
    samples, runs : ndarray of str, shape (n,)
    k : ndarray, shape (n,)
        Stiffness per run.
    overall : Summary
        Over all runs (as the thesis pools its 15 runs).
    per_sample : dict of str to Summary
    between_samples : Summary or None
        Over the sample means (None for one sample). Its interval is the one to quote when
        samples differ from one another: the runs of a sample are then not independent.
    z : ndarray, shape (n,)
        Modified z-score of each run (:func:`~kresling.fits.statistics.modified_z_scores`).
    outliers : ndarray of bool, shape (n,)
        ``|z| > 3.5``: flagged for a look, still included in every summary.
    fits : tuple of CreaseRunFit
        Per-run details when computed from raw records; empty for a table of stiffnesses.
    skipped : list of SkippedRow
    source : str
    """

    samples: np.ndarray
    runs: np.ndarray
    k: np.ndarray
    overall: Summary
    per_sample: dict
    between_samples: Summary | None
    z: np.ndarray
    outliers: np.ndarray
    fits: tuple = ()
    skipped: list = ()
    source: str = ""

    def as_dict(self) -> dict:
        """Everything as plain data (what ``kresling fit crease --json`` prints)."""
        result = {"source": self.source, "unit": "N/rad", **self.overall.as_dict()}
        result["samples"] = {label: s.as_dict() for label, s in self.per_sample.items()}
        result["between_samples"] = (self.between_samples.as_dict()
                                     if self.between_samples else None)
        result["outlier_rule"] = f"|modified z| > {OUTLIER_THRESHOLD} (flagged, not removed)"
        result["outliers"] = [{"sample": s, "run": r, "k": float(k), "z": float(z)} for s, r, k, z
                              in zip(self.samples, self.runs, self.k, self.z)
                              if abs(z) > OUTLIER_THRESHOLD]
        result["runs"] = ([f.as_dict() for f in self.fits] if self.fits else
                          [{"sample": s, "run": r, "k": float(k)}
                           for s, r, k in zip(self.samples, self.runs, self.k)])
        result["skipped"] = {"count": len(self.skipped), "rows": [str(s) for s in self.skipped]}
        return result


def summarize_crease(samples, runs, k, *, confidence: float = 0.95, fits=(), skipped=(),
                     source: str = "") -> CreaseStiffness:
    """Summaries of per-run stiffnesses: overall, per sample and between samples.

    Parameters
    ----------
    samples, runs : sequence of str, shape (n,)
        Labels of each run's sample and run.
    k : array_like, shape (n,)
        Stiffness per run, N/rad; n >= 2.
    confidence : float
        Level of the confidence intervals (:data:`~kresling.fits.statistics.CI_METHOD`).
    """
    k = np.asarray(k, dtype=float)
    samples = np.asarray([str(s) for s in samples], dtype=object)
    if k.size < 2:
        raise ValueError(f"{source or 'crease stiffness'}: {k.size} run(s); an SD needs 2")
    labels = list(dict.fromkeys(samples))  # first-appearance order
    with np.errstate(over="ignore", invalid="ignore"):  # overflow is reported below
        per_sample = {s: summarize(k[samples == s], confidence) for s in labels}
        means = [per_sample[s].mean for s in labels]
        spread = np.std(k)
    # Finite stiffnesses can still be too large to average (a mean or an SD that overflows):
    # say so, naming the run with the largest one, instead of returning inf.
    if not np.all(np.isfinite(means)) or not np.isfinite(spread):
        worst = int(np.argmax(np.abs(k)))
        origin = (fits[worst].source if fits and fits[worst].source else
                  f"sample {samples[worst]} run {runs[worst]}")
        raise ValueError(f"{source or 'crease stiffness'}: the stiffnesses are too large to "
                         f"summarize (k = {k[worst]:.3g} N/rad from {origin})")
    between = summarize(means, confidence) if len(labels) > 1 else None
    z = modified_z_scores(k)
    return CreaseStiffness(samples, np.asarray([str(r) for r in runs], dtype=object), k,
                           summarize(k, confidence), per_sample, between, z,
                           np.abs(z) > OUTLIER_THRESHOLD, tuple(fits), list(skipped), source)


def fit_crease_runs(runs, *, confidence: float = 0.95, skipped=(),
                    source: str = "") -> CreaseStiffness:
    """Fit every run (:func:`fit_crease_run`) and summarize (:func:`summarize_crease`)."""
    fits = [fit_crease_run(run) for run in runs]
    return summarize_crease([f.sample for f in fits], [f.run for f in fits],
                            [f.k for f in fits], confidence=confidence, fits=fits,
                            skipped=skipped, source=source)
