"""Synthetic laboratory records with a known truth, for testing the fits end to end.

The raw records behind the thesis's Tables 1 and 3 are not published, so the pipelines are
checked on records made here: a crease of known stiffness kf, or a specimen of known K_B,
"measured" by a testing machine and a camera with the noise model below. Every generator
takes a :class:`numpy.random.Generator`, so a seed fixes the records.

Noise model (independent, zero-mean normal, one SD each; the thesis states no instrument
noise, so these are assumed values typical of its instruments):

- force: 2 mN per sample on the crease test (a 25 lbf load cell read far below its range),
  5 mN on the bending test;
- displacement: 1 um per sample (crosshead encoder);
- video markers: 1 px per coordinate per marker (manual picking), at 15 px/mm;
- the measured lever length Lp: 0.25 mm (a ruler).

Physical model of the crease test: the upper facet turns about the crease against a linear
spring kf W while a wedge pushes it down at a fixed horizontal distance d = Lp cos(beta1):
``beta(y) = atan(tan(beta1) - y/d)`` and ``F(y) = F0 + kf W (beta1 - beta(y)) / d``
(F0: the small contact preload). Between-run and between-sample scatter of the true kf
(``run_cv``, ``sample_cv``) are off by default; they model what instrument noise does not
explain in the thesis's Table 1.

Physical model of the bending test: ``M(delta) = K delta + M_r (1 - exp(-delta/delta_r))``,
where the second term is the residual-stress rise of the contracted state (section 3.3):
``M_r = K * rise_angle`` (default rise_angle 0.02 rad) developing over ``delta_r`` = 0.005
rad, so it is complete (to e^-6) by the thesis's 0.03 rad offset. The extended state has no
rise. ``trial_cv`` scatters the true K between trials (off by default).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling.fits.bending import BendingTrial, state_name
from kresling.fits.crease import CreaseRun

__all__ = ["MachineRig", "CreaseRig", "crease_force", "synthetic_crease_runs", "BendingRig",
           "bending_moment", "synthetic_bending_trials"]


@dataclass(frozen=True)
class MachineRig:
    """A displacement-controlled test: ``travel`` mm at ``speed`` mm/s sampled at
    ``sample_rate`` Hz (the thesis: 5 mm at 0.1 mm/s), with the force (N) and displacement
    (mm) noise of the testing machine, one SD per sample."""

    travel: float = 5.0
    speed: float = 0.1
    sample_rate: float = 10.0
    force_sd: float = 0.005
    displacement_sd: float = 0.001

    def times(self) -> np.ndarray:
        """Sample times of one record, s, shape (m,)."""
        count = int(round(self.travel / self.speed * self.sample_rate)) + 1
        return np.arange(count) / self.sample_rate


@dataclass(frozen=True)
class CreaseRig(MachineRig):
    """The crease test set-up of section 3.2 and its noise (lengths mm, forces N, angles
    rad). Defaults: the thesis's samples (two 152.4 mm x 44.5 mm facets, crease along the
    long side), Table 1's range of Lp, and the noise model of the module docstring."""

    W: float = 152.4
    facet_depth: float = 44.5
    Lp_range: tuple = (29.8, 35.8)
    beta1_range: tuple = (math.radians(30.0), math.radians(40.0))
    preload_range: tuple = (0.005, 0.02)
    px_per_mm: float = 15.0
    marker_distance: float = 40.0
    force_sd: float = 0.002
    marker_sd: float = 1.0
    Lp_sd: float = 0.25


def crease_force(y, kf, W, d, beta1, preload=0.0):
    """Force on the wedge after a downward displacement ``y`` (mm), N.

    A facet hinged at the crease with rotational stiffness ``kf W`` (N*mm/rad), pushed at
    horizontal distance ``d`` (mm) from the vertex, starting at angle ``beta1`` (rad).
    """
    beta = np.arctan(np.tan(beta1) - np.asarray(y) / d)
    return preload + kf * W * (beta1 - beta) / d


def _markers(beta, rig: CreaseRig, origin, roll, rng) -> np.ndarray:
    """Noisy pixel coordinates of vertex, upper and lower marker, shape (3, 2)."""
    r = rig.marker_distance * rig.px_per_mm
    directions = np.array([[0.0, 0.0], [math.cos(beta), math.sin(beta)], [1.0, 0.0]])
    rotation = np.array([[math.cos(roll), -math.sin(roll)], [math.sin(roll), math.cos(roll)]])
    points = origin + r * directions @ rotation.T
    return points + rng.normal(0.0, rig.marker_sd, points.shape)


def _crease_run(sample, run, kf, rig: CreaseRig, rng) -> CreaseRun:
    Lp = rng.uniform(*rig.Lp_range)
    beta1 = rng.uniform(*rig.beta1_range)
    d = Lp * math.cos(beta1)
    y = rig.speed * rig.times()
    force = crease_force(y, kf, rig.W, d, beta1, rng.uniform(*rig.preload_range))
    beta2 = math.atan(math.tan(beta1) - y[-1] / d)
    origin = rng.uniform([300.0, 500.0], [500.0, 700.0])  # where the vertex sits in the frame
    roll = rng.normal(0.0, math.radians(1.0))  # the camera is never quite level
    return CreaseRun(
        str(sample), str(run),
        y + rng.normal(0.0, rig.displacement_sd, y.shape),
        force + rng.normal(0.0, rig.force_sd, y.shape),
        _markers(beta1, rig, origin, roll, rng), _markers(beta2, rig, origin, roll, rng),
        Lp + rng.normal(0.0, rig.Lp_sd), rig.W, source=f"synthetic sample {sample} run {run}")


def synthetic_crease_runs(kf: float, rng: np.random.Generator, *, samples: int = 5,
                          runs: int = 3, rig: CreaseRig = CreaseRig(), sample_cv: float = 0.0,
                          run_cv: float = 0.0):
    """Crease-test runs of a crease of known stiffness.

    Parameters
    ----------
    kf : float
        True stiffness per unit length, N/rad.
    rng : numpy.random.Generator
    samples, runs : int
        Samples, and runs per sample (the thesis: 5 x 3).
    rig : CreaseRig
        Set-up and noise model.
    sample_cv, run_cv : float
        Relative SD of the true kf between samples and between runs of a sample.

    Returns
    -------
    runs : list of CreaseRun, length samples * runs
    truth : ndarray, shape (samples * runs,)
        The true kf of each run, N/rad.
    """
    records, truth = [], []
    for sample in range(1, samples + 1):
        kf_sample = kf * (1.0 + sample_cv * rng.standard_normal())
        for run in range(1, runs + 1):
            kf_run = kf_sample * (1.0 + run_cv * rng.standard_normal())
            records.append(_crease_run(sample, run, kf_run, rig, rng))
            truth.append(kf_run)
    return records, np.array(truth)


@dataclass(frozen=True)
class BendingRig(MachineRig):
    """The bending test of section 3.3 and its noise, with the residual-stress rise of the
    contracted state (see the module docstring): ``rise_angle`` and ``rise_scale`` in rad."""

    rise_angle: float = 0.02
    rise_scale: float = 0.005


def bending_moment(angle, K, residual_moment=0.0, rise_scale=0.005):
    """``K delta + M_r (1 - exp(-delta / delta_r))``, N*m, for ``angle`` in rad."""
    angle = np.asarray(angle, dtype=float)
    return K * angle + residual_moment * -np.expm1(-angle / rise_scale)


def synthetic_bending_trials(K: float, state, module_length: float, rng: np.random.Generator,
                             *, trials: int = 3, rig: BendingRig = BendingRig(),
                             trial_cv: float = 0.0, rise: bool | None = None):
    """Bending trials of a specimen of known K_B.

    Parameters
    ----------
    K : float
        True bending stiffness, N*m/rad.
    state : {"extended", "contracted", 1, 0}
    module_length : float
        Lm, mm.
    rng : numpy.random.Generator
    trials : int
    rig : BendingRig
    trial_cv : float
        Relative SD of the true K between trials.
    rise : bool, optional
        Add the residual-stress rise; default: only in the contracted state.

    Returns
    -------
    trials : list of BendingTrial
    truth : ndarray, shape (trials,)
        The true K of each trial, N*m/rad.
    """
    state = state_name(state)
    rise = (state == "contracted") if rise is None else rise
    y = rig.speed * rig.times()
    angle = np.arctan(y / module_length)
    result, truth = [], []
    for index in range(trials):
        K_trial = K * (1.0 + trial_cv * rng.standard_normal())
        moment = bending_moment(angle, K_trial, K_trial * rig.rise_angle if rise else 0.0,
                                rig.rise_scale)
        force = moment * 1e3 / module_length
        result.append(BendingTrial(
            state, module_length, y + rng.normal(0.0, rig.displacement_sd, y.shape),
            force + rng.normal(0.0, rig.force_sd, y.shape),
            source=f"synthetic {state} trial {index + 1}"))
        truth.append(K_trial)
    return result, np.array(truth)
