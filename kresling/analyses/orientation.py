"""The orientation study of Appendix A: is the bending stiffness axisymmetric?

The thesis bent its specimens about one axis only, after a preliminary linear study
(Appendix A, figure A-1) showed that K_B hardly changes when the bending axis is turned about
the specimen's axis. Here the linearised model (:mod:`kresling.analyses.linear_bending`)
turns the load direction and the pin line together by the bending axis angle beta.

The specimen is symmetric under a turn by 2 pi / n (every level is a regular n-gon) and
K_B(beta + pi) = K_B(beta), so one period is ``0 <= beta <= 2 pi / n`` (the thesis plotted
``[0, pi/n]``). Over it, K_B varies by under 0.25 % for the thesis's designs (n = 4 the
most, n = 10 about 0.01 %): axisymmetric, as the thesis reports. What does matter is the pin
line's angle *relative to* the load (``pin_offset``: 4-65 % at pi/n; docs/thesis_equations.md,
'Bending test').
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling.analyses.linear_bending import LinearBendingTester
from kresling._validation import as_float_array, as_finite_real, as_integer
from kresling.geometry import Design, as_design

__all__ = ["OrientationStudy", "orientation_study"]


@dataclass(frozen=True)
class OrientationStudy:
    """K_B of both states against the bending axis angle.

    Attributes
    ----------
    design : Design
    angles : ndarray, shape (A,)
        Bending axis angles beta [rad].
    extended, contracted : ndarray, shape (A,)
        Linearised K_B [N*m/rad].
    pin_offset : float
        Turn of the pin line relative to the load [rad] (0: perpendicular).
    """

    design: Design
    angles: np.ndarray
    extended: np.ndarray
    contracted: np.ndarray
    pin_offset: float = 0.0

    @property
    def ratio(self) -> np.ndarray:
        """K_ext / K_con at each angle, shape (A,)."""
        return self.extended / self.contracted

    def variation(self, quantity: str = "ratio") -> float:
        """Spread of ``quantity`` ("ratio", "extended" or "contracted") over the angles,
        ``(max - min) / mean``."""
        if quantity not in ("ratio", "extended", "contracted"):
            raise ValueError(f"quantity = {quantity!r} is invalid: must be 'ratio', 'extended' "
                             "or 'contracted'")
        values = getattr(self, quantity)
        return float(np.ptp(values) / np.mean(values))


def orientation_study(design: Design, angles=None, *, points: int = 25, pin_offset: float = 0.0,
                      parameters=None) -> OrientationStudy:
    """Linearised K_B of ``design`` in both states against the bending axis angle.

    Parameters
    ----------
    design : Design
        Even n.
    angles : array_like, optional
        Bending axis angles [rad]; default ``points`` angles over one period, ``[0, 2 pi/n]``.
    points : int, default 25
        1 to 10 000 (so many angles at most, given or not).
    pin_offset : float, default 0
        Turn of the pin line relative to the load [rad].
    parameters : SpecimenParameters, optional

    Returns
    -------
    OrientationStudy

    Examples
    --------
    >>> from kresling import Design
    >>> study = orientation_study(Design(10, 0.9, 15), points=5)
    >>> study.variation() < 1e-3
    True
    """
    design = as_design(design)
    if angles is None:
        angles = np.linspace(0.0, 2 * math.pi / design.n,
                             as_integer("points", points, minimum=1, maximum=10_000))
    angles = as_float_array("angles", angles).ravel()
    if angles.size > 10_000:
        raise ValueError(f"angles has {angles.size} entries: must have at most 10000")
    tester = LinearBendingTester(design.n, parameters=parameters)
    stiffness = {state: np.array([tester.run(design, state, angle=a, pin_offset=pin_offset)
                                  for a in angles]) for state in (0, 1)}
    return OrientationStudy(design=design, angles=angles, extended=stiffness[1],
                            contracted=stiffness[0],
                            pin_offset=as_finite_real("pin_offset", pin_offset))
