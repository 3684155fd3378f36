"""Closing the loop in simulation: how precisely the arm reaches a point when the arm that
moves is not the controller's model.

The "true" arm differs from the controller's model as a built one would: its crease
stiffness, its cells' contracted height and its tendons' distance from the axis are drawn
(seeded) around the nominal values. The controller plans on its own model
(:func:`~kresling.arm.reach.reach`), sends the pulls, reads the tip through a camera whose
markers carry a 0.2 mm error (each coordinate, normal), and corrects the pulls on its own
model's tip Jacobian:

    P <- P + argmin_{dP, P + dP >= P_min} |J_model(P) dP - (target - measured tip)|,

with ``P_min`` the tendons let out by 90 % of the pretension's pull (still taut: a correction
may need less pull than the plan's zero).

Reported per target: the open-loop error of the constant-curvature model's pulls, of the
structural model's pulls, and the closed-loop error after each correction (the true tip's
distance from the target, not the measured one).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from kresling.arm.actuation import kinematic_model
from kresling.arm.analyses import DEFAULT_PRETENSION, ArmSolver
from kresling.arm.reach import reach, tip_jacobian
from kresling.arm.structure import ArmParameters, build_arm

__all__ = ["PERTURBATION", "CAMERA_ERROR", "ClosedLoopRun", "perturbed_parameters",
           "closed_loop"]

#: The spread of the true arm around the model (one standard deviation): the crease
#: stiffness (relative), the cells' contracted height [mm] and the tendons' radius [mm].
PERTURBATION = {"kf": 0.10, "Lc": 0.3, "tendon_radius": 0.3}
#: The camera's error on each marker coordinate (one standard deviation) [mm].
CAMERA_ERROR = 0.2


@dataclass(frozen=True)
class ClosedLoopRun:
    """One target reached with a perturbed arm.

    Attributes
    ----------
    target : ndarray (3,)
    configuration : str
        The controller's plan.
    arm_length : float
        The planned configuration's tip height as built [mm] (the errors' scale).
    open_loop_kinematic : float
        Error of the constant-curvature model's pulls on the true arm [mm] (NaN where that
        model has no answer: a configuration with no contracted module does not bend).
    open_loop_structural : float
        Error of the structural model's pulls on the true arm [mm].
    closed_loop : ndarray (iterations,)
        Error after each correction [mm].
    pulls : ndarray (3,)
        The last pulls sent [mm] (after the pretension; negative: let out).
    """

    target: np.ndarray
    configuration: str
    arm_length: float
    open_loop_kinematic: float
    open_loop_structural: float
    closed_loop: np.ndarray
    pulls: np.ndarray


def perturbed_parameters(seed: int, *, Lc: float = 15.0, spread=None) -> dict:
    """``build_arm`` keywords of a true arm drawn around the nominal one (``seed``)."""
    spread = dict(PERTURBATION, **(spread or {}))
    rng = np.random.default_rng(seed)
    nominal = ArmParameters()
    specimen = dataclasses.replace(nominal.specimen,
                                   kf=nominal.specimen.kf * (1 + spread["kf"] * rng.normal()))
    parameters = dataclasses.replace(
        nominal, specimen=specimen,
        tendon_radius=nominal.tendon_radius + spread["tendon_radius"] * rng.normal())
    return {"Lc": Lc + spread["Lc"] * rng.normal(), "parameters": parameters}


def closed_loop(target, *, seed: int = 0, iterations: int = 5, camera_error=CAMERA_ERROR,
                pretension: float = DEFAULT_PRETENSION, spread=None,
                configurations=None) -> ClosedLoopRun:
    """Plan on the model, move a perturbed arm, and correct from the measured tip.

    Parameters
    ----------
    target : array_like (3,)
        [mm], reachable by the model.
    seed : int
        Draws the true arm and the camera's errors.
    iterations : int
        Corrections after the first move.
    camera_error : float
        [mm] per coordinate.
    spread : dict, optional
        Overrides of :data:`PERTURBATION`.
    configurations : sequence of str, optional
        Those the plan may use (default: every one).

    Raises
    ------
    ValueError
        For a target the model does not reach.
    """
    from scipy.optimize import lsq_linear

    if not (isinstance(iterations, int) and iterations >= 1):
        raise ValueError(f"iterations = {iterations!r} is invalid: must be an integer >= 1")
    if not camera_error >= 0:
        raise ValueError(f"camera_error = {camera_error!r} is invalid: must be >= 0 mm")
    plan = reach(target, configurations=configurations, pretension=pretension)
    if not plan.reached:
        raise ValueError(f"target {np.asarray(target).tolist()} is out of the model's reach "
                         f"({plan.message})")
    rng = np.random.default_rng([seed, 1])
    configuration = plan.configuration
    model_arm = build_arm(configuration)
    model_solver = ArmSolver(model_arm)
    model_base = model_solver.pretension(pretension)
    true_arm = build_arm(configuration, **perturbed_parameters(seed, spread=spread))
    true_solver = ArmSolver(true_arm)
    true_base = true_solver.pretension(pretension)
    state = [true_base]

    def true_tip(P):
        states, completed, message = true_solver.ramp(state[0], true_base.pulls + P)
        if not completed:
            raise ValueError(f"the true arm does not follow the pulls {P.round(3).tolist()} "
                             f"({message})")
        state[0] = states[-1]
        return states[-1].tip_position

    kinematic = _kinematic_pulls(model_arm, plan.target, configuration)
    open_kinematic = (float(np.linalg.norm(true_tip(kinematic) - plan.target))
                      if kinematic is not None else float("nan"))
    P = plan.tendon_displacements.copy()
    tip = true_tip(P)
    open_structural = float(np.linalg.norm(tip - plan.target))
    errors = []
    model_state = plan.state
    # A correction may let a tendon out below the plan's zero (the pretension's pull), but
    # not so far that it goes slack: down to 90 % of the pretension's pull on the model.
    floor = -0.9 * (model_base.pulls - model_solver.built().pulls)
    for _ in range(iterations):
        measured = tip + camera_error * rng.normal(size=3)
        step = lsq_linear(tip_jacobian(model_arm, model_state), plan.target - measured,
                          bounds=(floor - P, np.inf)).x
        P = P + step
        tip = true_tip(P)
        errors.append(float(np.linalg.norm(tip - plan.target)))
        states, completed, _ = model_solver.ramp(model_state, model_base.pulls + P)
        if completed:
            model_state = states[-1]
    return ClosedLoopRun(plan.target, configuration, float(model_arm.tip_height),
                         open_kinematic, open_structural, np.array(errors), P)


def _kinematic_pulls(arm, target, configuration):
    """The constant-curvature model's pulls for ``target`` in ``configuration`` (as
    :func:`~kresling.arm.actuation.actuate` maps them: each flexible module's tendon
    lengths 2 Lc - pull / f), or None where it has no bending module or no answer."""
    from kresling.manipulator import inverse_kinematics

    flexible = configuration.count("0")
    if flexible == 0:
        return None
    r = inverse_kinematics(kinematic_model(arm), target, configurations=[configuration])
    if not r.reachable:
        return None
    return np.maximum((2 * arm.design.Lc - np.asarray(r.tendon_lengths)) * flexible, 0.0)
