"""Tendon inputs as motor encoder counts (thesis Appendix E, Appendix D).

Each tendon is wound on a pulley driven by a DC motor with a quadrature encoder. A change of
tendon length becomes counts through ``counts per mm = PPR * quadrature / (pi * D)``
(4704 / (pi * 20 mm) = 74.87 counts/mm for the thesis's 1176 PPR, 4x decoding and 20 mm
pulleys). Zero counts is the rest configuration (every contracted module's tendons at
``2 Lc``).

Numbering and sign, kept explicit because Appendix E's printout permutes them: it prints
``Counts 1 = -counts3``, ``Counts 2 = -counts2``, ``Counts 3 = -counts1``, where
``counts_i = (2 Lc - l_i) f`` in counts is tendon i's shortening. So motor 1 drives
tendon 3, motor 3 drives tendon 1, and a positive count pays tendon out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling._validation import as_finite_real, as_integer
from kresling.manipulator.constant_curvature import arc_from_tendons
from kresling.manipulator.forward import flexible_tendon_rows
from kresling.manipulator.model import Manipulator

__all__ = ["TendonDrive"]


@dataclass(frozen=True)
class TendonDrive:
    """Pulleys, encoders and the tendon-to-motor wiring.

    Parameters
    ----------
    pulley_diameter : float, default 20.0
        [mm] (the thesis's 0.02 m).
    pulses_per_revolution : int, default 1176
        Encoder pulses per output revolution (Appendix D).
    quadrature : int, default 4
        Counts per pulse (4x quadrature decoding).
    motor_of_tendon : tuple of int, default (3, 2, 1)
        Motor number (1-based) driving tendon 1, 2, 3 (Appendix E's printout).
    sign : {-1, +1}, default -1
        Counts per mm of tendon shortening divided by ``counts_per_mm``: -1 means reeling
        a tendon in is a negative count, as Appendix E prints.
    """

    pulley_diameter: float = 20.0
    pulses_per_revolution: int = 1176
    quadrature: int = 4
    motor_of_tendon: tuple = (3, 2, 1)
    sign: int = -1

    def __post_init__(self):
        if not as_finite_real("pulley_diameter", self.pulley_diameter) > 0:
            raise ValueError(f"pulley_diameter = {self.pulley_diameter!r} is invalid: must be > 0 (mm)")
        as_integer("pulses_per_revolution", self.pulses_per_revolution, minimum=1)
        as_integer("quadrature", self.quadrature, minimum=1)
        if not isinstance(self.motor_of_tendon, (tuple, list)) or sorted(
                as_integer("motor_of_tendon", m) for m in self.motor_of_tendon) != [1, 2, 3]:
            raise ValueError(f"motor_of_tendon = {self.motor_of_tendon!r} is invalid: "
                             "must be a permutation of (1, 2, 3)")
        if self.sign not in (-1, 1):
            raise ValueError(f"sign = {self.sign!r} is invalid: must be -1 or +1")

    @property
    def counts_per_revolution(self) -> int:
        """Encoder counts per pulley revolution (4704)."""
        return self.pulses_per_revolution * self.quadrature

    @property
    def counts_per_mm(self) -> float:
        """Encoder counts per mm of tendon: ``counts_per_revolution / (pi * pulley_diameter)``."""
        return self.counts_per_revolution / (math.pi * self.pulley_diameter)

    def tendon_shortening(self, model: Manipulator, configuration, tendon_lengths) -> np.ndarray:
        """How much each tendon is reeled in from rest, summed over the flexible modules [mm].

        Returns
        -------
        ndarray, shape (3,)
            Tendons 1, 2, 3; ``f (2 Lc - l_i)`` for identical modules.
        """
        configuration = model.configuration(configuration)
        rows = flexible_tendon_rows(configuration, tendon_lengths)
        if len(rows):  # lengths the modules can take (an arc realises them), as the chain's
            arc_from_tendons(rows, model.tendon_radius, model.segments)
        return (model.rest_tendon_length - rows).sum(axis=0)

    def motor_counts(self, model: Manipulator, configuration, tendon_lengths) -> np.ndarray:
        """Encoder counts per motor (motor 1, 2, 3) that set the tendon lengths, from rest.

        Returns
        -------
        ndarray, shape (3,)

        Examples
        --------
        >>> arm = Manipulator()
        >>> TendonDrive().motor_counts(arm, "101", [10.0, 40.0, 40.0]).round(2)
        array([  748.66,   748.66, -1497.33])
        """
        shortening = self.tendon_shortening(model, configuration, tendon_lengths)
        counts = np.empty(3)
        for tendon, motor in enumerate(self.motor_of_tendon):
            counts[motor - 1] = self.sign * shortening[tendon] * self.counts_per_mm
        return counts

    def snap_counts(self, model: Manipulator) -> float:
        """Counts of tendon travel that snap one module between its states:
        ``2 (Le - Lc)`` of tendon length per module (Appendix E's ``snapCounts``)."""
        return (model.extended_length - model.rest_tendon_length) * self.counts_per_mm
