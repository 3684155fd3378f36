"""``[[actuation]]`` in a motion in time (``method = "dynamic"``): each entry's creases'
rest angles as functions of time (docs/dynamics.md, 'Creases driven in time').

A driven crease's rest angle at time t is its rest angle at the start of the run plus
``factor(t) * delta``: for a time that drives to a target (step, ramp, table) ``delta`` is
the way from the start to the target fold angle, so the factor is the fraction of it; for a
harmonic or a chirp ``delta`` is one degree of fold angle (FOLD's convention, + valley), so
the factor is the fold angle's change from the start [deg].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.model.fold_angles import hinge_fold_signs, rest_angles_for
from kresling.simulate.fold_plan import actuated_creases
from kresling.simulate.problem_keys.dynamics import OSCILLATING, LoadTime

__all__ = ["CreaseDrive", "crease_drives", "rest_angles_at"]


@dataclass(frozen=True)
class CreaseDrive:
    """One ``[[actuation]]`` entry of a motion.

    Attributes
    ----------
    entry : int
        The entry's index in the problem's ``[[actuation]]`` (0-based).
    hinges : ndarray of int, shape (K,)
        The model hinges it drives (a hinge a later entry also names is the later's).
    delta : ndarray, shape (K,)
        Each rest angle's change per unit of the factor [rad].
    time : LoadTime or None
        The factor in time (None: a step, 1 from t = 0).
    """

    entry: int
    hinges: np.ndarray
    delta: np.ndarray
    time: LoadTime | None

    def for_solver(self) -> tuple:
        """The drive as :func:`kresling.solvers.solve_dynamics` takes an actuation."""
        return (self.hinges, self.delta, None if self.time is None else self.time.for_solver())

    def factor(self, times) -> np.ndarray:
        """The factor at ``times`` [s], shape (T,), as the integrator evaluates it."""
        from kresling.solvers.dynamics import time_factor
        return time_factor(None if self.time is None else self.time.for_solver(), times)


def crease_drives(problem, pattern_model) -> tuple:
    """The problem's actuation as drives in time, from the model's rest angles (where the
    run starts). A ValueError names an entry whose creases it would take beyond a flat
    fold (a rest angle outside [0, 2 pi)) at some time."""
    start = np.asarray(pattern_model.model.hinge_rest_angle, dtype=float)
    signs = hinge_fold_signs(pattern_model)
    creases = actuated_creases(problem, pattern_model)
    owner = {hinge: i for i, driven in enumerate(creases) for hinge, _ in driven.values()}
    drives = []
    for i, (entry, driven) in enumerate(zip(problem.actuations, creases)):
        kept = [(edge, hinge, angle) for edge, (hinge, angle) in driven.items()
                if owner[hinge] == i]
        if not kept:
            continue
        hinges = np.array([hinge for _, hinge, _ in kept], dtype=np.int64)
        time = entry.time
        if time is not None and time.kind in OSCILLATING:
            delta = -signs[hinges] * np.pi / 180.0   # one degree more valley
        else:
            delta = rest_angles_for([angle for _, _, angle in kept], signs[hinges]) - start[hinges]
        for factor in (time or LoadTime()).factor_range():
            reached = start[hinges] + factor * delta
            beyond = np.flatnonzero((reached < 0.0) | (reached >= 2.0 * np.pi))
            if beyond.size:
                k = int(beyond[0])
                fold = np.degrees(signs[hinges[k]] * (np.pi - start[hinges[k]]))
                raise ValueError(
                    f"{problem.source}: actuation[{i}] key 'time': at a factor of {factor:g} "
                    f"it takes crease {list(kept[k][0])} from its fold angle at the start "
                    f"({fold:.6g} deg) beyond a flat fold: a fold angle must stay in "
                    "[-180, 180] deg")
        drives.append(CreaseDrive(i, hinges, delta, time))
    return tuple(drives)


def rest_angles_at(model, drives, time: float) -> np.ndarray:
    """Every hinge's rest angle at ``time`` [s], shape (H,) [rad]: the model's (the
    start's) where no drive moves it."""
    start = np.asarray(model.hinge_rest_angle, dtype=float)
    rest = start.copy()
    for drive in drives:
        rest[drive.hinges] = start[drive.hinges] + drive.factor(time)[0] * drive.delta
    return rest
