"""Tendon actuation of the arm as a structure, beside the constant-curvature model.

The thesis moves its arm by tendon lengths (motor counts, Appendix E) and predicts the shape
with constant-curvature kinematics (:mod:`kresling.manipulator`), treating contracted
modules as arcs whose three tendons sit exactly at their commanded lengths and extended
modules as rigid links. Here the same commands drive the bar-and-hinge arm: starting from the
pretensioned arm, each tendon's rest length is changed by the commanded amount (shortened:
pulled; lengthened: let out, the tendon slack until the arm's motion takes it up) and the
arm finds its equilibrium. Both models' markers (the base and every module end: the guide
centres of the structure) are compared step by step (thesis figures 4.13-4.15 with a
mechanical model beside the kinematic one).

The section 4.3 protocol: at step ``k`` every flexible module gets ``l1 = 2 Lc - 2k`` and
``l2 = l3 = 2 Lc + k``, so with ``f`` flexible modules tendon 1 is shortened by ``2 k f``
and tendons 2 and 3 are let out by ``k f`` (:func:`protocol_changes`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling._validation import show
from kresling.arm.analyses import DEFAULT_PRETENSION, ArmSolver, ArmState
from kresling.arm.structure import Arm
from kresling.manipulator import Manipulator, TendonDrive, forward_kinematics

__all__ = ["ActuationRun", "actuate", "protocol_changes", "pseudo_linkage_run",
           "kinematic_model", "guide_normals", "table5_comparison"]


def protocol_changes(configuration: str, steps) -> np.ndarray:
    """Rest-length changes of tendons 1-3 [mm] at protocol steps ``k`` (section 4.3):
    ``(-2 k f, k f, k f)`` for ``f`` contracted modules; shape (n, 3)."""
    f = configuration.count("0")
    k = np.asarray(steps, dtype=float).reshape(-1, 1)
    return f * k * np.array([[-2.0, 1.0, 1.0]])


def kinematic_model(arm: Arm) -> Manipulator:
    """The constant-curvature model of the same arm (same cell, modules and d)."""
    return Manipulator(modules=arm.modules, design=arm.design,
                       tendon_radius=arm.parameters.tendon_radius)


@dataclass(frozen=True)
class ActuationRun:
    """Tendon commands in, the structure's shape and the kinematic model's out.

    Attributes
    ----------
    configuration : str
    changes : ndarray (n, 3)
        Rest-length change of tendons 1-3 from the pretensioned arm [mm] (negative:
        shortened).
    motor_counts : ndarray (n, 3)
        The same commands as encoder counts of tendons 1-3 (Appendix E's pulleys and
        encoders; negative: reeling in).
    states : list of ArmState
        The structure's equilibrium at each step reached.
    markers : ndarray (n, m + 1, 3)
        Base and module ends of the structure (guide centres) [mm]; NaN after the path
        stopped.
    kinematic_markers : ndarray (n, m + 1, 3)
        The constant-curvature model's markers for the same tendon lengths [mm].
    marker_error : ndarray (n, m + 1)
        Distance between the two [mm].
    tip_error : ndarray (n,)
        [mm]
    bend_direction, kinematic_bend_direction : ndarray (n,)
        Azimuth of the tip's sideways displacement, atan2(y, x) [rad] (0: towards tendon 1;
        NaN where the tip lies within 0.05 mm of the axis).
    bend_angles, kinematic_bend_angles : ndarray (n, m)
        Each module's bend: the angle between the normals of its two guides (the z axes of
        its end frames in the kinematic model) [rad].
    tension : ndarray (n, 3)
        [N]
    completed : bool
        Every step reached; otherwise ``message`` says where the path stopped (a module
        snapped, or equilibrium was lost).
    message : str
    """

    configuration: str
    changes: np.ndarray
    motor_counts: np.ndarray
    states: list
    markers: np.ndarray
    kinematic_markers: np.ndarray
    marker_error: np.ndarray
    tip_error: np.ndarray
    bend_direction: np.ndarray
    kinematic_bend_direction: np.ndarray
    bend_angles: np.ndarray
    kinematic_bend_angles: np.ndarray
    tension: np.ndarray
    completed: bool
    message: str

    @property
    def module_lengths(self) -> np.ndarray:
        """Guide-centre distance of each module per step [mm], shape (n, m)."""
        return np.linalg.norm(np.diff(self.markers, axis=1), axis=2)


def _azimuth(points: np.ndarray) -> np.ndarray:
    xy = points[:, :2]
    out = np.arctan2(xy[:, 1], xy[:, 0])
    out[~(np.linalg.norm(xy, axis=1) >= 0.05)] = math.nan
    return out


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    return math.atan2(np.linalg.norm(np.cross(a, b)), float(a @ b))


def guide_normals(arm: Arm, positions: np.ndarray) -> np.ndarray:
    """Unit normal of every guide's plane (base first), pointing up the arm, (m + 1, 3)."""
    normals = []
    for g in range(arm.modules + 1):
        ring = positions[[arm.node(2 * g, j) for j in range(arm.n)]]
        _, _, vt = np.linalg.svd(ring - ring.mean(axis=0))
        normal = vt[-1]
        reference = (positions[arm.node(2 * g + 1, arm.n)] - ring.mean(axis=0)
                     if g < arm.modules else
                     ring.mean(axis=0) - positions[arm.node(2 * g - 1, arm.n)])
        normals.append(normal if normal @ reference > 0 else -normal)
    return np.array(normals)


def actuate(arm: Arm, changes, *, pretension: float = DEFAULT_PRETENSION,
            solver: ArmSolver | None = None) -> ActuationRun:
    """Drive ``arm`` through tendon rest-length changes, step by step.

    Parameters
    ----------
    arm : Arm
    changes : array_like (n, 3)
        Change of each tendon's rest length from the pretensioned arm at each step [mm]
        (negative: pulled in).
    pretension : float
        Tension of each tendon before the first step [N] (> 0).

    The kinematic model gets, per flexible module, ``2 Lc + change / f`` (the commands
    shared equally by the ``f`` contracted modules, as the thesis assumes); configurations
    without a contracted module have no kinematic bend (their markers are the straight
    chain). A step the solver does not reach ends the run (``completed`` False); a
    pretension it does not reach raises
    :class:`~kresling.arm.analyses.EquilibriumNotReached`.
    """
    changes = np.atleast_2d(np.asarray(changes, dtype=float))
    if changes.ndim != 2 or changes.shape[1] != 3 or not np.isfinite(changes).all():
        raise ValueError(f"changes has shape {changes.shape}: must be (n, 3), finite [mm]")
    solver = ArmSolver(arm) if solver is None else solver
    start = solver.pretension(pretension)
    m, f = arm.modules, arm.configuration.count("0")
    model = kinematic_model(arm)
    drive = TendonDrive()
    states, message, completed = [], "", True
    current = start
    for change in changes:
        pulls = start.pulls - change
        path, done, why = solver.ramp(current, pulls)
        if not done:
            completed, message = False, f"step {len(states)}: {why}"
            break
        current = path[-1]
        states.append(current)
    n = len(changes)
    markers = np.full((n, m + 1, 3), math.nan)
    tension = np.full((n, 3), math.nan)
    bends = np.full((n, m), math.nan)
    for i, s in enumerate(states):
        x = arm.model.nodes + s.displacement.reshape(-1, 3)
        markers[i] = arm.guide_centres(x)
        tension[i] = s.tension
        normals = guide_normals(arm, x)
        bends[i] = [_angle(normals[j], normals[j + 1]) for j in range(m)]
    rest = 2 * arm.design.Lc
    kinematic = np.empty((n, m + 1, 3))
    kinematic_bends = np.empty((n, m))
    for i, change in enumerate(changes):
        lengths = rest + change / f if f else None
        chain = forward_kinematics(model, arm.configuration, lengths)
        kinematic[i] = chain.markers
        z = chain.frames[:, :3, 2]
        kinematic_bends[i] = [_angle(z[j], z[j + 1]) for j in range(m)]
    error = np.linalg.norm(markers - kinematic, axis=2)
    counts = drive.sign * drive.counts_per_mm * (-changes)
    return ActuationRun(arm.configuration, changes, counts, states, markers, kinematic, error,
                        error[:, -1], _azimuth(markers[:, -1]), _azimuth(kinematic[:, -1]),
                        bends, kinematic_bends, tension, completed, message)


def pseudo_linkage_run(arm: Arm, steps=range(0, 11), *, pretension: float = DEFAULT_PRETENSION,
                       solver: ArmSolver | None = None) -> ActuationRun:
    """The section 4.3 protocol (:func:`protocol_changes`) on the structure.

    Examples
    --------
    >>> from kresling.arm import build_arm
    >>> run = pseudo_linkage_run(build_arm("0"), steps=[0, 1, 2])
    >>> run.completed, bool(run.markers[-1, -1, 0] > 0)   # bends towards tendon 1 (+x)
    (True, True)
    """
    if "0" not in arm.configuration:
        raise ValueError(f"configuration = {show(arm.configuration)}: the protocol bends "
                         "contracted modules; this arm has none")
    return actuate(arm, protocol_changes(arm.configuration, list(steps)), pretension=pretension,
                   solver=solver)


def table5_comparison(*, steps=range(0, 11), pretension: float = DEFAULT_PRETENSION,
                      **arm_options) -> list:
    """Module lengths of the three-module arm under the section 4.3 protocol, predicted by the
    structure, beside the kinematic model's and Table 5's measured ranges.

    A prediction, not a fit: nothing is tuned to Table 5 (the pretension and the tendon's
    stiffness are the assumptions of :mod:`kresling.arm.analyses`). The all-extended
    configuration (111) has no protocol (no module bends): its modules are measured once,
    and predicted at the pretensioned state.

    Returns
    -------
    list of dict
        One per Table 5 row: ``config``, ``joint`` (1-based from the base), ``state``,
        ``min_mm``/``max_mm`` (measured), ``kinematic_min_mm``/``kinematic_max_mm`` (the
        constant-curvature model: ``2 Lc`` and ``2 Le``), ``predicted_min_mm``/
        ``predicted_max_mm`` (the structure), ``inside`` (the predicted range within the
        measured one, widened by Table 5's 0.1 mm rounding) and ``outside_by_mm`` (how far
        it lies outside, 0 when inside), and ``completed`` (every step reached).
    """
    from kresling.arm.structure import build_arm
    from kresling.manipulator.joint_lengths import read_table5

    runs = {}
    rows = []
    for row in read_table5():
        config = row["config"]
        if config not in runs:
            arm = build_arm(config, **arm_options)
            if "0" in config:
                runs[config] = pseudo_linkage_run(arm, steps, pretension=pretension)
            else:
                runs[config] = actuate(arm, np.zeros((1, 3)), pretension=pretension)
        run = runs[config]
        j = row["joint"] - 1
        predicted = run.module_lengths[:, j]
        predicted = predicted[np.isfinite(predicted)]
        kinematic = np.linalg.norm(np.diff(run.kinematic_markers, axis=1), axis=2)[:, j]
        lo, hi = float(predicted.min()), float(predicted.max())
        outside = max(row["min_mm"] - 0.05 - lo, hi - row["max_mm"] - 0.05, 0.0)
        rows.append(dict(row, kinematic_min_mm=float(kinematic.min()),
                         kinematic_max_mm=float(kinematic.max()), predicted_min_mm=lo,
                         predicted_max_mm=hi, inside=outside == 0.0, outside_by_mm=outside,
                         completed=run.completed))
    return rows
