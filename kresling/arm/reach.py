"""Reaching a point with the structural arm: the configuration and the tendon pulls that
bring its tip to a target.

For one configuration (which modules are extended) the arm is pretensioned as
:func:`~kresling.arm.tip_load` does, then the three tendons' further pulls ``P`` (mm,
shortening positive: what ``kresling arm --pulls`` takes) are sought so that the tip guide's
centre is at the target: a bounded least-squares problem (a tendon cannot push, so
``P >= 0``) solved by SciPy's trust-region reflective method on the exact tip Jacobian
``d tip / d P`` (:func:`tip_jacobian`: the equilibrium's sensitivity to the tendons' rest
lengths, one factorisation and three solves). Every configuration that reaches the target
is a candidate; the one returned has the smallest tendon travel (``prefer="travel"``, the
sum of the pulls) or the stiffest tip (``prefer="stiffness"``, the smallest largest
compliance). A target no configuration reaches is answered with the nearest point one
reaches, and says so.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kresling._validation import as_choice, as_float_array, as_positive_real, show
from kresling.arm.analyses import DEFAULT_PRETENSION, ArmSolver, ArmState
from kresling.arm.structure import Arm, all_configurations, build_arm, parse_configuration
from kresling.solvers.sensitivity import Parameter, equilibrium_sensitivity, with_parameter

__all__ = ["tip_jacobian", "ReachResult", "reach", "reach_with", "reach_candidates",
           "reach_answer", "Solution", "REACH_TOLERANCE"]

#: A target counts as reached when the tip is within this distance of it [mm].
REACH_TOLERANCE = 1e-3
#: Increments of each move of the search (from the last equilibrium: short moves).
_STEPS = 3
#: Halvings of a move's increments before the move counts as one the arm does not follow
#: (a snap): few, so that trying a step too far costs little; the step is halved instead.
_BISECTIONS = 3
#: Gauss-Newton steps of one configuration's search.
_MAX_ITERATIONS = 30


def tip_jacobian(arm: Arm, state: ArmState) -> np.ndarray:
    """d(tip position)/d(pull of each tendon) at an equilibrium ``state`` of ``arm``,
    (3, 3) [mm/mm], column t for tendon t (a pull shortens the tendon's rest length by as
    much). A slack tendon's column is zero.

    Raises
    ------
    ValueError
        Where the arm's tangent is singular (a module at its snap).
    """
    rest = arm.slack_length - np.asarray(state.pulls, dtype=float)
    model = with_parameter(arm.model, "cables.rest_length", rest)
    sens = equilibrium_sensitivity(model, state.displacement,
                                   [Parameter("cables", "rest_length", entry=t) for t in range(3)])
    tip = 3 * arm.tip_node + np.arange(3)
    return -sens.displacement[tip, :]


@dataclass(frozen=True)
class ReachResult:
    """The answer of :func:`reach`.

    Attributes
    ----------
    target : ndarray (3,)
        [mm]
    configuration : str
        Module states from the base ("1" extended, "0" contracted).
    tendon_displacements : ndarray (3,)
        Each tendon's pull after the pretension [mm], shortening positive (``--pulls``).
    tip_position : ndarray (3,)
        Where the tip ends [mm].
    error : float
        Its distance from the target [mm].
    reached : bool
        ``error <= tolerance``.
    state : ArmState
        The arm's equilibrium there.
    candidates : dict
        Per configuration tried: ``(error [mm], tendon travel [mm], largest tip compliance
        [mm/N])``, or the reason it failed.
    message : str
    gravity : str or None
        The orientation the arm was weighed in (None: without its weight).
    """

    target: np.ndarray
    configuration: str
    tendon_displacements: np.ndarray
    tip_position: np.ndarray
    error: float
    reached: bool
    state: ArmState = field(repr=False)
    candidates: dict = field(repr=False)
    message: str = ""
    gravity: str | None = None


def _solve_pulls(follow, jacobian, target, start):
    """Gauss-Newton on the tip's miss over the pulls >= 0, from ``start``: (pulls, state,
    evaluations). ``follow(state, P)`` is the arm's equilibrium at pulls ``P`` reached from
    ``state`` (None where the arm does not follow: a snap), ``follow(None, 0)`` the one
    without pulls; ``jacobian(state)`` its tip Jacobian. Each step is the linearised
    problem's bounded least squares (no pull below zero); it is halved until the arm
    follows it to an equilibrium nearer the target, and the search ends where no step gets
    nearer: at the target, or at the nearest point this configuration reaches."""
    from scipy.optimize import lsq_linear

    evaluations = 0

    def move(state, P):
        nonlocal evaluations
        evaluations += 1
        return follow(state, P)

    P = np.zeros(3)
    state = move(None, P)
    if state is None:
        raise ValueError("the pretensioned arm finds no equilibrium under the loads")
    trial = np.maximum(start, 0.0)
    for _ in range(8):  # the start, shortened toward no pull until the arm follows it
        moved = move(state, trial)
        if moved is not None:
            P, state = trial, moved
            break
        trial = 0.5 * trial
    miss = np.linalg.norm(state.tip_position - target)
    for _ in range(_MAX_ITERATIONS):
        if miss <= 0.01 * REACH_TOLERANCE:
            break
        # The linearised miss's least squares over the steps that keep every pull >= 0.
        step = lsq_linear(jacobian(state), target - state.tip_position,
                          bounds=(-P, np.inf)).x
        scale, accepted = 1.0, False
        while scale >= 1.0 / 64:
            trial = np.maximum(P + scale * step, 0.0)
            moved = move(state, trial)
            if moved is not None:
                trial_miss = np.linalg.norm(moved.tip_position - target)
                if trial_miss < miss:
                    P, state, miss, accepted = trial, moved, trial_miss, True
                    break
            scale *= 0.5
        if not accepted:
            break
    return P, state, evaluations


def search_solver(arm: Arm) -> ArmSolver:
    """The solver of a reach's search on ``arm``: the arm's own Newton tolerance (1e-6 mm),
    as ``kresling arm --pulls`` runs it, so that those pulls give back the tip found; short
    moves, and few halvings before a move counts as one the arm does not follow."""
    return ArmSolver(arm, steps=_STEPS, max_bisections=_BISECTIONS, max_iterations=12)


def reach_with(arm: Arm, target, *, pretension: float = DEFAULT_PRETENSION,
               start=None, solver: ArmSolver | None = None, gravity: str | None = None,
               measured_mass: bool = False) -> tuple:
    """The pulls (after the pretension) that bring ``arm``'s tip nearest to ``target``, in
    its own configuration, without a module snapping on the way: ``(pulls (3,), state,
    arm's equilibria computed)``.

    With ``gravity`` (an orientation of :data:`kresling.arm.gravity.ORIENTATIONS`) the arm
    carries its own weight: each equilibrium is the pretensioned arm pulled by ``P``
    without its weight, then weighed with the tendons' lengths held
    (:func:`kresling.arm.gravity.gravity_sag`; the arm is elastic, so this is where it
    rests with both), and the tip Jacobian is the loaded arm's (the weight is a dead load:
    the tangent at the loaded equilibrium). ``measured_mass`` scales the masses to the
    thesis's weighed skeleton.

    Raises
    ------
    ValueError
        For a bad target or orientation; EquilibriumNotReached where the arm cannot be
        pretensioned.
    """
    target = _target(target)
    solver = search_solver(arm) if solver is None else solver
    base = solver.pretension(pretension)
    follow = _follower(arm, solver, base, gravity, measured_mass)
    if start is None:
        # The linearised answer from the pretensioned arm: often within a few per cent.
        state = follow(None, np.zeros(3))
        if state is None:
            raise ValueError(f"gravity = {gravity!r}: the pretensioned arm does not carry its "
                             "own weight")
        miss = target - state.tip_position
        start = np.linalg.lstsq(tip_jacobian(arm, state), miss, rcond=None)[0]
    start = np.maximum(as_float_array("start", start), 0.0)
    return _solve_pulls(follow, lambda state: tip_jacobian(arm, state), target, start)


def _follower(arm, solver, base, gravity, measured_mass):
    """``follow(state, P)`` of :func:`_solve_pulls`: without gravity, the ramp from the last
    equilibrium; with it, the ramp from the pretensioned arm, then its weight."""
    if gravity is None:
        def follow(state, P):
            if state is None:
                return base
            states, completed, _ = solver.ramp(state, base.pulls + P)
            return states[-1] if completed else None
        return follow

    from kresling.arm.gravity import ORIENTATIONS, gravity_sag
    from kresling.arm.masses import arm_masses

    gravity = as_choice("gravity", gravity, tuple(ORIENTATIONS))
    masses = arm_masses(arm, measured_skeleton=bool(measured_mass))

    def weighed(state, P):
        unloaded = base
        if np.any(P):
            states, completed, _ = solver.ramp(base, base.pulls + P)
            if not completed:
                return None
            unloaded = states[-1]
        sag = gravity_sag(arm, gravity, start=unloaded, masses=masses, solver=solver)
        if not sag.completed:
            return None
        return solver.state_at(sag.displacement, unloaded.pulls)
    return weighed


def reach(target, *, configurations=None, prefer="travel", tolerance=REACH_TOLERANCE,
          pretension: float = DEFAULT_PRETENSION, gravity: str | None = None,
          measured_mass: bool = False, **arm_options) -> ReachResult:
    """The configuration and tendon pulls that bring the structural arm's tip to ``target``.

    Parameters
    ----------
    target : array_like (3,)
        The tip guide's centre [mm], in the base's frame (z up the arm).
    configurations : sequence of str, optional
        Those to try (default: every one of the arm's modules' states).
    prefer : {"travel", "stiffness"}
        Among the configurations that reach the target: the smallest tendon travel (sum of
        the pulls), or the stiffest tip (the smallest largest eigenvalue of its compliance).
    tolerance : float
        Reached when the tip is within this distance [mm].
    pretension : float
        Each tendon's tension before the pulls [N] (as ``tip_load``), set before the arm's
        weight acts.
    gravity : {"hanging", "standing", "horizontal"}, optional
        The arm carries its own weight in this orientation
        (:data:`kresling.arm.gravity.ORIENTATIONS`): the tip is the loaded arm's and the
        search runs on the loaded arm's tip Jacobian (see :func:`reach_with`). Default:
        no gravity.
    measured_mass : bool, default False
        With ``gravity``: the masses scaled to the thesis's weighed skeleton.
    **arm_options
        ``modules`` (default 3), and :func:`~kresling.arm.build_arm`'s ``n``, ``lam``,
        ``Lc``, ``R``, ``parameters``.

    Returns
    -------
    ReachResult
        ``reached`` False: no configuration gets there; the result is the nearest point one
        reaches.
    """
    target = _target(target)
    if prefer not in ("travel", "stiffness"):
        raise ValueError(f"prefer = {show(prefer)} is invalid: must be 'travel' or 'stiffness'")
    target, solutions, candidates = reach_candidates(
        target, configurations=configurations, tolerance=tolerance, pretension=pretension,
        gravity=gravity, measured_mass=measured_mass, **arm_options)
    tolerance = as_positive_real("tolerance", tolerance)

    def key(c):
        s = solutions[c]
        missed = s.error > tolerance
        return (missed, s.error if missed else 0.0,
                s.travel if prefer == "travel" else s.compliance)
    return reach_answer(target, min(solutions, key=key), solutions, candidates, tolerance,
                        gravity)


@dataclass(frozen=True)
class Solution:
    """One configuration's answer in :func:`reach_candidates`: ``pulls`` (3,) [mm], its
    equilibrium ``state``, the tip's ``error`` [mm], the tendon ``travel`` (sum of the
    pulls) [mm] and the tip's largest ``compliance`` [mm/N]."""

    pulls: np.ndarray
    state: ArmState = field(repr=False)
    error: float
    travel: float
    compliance: float


def reach_candidates(target, *, configurations=None, tolerance=REACH_TOLERANCE,
                     pretension: float = DEFAULT_PRETENSION, gravity: str | None = None,
                     measured_mass: bool = False, **arm_options) -> tuple:
    """Every configuration's nearest approach to ``target`` (parameters as :func:`reach`):
    ``(target (3,), {configuration: Solution}, candidates)``, ``candidates`` as
    :attr:`ReachResult.candidates`.

    Raises
    ------
    ValueError
        Naming the parameter; or when no configuration could be pulled toward the target.
    """
    target = _target(target)
    tolerance = as_positive_real("tolerance", tolerance)
    if gravity is not None:
        from kresling.arm.gravity import ORIENTATIONS

        gravity = as_choice("gravity", gravity, tuple(ORIENTATIONS))
    modules = arm_options.pop("modules", 3)
    if configurations is None:
        configurations = all_configurations(modules)
    else:
        given = (list(configurations) if hasattr(configurations, "__iter__")
                 and not isinstance(configurations, (str, bytes)) else [])
        if not given:
            raise ValueError(f"configurations = {show(configurations)} is invalid: must be "
                             "None (every configuration) or a non-empty list of "
                             "configurations such as ['101', '111']")
        configurations = ["".join(str(s) for s in parse_configuration(c, modules))
                          for c in given]
    solutions, candidates = {}, {}
    # Pulling only shortens an arm: one whose built tip is nearer the base than the target
    # cannot reach it (unless none is taller: then the tallest gives the nearest point). A
    # module's two cells stand at their state's height.
    design = build_arm(configurations[0], **arm_options).design
    height = {c: 2.0 * sum(design.height(int(s)) for s in c) for c in configurations}
    distance = float(np.linalg.norm(target))
    tall = [c for c in configurations if height[c] >= distance] or \
        [max(configurations, key=height.get)]
    for configuration in configurations:
        if configuration not in tall:
            candidates[configuration] = (f"too short: its tip is {height[configuration]:.1f} mm "
                                         f"from the base as built, the target {distance:.1f} mm")
            continue
        arm = build_arm(configuration, **arm_options)
        try:
            solver = search_solver(arm)
            pulls, state, _ = reach_with(arm, target, pretension=pretension, solver=solver,
                                         gravity=gravity, measured_mass=measured_mass)
        except (ValueError, RuntimeError) as error:
            candidates[configuration] = str(error)
            continue
        error = float(np.linalg.norm(state.tip_position - target))
        compliance = float(np.linalg.eigvalsh(_symmetric(solver.tip_compliance(state)))
                           .max())
        solutions[configuration] = Solution(pulls, state, error, float(pulls.sum()), compliance)
        candidates[configuration] = (error, float(pulls.sum()), compliance)
    if not solutions:
        raise ValueError(f"target {target.tolist()}: no configuration could be pulled toward it "
                         f"({candidates})")
    return target, solutions, candidates


def reach_answer(target, configuration: str, solutions: dict, candidates: dict,
                 tolerance: float = REACH_TOLERANCE, gravity: str | None = None) -> ReachResult:
    """The :class:`ReachResult` of ``configuration`` among :func:`reach_candidates`'
    ``solutions``."""
    s = solutions[configuration]
    reached = s.error <= tolerance
    message = ("" if reached else
               f"target out of reach: the nearest point reached is {s.error:.3g} mm away "
               f"({s.state.tip_position.round(3).tolist()}, configuration {configuration})")
    return ReachResult(np.asarray(target, dtype=float), configuration, s.pulls,
                       s.state.tip_position.copy(), s.error, reached, s.state, candidates,
                       message, gravity)


def _symmetric(C):
    C = np.asarray(C, dtype=float)
    return 0.5 * (C + C.T)


def _target(target) -> np.ndarray:
    t = as_float_array("target", target).ravel()
    if t.shape != (3,) or not np.all(np.isfinite(t)):
        raise ValueError(f"target = {show(target)} is invalid: must be three finite coordinates "
                         "[mm]")
    if t[2] <= 0:
        raise ValueError(f"target = {t.tolist()} is invalid: must be above the base (z > 0 mm)")
    return t
