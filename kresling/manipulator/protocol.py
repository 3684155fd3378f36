"""The pseudo-linkage evaluation of thesis section 4.3.

Every flexible module gets ``l1 = rest - 2k``, ``l2 = l3 = rest + k`` at step k = 1..10
(``Delta l2 = Delta l3 = -Delta l1 / 2``; the motors move tendon 1 by ``2 f k`` in total
for f flexible modules). The mean tendon length stays at ``rest``, which for N = 1 is the
module's marker-to-marker chord: the modules behave as revolute joints of fixed length,
bending in the plane of tendon 1 by ``2 asin(k / d)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_finite_real, as_float_array, show
from kresling.manipulator.forward import MarkerViews, forward_kinematics
from kresling.manipulator.model import Manipulator

__all__ = ["protocol_tendon_lengths", "ProtocolRun", "pseudo_linkage", "protocol_deviations",
           "THESIS_STEPS"]

#: The thesis's displacement steps (0 is the rest state, photographed too).
THESIS_STEPS = tuple(range(0, 11))


def protocol_tendon_lengths(k, rest_length: float = 30.0) -> np.ndarray:
    """Tendon lengths of one flexible module at protocol step(s) ``k`` [mm].

    Parameters
    ----------
    k : float or array_like, shape (n,)
        Displacement step(s); the thesis uses 1..10 (0 = rest).
    rest_length : float
        Tendon length at rest [mm] (``2 Lc`` = 30 mm).

    Returns
    -------
    ndarray, shape (3,) or (n, 3)
        ``(rest - 2k, rest + k, rest + k)``.
    """
    k = as_float_array("k", k)
    rest_length = as_finite_real("rest_length", rest_length)
    with np.errstate(over="ignore"):
        lengths = np.stack([rest_length - 2 * k, rest_length + k, rest_length + k], axis=-1)
    if not np.isfinite(lengths).all():
        raise ValueError(f"k = {show(k.tolist())} is invalid: must be finite numbers whose "
                         f"tendon lengths rest_length - 2 k, rest_length + k are finite [mm]")
    return lengths


@dataclass(frozen=True)
class ProtocolRun(MarkerViews):
    """Predicted markers of one configuration over the protocol's steps.

    Attributes
    ----------
    configuration : tuple of int
    steps : ndarray, shape (n,)
    tendon_lengths : ndarray, shape (n, 3)
        Tendon lengths of every flexible module at each step [mm].
    markers : ndarray, shape (n, m + 1, 3)
        Base and module-end positions [mm] in the frame of eqn 26.
    """

    configuration: tuple
    steps: np.ndarray
    tendon_lengths: np.ndarray
    markers: np.ndarray

    @property
    def path_lengths(self) -> np.ndarray:
        """Length of the arm from the base to each marker along the chain of marker-to-marker
        segments [mm], shape (n, m + 1) (0 at the base)."""
        return np.concatenate([np.zeros((len(self.steps), 1)),
                               np.cumsum(self.module_lengths, axis=1)], axis=1)

    def at(self, step) -> np.ndarray:
        """Markers at one step [mm], shape (m + 1, 3)."""
        matches = np.flatnonzero(self.steps == step)
        if matches.size == 0:
            raise ValueError(f"step = {step!r} is invalid: must be one of {self.steps.tolist()}")
        return self.markers[matches[0]]


def pseudo_linkage(model: Manipulator, configuration, steps=THESIS_STEPS) -> ProtocolRun:
    """Predicted markers of ``configuration`` under the section 4.3 protocol.

    Parameters
    ----------
    model : Manipulator
    configuration : str or sequence of int
    steps : array_like of float
        Displacement steps k (default 0..10).

    Returns
    -------
    ProtocolRun

    Raises
    ------
    ValueError
        For a bad configuration, or a step beyond which tendon 1 would be negative or no arc
        realises the lengths.
    """
    configuration = model.configuration(configuration)
    steps = np.atleast_1d(as_float_array("steps", steps))
    lengths = np.atleast_2d(protocol_tendon_lengths(steps, model.rest_tendon_length))
    markers = _core.kinematics.markers_of_identical_modules(model._chain, configuration, lengths)
    return ProtocolRun(configuration, steps, lengths, markers)


def protocol_deviations(model: Manipulator, steps=range(1, 11)) -> tuple[float, float]:
    """Largest deviation of a flexible module's chord from the rest tendon length [mm] and of
    its bend from ``2 asin(k / d)`` [rad], over every configuration and step."""
    chord_error = bend_error = 0.0
    for configuration in model.configurations:
        if 0 not in configuration:
            continue
        for k in steps:
            state = forward_kinematics(model, configuration,
                                       protocol_tendon_lengths(k, model.rest_tendon_length))
            for j in (j for j, s in enumerate(configuration) if s == 0):
                chord = np.linalg.norm(state.markers[j + 1] - state.markers[j])
                a, b = state.frames[j][:3, 2], state.frames[j + 1][:3, 2]
                bend = math.atan2(np.linalg.norm(np.cross(a, b)), float(a @ b))
                chord_error = max(chord_error, abs(chord - model.rest_tendon_length))
                bend_error = max(bend_error, abs(bend - 2 * math.asin(k / model.tendon_radius)))
    return chord_error, bend_error
