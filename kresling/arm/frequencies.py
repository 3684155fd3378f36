"""Natural frequencies of the arm in a configuration: the stiffness switch in the modes.

The modes (:func:`kresling.analyses.modes.vibration_modes`) are taken about the arm
pretensioned as for a tip load (1 N per tendon by default), the tendons held at their
lengths (:func:`kresling.arm.gravity.held_tendons_model`), with the masses of the thesis's
materials (:func:`kresling.arm.masses.arm_masses`); the base guide and its holes are fixed.
"""

from __future__ import annotations

from dataclasses import dataclass

from kresling._validation import as_integer
from kresling.analyses.modes import Modes, vibration_modes
from kresling.arm.analyses import DEFAULT_PRETENSION, ArmSolver
from kresling.arm.gravity import held_tendons_model, pretensioned
from kresling.arm.masses import arm_masses

__all__ = ["ArmFrequencies", "arm_frequencies"]


@dataclass(frozen=True)
class ArmFrequencies:
    """The lowest modes of the arm in one configuration.

    Attributes
    ----------
    configuration : str
    modes : Modes
    mass : float
        The arm's mass [t].
    """

    configuration: str
    modes: Modes
    mass: float


def arm_frequencies(configuration="111", *, k: int = 6,
                    pretension: float = DEFAULT_PRETENSION, measured_skeleton: bool = False,
                    **arm_options) -> ArmFrequencies:
    """The ``k`` lowest natural frequencies of the pretensioned arm.

    Parameters
    ----------
    configuration : str, default "111"
        Module states from the base.
    k : int, default 6
        Modes (1 to 30).
    pretension : float
        Tension of each tendon [N].
    measured_skeleton : bool, default False
        Masses scaled to the thesis's weighed skeleton (:func:`arm_masses`).
    **arm_options
        Passed to :func:`kresling.arm.build_arm`.

    Examples
    --------
    >>> f = arm_frequencies("000", k=2)
    >>> [round(float(v), 2) for v in f.modes.frequencies_hz]
    [6.97, 7.0]
    """
    from kresling.arm.structure import build_arm

    k = as_integer("k", k, minimum=1, maximum=30)
    arm = build_arm(configuration, **arm_options)
    state = pretensioned(ArmSolver(arm), pretension)
    masses = arm_masses(arm, measured_skeleton=measured_skeleton)
    modes = vibration_modes(held_tendons_model(arm, state.pulls), masses.node, k,
                            u=state.displacement)
    return ArmFrequencies(configuration, modes, masses.total)
