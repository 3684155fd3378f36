"""Synthetic "measured" markers, made from the model with known perturbations.

The thesis's raw marker data is not published, so comparisons are exercised on data made
here. Each configuration's arm is rebuilt module by module with three kinds of error the
thesis names as its sources (section 4.3):

* module length: every (configuration, module) pair gets an offset drawn from
  N(0, module_length_sd): an extended module is ``2 Le + offset`` long, a contracted one
  rests at ``2 Lc + offset`` (manufacturing spread, gravity);
* bend efficiency: per configuration the flexible modules bend by a fraction
  ``e ~ N(bend_efficiency, bend_efficiency_sd)`` of the commanded tendon change (tendons
  only pull; the modules are not forced into rotation);
* measurement noise: N(0, noise_sd) on each coordinate of every marker but the base marker,
  the origin of the measurements (the thesis estimates 0.2 mm).

``python studies/manipulator.py --write-synthetic OUT.csv`` writes the file shipped as
``kresling/data/synthetic_manipulator_markers.csv`` (the defaults below, seed 20240607);
a test checks that the shipped file is what this module makes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling.manipulator.forward import to_plot_plane
from kresling.manipulator.markers import MarkerData
from kresling.manipulator.model import Manipulator, configuration_name
from kresling.manipulator.protocol import THESIS_STEPS, protocol_tendon_lengths

__all__ = ["MarkerPerturbation", "synthetic_markers", "SHIPPED_FILE"]

#: Name of the shipped synthetic data set (``kresling.data.path(SHIPPED_FILE)``).
SHIPPED_FILE = "synthetic_manipulator_markers.csv"


@dataclass(frozen=True)
class MarkerPerturbation:
    """The known errors put into synthetic markers (all lengths in mm)."""

    module_length_sd: float = 1.0
    bend_efficiency: float = 0.92
    bend_efficiency_sd: float = 0.03
    noise_sd: float = 0.2
    seed: int = 20240607

    @classmethod
    def none(cls) -> "MarkerPerturbation":
        """No perturbation: the synthetic markers are the model's predictions."""
        return cls(0.0, 1.0, 0.0, 0.0)


def _perturbed_markers(model, configuration, steps, offsets, efficiency) -> np.ndarray:
    """Markers (steps, m + 1, 3) of an arm whose module j is off by offsets[j] and whose
    flexible modules bend by `efficiency` of the commanded tendon change. Built module by
    module (twist-free frames) because the chain model has one length for all modules."""
    rest = model.rest_tendon_length
    commanded = np.atleast_2d(protocol_tendon_lengths(steps, rest))
    out = np.zeros((len(steps), model.modules + 1, 3))
    for i, lengths in enumerate(commanded):
        frame = np.eye(4)
        for j, state in enumerate(configuration):
            if state == 1:
                module = _core.kinematics.rigid_module_transform(model.extended_length + offsets[j])
            else:
                actual = rest + offsets[j] + efficiency * (lengths - rest)
                s, kappa, phi = _core.kinematics.arc_from_tendons(
                    actual, model.tendon_radius, model.segments)[0]
                module = _core.kinematics.flexible_module_transform(
                    s, kappa, phi, _core.kinematics.FrameConvention.twist_free)
            frame = frame @ module
            out[i, j + 1] = frame[:3, 3]
    return out


def synthetic_markers(model: Manipulator | None = None,
                      perturbation: MarkerPerturbation = MarkerPerturbation(),
                      steps=THESIS_STEPS, configurations=None) -> MarkerData:
    """Markers of every configuration and step, made from the model with known errors.

    Parameters
    ----------
    model : Manipulator, optional
        Default: the thesis's three-module arm.
    perturbation : MarkerPerturbation
    steps : array_like of int
    configurations : iterable, optional
        Default: all ``2**m``.

    Returns
    -------
    MarkerData
        In the thesis's plot coordinates, relative to the base marker.
    """
    model = Manipulator() if model is None else model
    configurations = model.configurations if configurations is None else [
        model.configuration(c) for c in configurations]
    rng = np.random.default_rng(perturbation.seed)
    steps = np.asarray(steps, dtype=int)
    config, step, marker, xy = [], [], [], []
    for configuration in configurations:
        offsets = rng.normal(0.0, perturbation.module_length_sd, model.modules)
        efficiency = rng.normal(perturbation.bend_efficiency, perturbation.bend_efficiency_sd)
        points = to_plot_plane(_perturbed_markers(model, configuration, steps, offsets, efficiency))
        noise = rng.normal(0.0, perturbation.noise_sd, points.shape)
        noise[:, 0, :] = 0.0  # the base marker is the origin of the measurements
        points = points + noise
        for i, k in enumerate(steps):
            for j in range(model.modules + 1):
                config.append(configuration_name(configuration)), step.append(k)
                marker.append(j + 1), xy.append(points[i, j])
    return MarkerData(np.array(config, dtype=str), np.array(step, dtype=int),
                      np.array(marker, dtype=int), np.array(xy))
