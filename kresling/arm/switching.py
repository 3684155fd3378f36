"""Switching by pulling: which pulls reach which configurations.

From a configuration, tendons are shortened (all three together, or one alone) until the
first module snaps (:func:`~kresling.arm.analyses.pull_until_snap`); the arm is then
released and comes to rest in a new configuration. Tendons only pull, so pulling can
contract an extended module but never extend a contracted one; and a pulled module snaps
one cell at a time: its tendons slacken as the cell drops, and the other cell re-extends
(the module ends half-switched, written 'x'), unless the pull goes on.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling._validation import as_integer
from kresling.arm.analyses import ArmSolver, pull_until_snap
from kresling.arm.structure import all_configurations, build_arm
from kresling.manipulator import TendonDrive

__all__ = ["PULLS", "Switch", "switching_map"]

#: The pulls of the map: all three tendons together, or one alone (relative pulls).
PULLS = {"all": (1.0, 1.0, 1.0), "tendon 1": (1.0, 0.0, 0.0), "tendon 2": (0.0, 1.0, 0.0),
         "tendon 3": (0.0, 0.0, 1.0)}


@dataclass(frozen=True)
class Switch:
    """One pull from one configuration.

    Attributes
    ----------
    start, pull : str
        The configuration pulled and the pull's name (:data:`PULLS`).
    snapped : bool
    snapped_module : int
        0-based from the base (-1: none).
    end : str
        Where the released arm rests ('x': a half-switched module); ``start`` if nothing
        snapped.
    pull_mm : float
        Largest tendon pull at the snap [mm].
    tension_sum : float
        Sum of the tendon tensions at the snap [N].
    motor_counts : ndarray (3,)
        The pulls at the snap as encoder counts of tendons 1-3 (Appendix E's drive).
    message : str
    """

    start: str
    pull: str
    snapped: bool
    snapped_module: int
    end: str
    pull_mm: float
    tension_sum: float
    motor_counts: np.ndarray
    message: str


def switching_map(modules: int = 3, *, pulls: dict | None = None,
                  configurations=None, **arm_options) -> list:
    """Every pull of :data:`PULLS` from every configuration with an extended module.

    ``arm_options`` go to :func:`~kresling.arm.structure.build_arm`. Each pull runs up to
    ``2 (Le - Lc)`` per extended module (see :func:`~kresling.arm.analyses.pull_until_snap`).
    """
    modules = as_integer("modules", modules, minimum=1)
    pulls = PULLS if pulls is None else pulls
    configurations = all_configurations(modules) if configurations is None else configurations
    drive = TendonDrive()
    out = []
    for start in configurations:
        if "1" not in start:
            continue  # nothing a pull can switch
        arm = build_arm(start, **arm_options)
        solver = ArmSolver(arm)
        for name, direction in pulls.items():
            r = pull_until_snap(arm, direction, solver=solver)
            counts = drive.sign * drive.counts_per_mm * r.pulls
            out.append(Switch(start, name, r.snapped, r.snapped_module,
                              r.configuration_after if r.snapped else start, r.pull,
                              r.tension_sum, counts, r.message))
    return out
