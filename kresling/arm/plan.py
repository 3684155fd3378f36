"""Reaching a point from where the arm is: the switches to the target configuration, then
the move.

:func:`~kresling.arm.reach.reach` answers which configuration and which tendon pulls bring
the tip to a target. An arm resting in another configuration has to get there first:
:func:`plan_reach` returns the steps, each checked on the model:

- **switch** steps, one module each. A module is contracted by the tendons where pulling can
  snap it (:func:`~kresling.arm.analyses.pull_until_snap`, all three tendons together: a
  single tendon bends the arm so far that, without panel contact, the panels pass through
  each other), each pull until the arm loses equilibrium, then the tendons let out: a
  first pull snaps one of its cells (the tendons slacken as that cell drops and the other
  re-extends); a second takes the other cell just below the height at which it counts as
  contracted, from where, let out, it re-extends; a third pulls it past its unstable
  equilibrium, where the tendons go slack, and it stays (up to :data:`MAX_PULLS`). Tendons
  cannot extend a module; its creases can (:func:`~kresling.arm.creases.crease_switch`,
  one crease group after another, :data:`CREASE_GROUPS`), and they are tried for a
  contraction where the tendons fail. After every switch the tendons are let out and the
  configuration is read from the cells' heights where the arm comes to rest: the step
  counts only if the intended module changed and no other one did; otherwise the next
  means, then another module first, is tried. Only the modules that differ from the target
  configuration are switched (no detour through other configurations).
- one **move** step: the pulls after the pretension that :func:`reach` finds for the
  configuration reached (the arm of that configuration as built, pretensioned).

**The model of a switch.** A cell of the model is stress-free in the state it is built in,
and its crease rest angles fix which switches its creases can make. A module is taken as
made extended: a contraction starts from the arm built in the configuration before it (the
module built extended); an extension from the arm built in the configuration after it,
with the module resting contracted (:func:`~kresling.arm.creases.resting_state`). Built
contracted, the thesis's module is not extended by any crease group (its start state
persists up to a change of 170 degrees). Each switch starts from the arm as built in its
configuration, as the reach does; where a switch leaves the arm (a module resting contracted
stands taller than one built contracted) is reported with the step.

**Choosing the configuration.** Among the configurations that reach the target,
``prefer="switches"`` takes the fewest switches (then the smallest tendon travel);
``prefer="travel"`` and ``prefer="stiffness"`` take the fewest switches among those whose
travel (or largest tip compliance) is within :data:`COMPARABLE` of the best, then the best
of those. A configuration whose switches fail on the model is passed over for the next.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kresling._validation import show
from kresling.arm.analyses import DEFAULT_PRETENSION, ArmSolver, ArmState, pull_until_snap
from kresling.arm.reach import REACH_TOLERANCE, ReachResult, reach_answer, reach_candidates
from kresling.arm.structure import build_arm, parse_configuration

__all__ = ["SwitchStep", "MoveStep", "ReachPlan", "plan_reach", "switch_module",
           "COMPARABLE", "MAX_PULLS", "CREASE_GROUPS", "PREFERENCES"]

#: How the configuration is chosen (see the module).
PREFERENCES = ("travel", "stiffness", "switches")
#: Travels (or compliances) within this fraction of the best, or within 1 mm of travel,
#: count as comparable: among them the fewest switches win.
COMPARABLE = 0.2
#: Pulls of all tendons (each until the arm loses equilibrium, then let out) a contraction
#: may take: a pull snaps one cell, and the second cell needs two (see the module).
MAX_PULLS = 4
#: The crease groups a crease switch drives, in turn (all folds first: the least change).
CREASE_GROUPS = ("fold", "valley", "polygon")


@dataclass(frozen=True)
class SwitchStep:
    """One module switched.

    Attributes
    ----------
    module : int
        0-based from the base.
    to : str
        ``"extended"`` or ``"contracted"``.
    means : str
        ``"tendon"`` or ``"crease"``.
    configuration_before, configuration_after : str
        The latter read from the cells' heights where the arm rests, tendons let out.
    actuation : dict
        Tendons: ``pulls`` (each pull's three tendon pulls [mm] at the last equilibrium
        before the arm lost it, or, where another module snapped, before the tendons were
        let out) and ``tension_sums`` there [N]. Creases: ``group``, ``creases``, ``change_deg`` (the rest
        angles' change at the snap), ``moment`` [N mm], ``work`` [N mm].
    module_length : ndarray (m,)
        Each module's length where the arm rests after the switch [mm].
    tip_position : ndarray (3,)
        The tip there [mm].
    attempts : tuple of str
        What failed before this means succeeded.
    state : ArmState
    positions : ndarray (N, 3)
        Every node where the arm rests after the switch [mm] (the arms of all
        configurations have the same nodes).
    """

    module: int
    to: str
    means: str
    configuration_before: str
    configuration_after: str
    actuation: dict
    module_length: np.ndarray
    tip_position: np.ndarray
    attempts: tuple
    state: ArmState = field(repr=False)
    positions: np.ndarray = field(repr=False)


@dataclass(frozen=True)
class MoveStep:
    """The tendon pulls after the pretension (:attr:`ReachResult.tendon_displacements`)."""

    configuration: str
    tendon_displacements: np.ndarray
    tip_position: np.ndarray


@dataclass(frozen=True)
class ReachPlan:
    """The answer of :func:`plan_reach`.

    Attributes
    ----------
    reach : ReachResult
        The move: ``configuration``, ``tendon_displacements``, ``tip_position`` and
        ``error`` as :func:`reach` gives them.
    start_configuration : str
    steps : list of SwitchStep, then one MoveStep
    switches : int
    passed_over : dict
        Configurations preferred to the one chosen whose switches failed: why.
    """

    reach: ReachResult
    start_configuration: str
    steps: list
    switches: int
    passed_over: dict

    @property
    def configuration(self) -> str:
        return self.reach.configuration


class _Failed(Exception):
    """A switch no means achieves on the model (the message says what each did)."""


def _set(configuration: str, module: int, state: int) -> str:
    return configuration[:module] + str(state) + configuration[module + 1:]


def _measured(solver: ArmSolver, state: ArmState, let_out: float) -> ArmState:
    """Where the arm rests from ``state`` with every tendon let out by ``let_out`` [mm]."""
    rest, converged, message = solver.release(state, np.full(3, -let_out))
    if not converged:
        raise _Failed(f"released, the arm found no rest ({message})")
    return rest


def _tendon_contraction(arm, module, solver, let_out, goal):
    """Pull all tendons until the arm loses equilibrium, let them out and read where it
    rests; again from the pulled state, up to :data:`MAX_PULLS` times, until ``module``
    rests contracted: (state, actuation), or _Failed. Where another module snaps first,
    the tendons are let out from the last equilibrium of that pull with ``module``
    contracted and every other module in its state, if there is one."""
    state, pulls, tensions = solver.built(), [], []

    def done(rest):
        return rest, {"pulls": pulls, "tension_sums": tensions}
    for _ in range(MAX_PULLS):
        r = pull_until_snap(arm, start=state, solver=solver)
        if not r.snapped or r.after is None:
            raise _Failed(f"pulling all tendons snaps no module ({r.message})")
        pulls.append(r.pulls.tolist())
        tensions.append(r.tension_sum)
        rest = _measured(solver, r.after, let_out)
        if rest.configuration == goal:
            return done(rest)
        others = [j for j in range(len(goal)) if j != module and rest.configuration[j] != goal[j]]
        if others:
            held = [s for s in r.states if s.configuration == goal]
            if held:
                pulls[-1], tensions[-1] = held[-1].pulls.tolist(), held[-1].tension_sum
                rest = _measured(solver, held[-1], let_out)
                if rest.configuration == goal:
                    return done(rest)
            raise _Failed(f"pulling all tendons snaps module {others[0]} before module "
                          f"{module} rests contracted")
        state = r.after
    raise _Failed(f"after {MAX_PULLS} pulls of all tendons, each let out, module {module} "
                  f"rests {rest.configuration[module]!r}")


def _crease_switch(arm, module, start, to, let_out):
    """The first crease group that switches ``module``: (state, actuation), or _Failed."""
    from kresling.arm.creases import crease_switch

    why = []
    for group in CREASE_GROUPS:
        r = crease_switch(arm, module, group=group, start=start, to=to, let_out=let_out,
                          compare_tendons=False)
        if r.switched and r.after is not None and \
                r.after.configuration[module] == ("1" if to == "extended" else "0"):
            return r.after, {"group": group, "creases": r.creases,
                             "change_deg": r.snap_change_deg, "moment": r.moment,
                             "work": r.work}
        why.append(f"{group}: {r.message}")
        if to == "contracted":
            break   # one scan says it: each costs a full scan of the start branch
    raise _Failed("; ".join(why))


def switch_module(configuration: str, module: int, *, means=("tendon", "crease"),
                  **arm_options) -> SwitchStep:
    """Switch ``module`` of the arm resting in ``configuration`` to its other state, by the
    first of ``means`` that does it on the model (see the module), checked: the arm comes
    to rest, tendons let out, with that module switched and every other in its state.

    Parameters
    ----------
    configuration : str
        From the base, "0" contracted, "1" extended.
    module : int
        0-based from the base.
    means : sequence of {"tendon", "crease"}
        Tried in turn (tendons cannot extend a module: skipped for an extension).
    **arm_options
        :func:`~kresling.arm.build_arm`'s ``n``, ``lam``, ``Lc``, ``R``, ``design``,
        ``parameters``.

    Raises
    ------
    ValueError
        Naming the parameter for bad input; or, with what each means did, where none
        switches the module alone.
    """
    states = parse_configuration(configuration)
    if not isinstance(module, (int, np.integer)) or not 0 <= module < len(states):
        raise ValueError(f"module = {show(module)} is invalid: must be an integer in "
                         f"[0, {len(states) - 1}] (0: the base)")
    means = tuple(means)
    for m in means:
        if m not in ("tendon", "crease"):
            raise ValueError(f"means = {show(means)} is invalid: each must be 'tendon' or "
                             "'crease'")
    to = "contracted" if states[module] else "extended"
    after = _set(configuration, module, 0 if states[module] else 1)
    attempts = []
    for m in means:
        if m == "tendon" and to == "extended":
            attempts.append("tendon: tendons only pull, they cannot extend a module")
            continue
        # The module as made extended: built so before a contraction; after an extension,
        # resting contracted (see the module).
        arm = build_arm(configuration if to == "contracted" else after, **arm_options)
        solver = ArmSolver(arm)
        let_out = 3.0 * (arm.design.Le - arm.design.Lc)
        try:
            if to == "extended":
                from kresling.arm.creases import resting_state

                start = resting_state(arm, module, 0, let_out=let_out, solver=solver)
                if start.configuration != configuration:
                    raise _Failed(f"resting contracted, the arm rests in "
                                  f"{start.configuration}, not {configuration}")
                state, actuation = _crease_switch(arm, module, start, to, let_out)
            elif m == "tendon":
                state, actuation = _tendon_contraction(arm, module, solver, let_out, after)
            else:
                state, actuation = _crease_switch(arm, module, None, to, let_out)
            state = _measured(solver, state, let_out)
        except (_Failed, ValueError, RuntimeError) as error:
            attempts.append(f"{m}: {error}")
            continue
        if state.configuration != after:
            attempts.append(f"{m}: the arm rests in {state.configuration}, not {after}")
            continue
        return SwitchStep(module, to, m, configuration, state.configuration, actuation,
                          state.module_length.copy(), state.tip_position.copy(),
                          tuple(attempts), state,
                          arm.model.nodes + state.displacement.reshape(-1, 3))
    raise ValueError(f"module {module} of {configuration} cannot be switched to {after} on the "
                     f"model: " + "; ".join(attempts))


def _switch_sequence(start: str, goal: str, cache: dict, arm_options: dict) -> list:
    """The switches from ``start`` to ``goal``: contractions from the tip down, then
    extensions from the base up; where a module cannot be switched now, the next is tried
    first. Raises _Failed with what each tried."""
    steps, current, why = [], start, []
    while current != goal:
        pending = [k for k in range(len(goal)) if current[k] != goal[k]]
        order = sorted((k for k in pending if current[k] == "1"), reverse=True) + \
            sorted(k for k in pending if current[k] == "0")
        for k in order:
            if (current, k) not in cache:
                try:
                    cache[current, k] = switch_module(current, k, **arm_options)
                except ValueError as error:
                    cache[current, k] = str(error)
            step = cache[current, k]
            if isinstance(step, SwitchStep):
                steps.append(step)
                current = step.configuration_after
                break
            why.append(step)
        else:
            raise _Failed("; ".join(why))
    return steps


def plan_reach(target, start_configuration: str, *, prefer: str = "switches",
               configurations=None, tolerance: float = REACH_TOLERANCE,
               pretension: float = DEFAULT_PRETENSION, gravity: str | None = None,
               measured_mass: bool = False, **arm_options) -> ReachPlan:
    """The steps that bring the tip of the arm resting in ``start_configuration`` to
    ``target``: the switches to the configuration chosen, then the move.

    Parameters
    ----------
    target : array_like (3,)
        [mm], as :func:`~kresling.arm.reach.reach`.
    start_configuration : str
        Where the arm rests, one character per module from the base ("0" contracted, "1"
        extended); its length is the number of modules.
    prefer : {"switches", "travel", "stiffness"}, default "switches"
        How the target configuration is chosen (see the module).
    configurations, tolerance, pretension, gravity, measured_mass, **arm_options
        As :func:`~kresling.arm.reach.reach` (``modules`` is the start's length).

    Returns
    -------
    ReachPlan

    Raises
    ------
    ValueError
        Naming the parameter: a bad start configuration or preference, and as
        :func:`~kresling.arm.reach.reach`.
    """
    if not isinstance(start_configuration, str):
        raise ValueError(f"start_configuration = {show(start_configuration)} is invalid: must "
                         "be a string of 0 (contracted) and 1 (extended), one per module from "
                         "the base")
    try:
        parse_configuration(start_configuration)
    except ValueError:
        raise ValueError(f"start_configuration = {show(start_configuration)} is invalid: must "
                         "be a string of 0 (contracted) and 1 (extended), one per module from "
                         "the base") from None
    if prefer not in PREFERENCES:
        raise ValueError(f"prefer = {show(prefer)} is invalid: must be one of "
                         f"{', '.join(PREFERENCES)}")
    if arm_options.pop("modules", len(start_configuration)) != len(start_configuration):
        raise ValueError(f"start_configuration = {start_configuration!r} is invalid: has "
                         f"{len(start_configuration)} modules, the arm "
                         f"{arm_options.get('modules')}")
    target, solutions, candidates = reach_candidates(
        target, configurations=configurations, tolerance=tolerance, pretension=pretension,
        gravity=gravity, measured_mass=measured_mass, modules=len(start_configuration),
        **arm_options)
    switches = {c: sum(a != b for a, b in zip(c, start_configuration)) for c in solutions}
    reaching = [c for c, s in solutions.items() if s.error <= tolerance]
    measure = {c: (s.compliance if prefer == "stiffness" else s.travel)
               for c, s in solutions.items()}
    best = min((measure[c] for c in reaching), default=0.0)
    floor = 1.0 if prefer != "stiffness" else 0.0   # mm of travel

    def key(c):
        s = solutions[c]
        if s.error > tolerance:   # after every reaching one, the nearest first
            return (2, s.error, switches[c], 0.0)
        if prefer == "switches":
            return (0, switches[c], s.travel, 0.0)
        comparable = measure[c] <= best * (1.0 + COMPARABLE) + floor
        return (0 if comparable else 1, switches[c] if comparable else 0, measure[c], 0.0)

    cache, passed_over = {}, {}
    for configuration in sorted(solutions, key=key):
        try:
            steps = _switch_sequence(start_configuration, configuration, cache, arm_options)
        except _Failed as error:
            passed_over[configuration] = str(error)
            continue
        result = reach_answer(target, configuration, solutions, candidates, tolerance, gravity)
        move = MoveStep(configuration, result.tendon_displacements.copy(),
                        result.tip_position.copy())
        return ReachPlan(result, start_configuration, [*steps, move], len(steps), passed_over)
    # None could be switched to: the start's own nearest approach (it needs no switch).
    _, own, more = reach_candidates(
        target, configurations=[start_configuration], tolerance=tolerance,
        pretension=pretension, gravity=gravity, measured_mass=measured_mass,
        modules=len(start_configuration), **arm_options)
    result = reach_answer(target, start_configuration, own, {**candidates, **more}, tolerance,
                          gravity)
    move = MoveStep(start_configuration, result.tendon_displacements.copy(),
                    result.tip_position.copy())
    return ReachPlan(result, start_configuration, [move], 0, passed_over)
