"""Switching one module of the arm by its creases instead of by pulling the tendons.

The crease actuation of a single cell (:mod:`kresling.analyses.switching`) on the whole arm:
the rest angles of one crease group (``valley``, ``mountain``, ``polygon`` edges, or every
``fold``) in one module's cells (both, or the one not yet in the state the module is driven
to, as in a module a tendon pull half switched) are driven by one change ``Delta``, each crease the way
it turns from the module's one state to the other as built (to extend the module: the sign
of its angle in the arm built with the module extended minus its angle in the arm built with
it contracted; the opposite to contract it). Each increment is an equilibrium of the whole
arm (the fold solver); bisection locates the change at which the module's start state
ceases to exist; held just past it the arm snaps, and released (the stress-free rest angles
back) it comes to rest (energy descent), in a configuration that is read off its cells.

The tendons are let out first (their rest lengths their slack lengths plus ``let_out``), so
that they carry nothing while the module changes length: extending a module lengthens their
paths, which just-taut tendons would resist; from the start, the arm then settles (energy
descent) where it rests without them before the creases are driven. The start may be the built arm or any state of
it, e.g. where pulling the tendons left it (:func:`~kresling.arm.analyses.pull_until_snap`):
tendons only pull, so they contract an extended module but cannot extend it again; the
creases can. docs/arm.md, 'Switching a module by its creases', has the numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_finite_real, as_integer, show
from kresling.analyses.switching import GROUPS, angle_in_radians
from kresling.arm.analyses import ArmSolver, ArmState, SnapResult, pull_until_snap
from kresling.arm.structure import Arm

__all__ = ["CreaseSwitchResult", "crease_switch", "resting_state"]


@dataclass(frozen=True)
class CreaseSwitchResult:
    """One module driven by one crease group.

    Attributes
    ----------
    module : int
        0-based from the base.
    group : str
        ``valley``, ``mountain``, ``polygon`` or ``fold``.
    to : str
        ``"extended"`` or ``"contracted"``: the state the creases drive the module towards.
    creases : int
        Driven creases (those with stiffness).
    switched : bool
        The start state ceased to exist and the released module rests at another length.
    configuration_before, configuration_after : str
        Module states from the cells ('x': the module's two cells in different states).
    snap_change : float
        Rest-angle change at the snap, the last state on the start branch [rad] (where the
        scan ended if there was none).
    resolution : float
        The start branch ends within this above ``snap_change`` [rad].
    moment, max_crease_moment : float
        Summed moment of the driven creases at the snap, in the driving sense, and the
        largest moment of one of them [N mm].
    work : float
        The actuation's work up to the snap: the integral of the rest angles' generalised
        force over the change [N mm]; it equals ``snap.energy - start.energy``.
    let_out : float
        How far each tendon was let out beyond its slack length [mm].
    start, snap : ArmState
        The start (tendons let out) and the last state on the branch (actuated; its
        ``energy`` is the actuated one).
    after : ArmState or None
        Where the released arm rests (None if it found no rest or did not snap).
    tip_displacement : ndarray, shape (3,)
        ``after``'s tip minus ``start``'s [mm] (NaN without ``after``).
    change, moments, energy, module_length : ndarray, shape (S,)
        The followed path: change [rad], summed moment [N mm], strain energy [N mm], the
        module's length (guide centre to guide centre) [mm].
    tendons : SnapResult or None
        Pulling all three tendons from the same start until a module snaps, for comparison
        (only when the creases contract the module: tendons cannot extend one).
    message : str
    """

    module: int
    group: str
    to: str
    creases: int
    switched: bool
    configuration_before: str
    configuration_after: str
    snap_change: float
    resolution: float
    moment: float
    max_crease_moment: float
    work: float
    let_out: float
    start: ArmState
    snap: ArmState
    after: ArmState | None
    tip_displacement: np.ndarray
    change: np.ndarray
    moments: np.ndarray
    energy: np.ndarray
    module_length: np.ndarray
    tendons: SnapResult | None
    message: str

    @property
    def snap_change_deg(self) -> float:
        """``snap_change`` in degrees."""
        return math.degrees(self.snap_change)


def _settle(solver: ArmSolver, start: ArmState, let_out: float) -> ArmState:
    """Where the arm rests from ``start`` once the tendons are let out (energy descent: a
    released arm's tendons carry almost nothing, but the state they held may move a little,
    and Newton's method converges poorly from where a tendon just switches off)."""
    state, converged, message = solver.release(start, np.full(3, -let_out))
    if not converged:
        raise ValueError(f"start is invalid: with the tendons let out by {let_out:g} mm the arm "
                         f"finds no rest from it ({message})")
    return state


def _direction(module: int, start: ArmState, to) -> tuple:
    """The state to drive to and the module's cells not yet in it (those driven)."""
    states = start.cell_states[2 * module:2 * module + 2]
    if to is None:
        to = "extended" if 0 in states else "contracted"
    if to not in ("extended", "contracted"):
        raise ValueError(f"to = {show(to)} is invalid: must be 'extended', 'contracted' or None "
                         "(the other state of the module's)")
    target = 1 if to == "extended" else 0
    cells = [2 * module + k for k in range(2) if states[k] != target]
    if not cells:
        raise ValueError(f"to = {to!r} is invalid: module {module} is {to} already")
    return to, cells


def resting_state(arm: Arm, module: int, state: int, *, let_out: float | None = None,
                  solver: ArmSolver | None = None) -> ArmState:
    """Where the arm rests with ``module``'s two cells in ``state`` (0 contracted, 1
    extended), whatever it was built in: energy descent, tendons let out by ``let_out``
    (default 3 (Le - Lc)), from the geometry of the arm built with the module in ``state``.

    A module built extended rests contracted with its cells strained (their rest angles are
    the extended ones), taller than as built: this is the state a pull that contracts both
    cells leaves it in, and where the creases can extend it from. Raises ValueError naming
    ``state`` when the module does not rest there (it returns to the other state: the module
    is not bistable).
    """
    from kresling.arm.structure import build_arm

    module = as_integer("module", module, minimum=0, maximum=arm.modules - 1)
    state = as_integer("state", state, minimum=0, maximum=1)
    travel = arm.design.Le - arm.design.Lc
    let_out = 3.0 * travel if let_out is None else as_finite_real("let_out", let_out)
    solver = ArmSolver(arm) if solver is None else solver
    flipped = arm.configuration[:module] + str(state) + arm.configuration[module + 1:]
    other = build_arm(flipped, design=arm.design, parameters=arm.parameters)
    u = (other.model.nodes - arm.model.nodes).ravel()
    start = ArmState.from_core(solver._core.evaluate(u, [-let_out] * 3, [0.0, 0.0, 0.0]))
    rest, converged, message = solver.release(start)
    cells = rest.cell_states[2 * module:2 * module + 2]
    if not converged:
        raise ValueError(f"state = {state} is invalid: released from module {module}'s "
                         f"{'extended' if state else 'contracted'} geometry the arm finds no "
                         f"rest ({message})")
    if cells != (state, state):
        raise ValueError(f"state = {state} is invalid: module {module} does not rest "
                         f"{'extended' if state else 'contracted'} (released from there it "
                         f"rests with cells {cells}: the module is not bistable)")
    return rest


def crease_switch(arm: Arm, module: int, *, group: str = "fold", start: ArmState | None = None,
                  to: str | None = None, let_out: float | None = None, compare_tendons=True,
                  scan_step_deg=0.25, max_change_deg=170.0, resolution_deg=1e-5,
                  overshoot_deg=0.01, tolerance=1e-6, max_iterations=50) -> CreaseSwitchResult:
    """Switch ``module`` of ``arm`` by driving one crease group's rest angles.

    Parameters
    ----------
    arm : Arm
    module : int
        0-based from the base.
    group : {"fold", "valley", "mountain", "polygon"}
    start : ArmState, optional
        Where the arm is (default: as built), e.g. ``pull_until_snap(arm).after``; with the
        tendons let out the arm settles from there first.
    to : {"extended", "contracted"}, optional
        Default: extended if one of the module's cells is contracted at ``start``, else
        contracted.
    let_out : float, optional
        Tendon let-out [mm], >= 0; default 3 (Le - Lc), one and a half times a module's
        travel.
    compare_tendons : bool, default True
        When contracting: also pull all tendons from ``start`` until a module snaps.
    scan_step_deg, max_change_deg, resolution_deg, overshoot_deg, tolerance, max_iterations
        As :func:`kresling.analyses.switching.switching`.

    Returns
    -------
    CreaseSwitchResult

    Raises
    ------
    ValueError
        Naming the parameter: a module out of range, an unknown group or direction, a
        negative let-out, options out of range, a start of another arm or one from which
        the arm finds no rest.

    Examples
    --------
    >>> from kresling.arm import build_arm
    >>> arm = build_arm("1")
    >>> contracted = resting_state(arm, 0, 0)    # the module at rest contracted
    >>> r = crease_switch(arm, 0, start=contracted)
    >>> r.to, r.switched, r.configuration_after, round(r.snap_change_deg, 2)
    ('extended', True, '1', 47.08)
    """
    if not isinstance(arm, Arm):
        raise ValueError(f"arm = {show(arm)} is invalid: must be a kresling.arm.Arm")
    module = as_integer("module", module, minimum=0, maximum=arm.modules - 1)
    if group not in GROUPS:
        raise ValueError(f"group = {show(group)} is invalid: must be one of {', '.join(GROUPS)}")
    travel = arm.design.Le - arm.design.Lc
    let_out = 3.0 * travel if let_out is None else as_finite_real("let_out", let_out)
    if let_out < 0:
        raise ValueError(f"let_out = {let_out!r} mm is invalid: must be >= 0")
    if start is not None and not (isinstance(start, ArmState)
                                  and start.displacement.shape == (arm.model.num_dofs,)):
        raise ValueError(f"start = {show(start)} is invalid: must be an ArmState of the arm "
                         f"({arm.model.num_dofs} displacements)")
    max_change = angle_in_radians("max_change_deg", max_change_deg, 0.0, 171.0)
    scan = (angle_in_radians("scan_step_deg", scan_step_deg, 0.0, max_change_deg), max_change,
            angle_in_radians("resolution_deg", resolution_deg, 0.0, scan_step_deg),
            angle_in_radians("overshoot_deg", overshoot_deg, 0.0, scan_step_deg),
            as_finite_real("tolerance", tolerance),
            as_integer("max_iterations", max_iterations, minimum=1))
    solver = ArmSolver(arm)
    given = solver.built() if start is None else start
    to, cells = _direction(module, given, to)
    settled = _settle(solver, given, let_out)
    core = _core.analyses.arm_crease_switch(
        arm.design._core, [int(c) for c in arm.configuration], arm.parameters.to_core(), module,
        cells, settled.displacement, to == "extended", group, *scan[:4], scan[4], scan[5], let_out)
    tendons = None
    if compare_tendons and to == "contracted":
        tendons = pull_until_snap(arm, start=given if start is not None else None, solver=solver)
    return _result(core, group, to, tendons)


def _result(core, group, to, tendons) -> CreaseSwitchResult:
    s = core.scan
    start, snap = ArmState.from_core(core.start), ArmState.from_core(core.snap)
    after = ArmState.from_core(core.after) if core.after.displacement.size else None
    tip = after.tip_position - start.tip_position if after else np.full(3, np.nan)
    return CreaseSwitchResult(
        module=int(core.module), group=group, to=to, creases=int(s.creases),
        switched=bool(s.switched), configuration_before=core.configuration_before,
        configuration_after=core.configuration_after, snap_change=float(s.snap_change),
        resolution=float(s.resolution), moment=float(s.moment),
        max_crease_moment=float(s.max_crease_moment), work=float(s.work),
        let_out=float(core.let_out), start=start, snap=snap, after=after,
        tip_displacement=tip, change=np.asarray(s.change), moments=np.asarray(s.moments),
        energy=np.asarray(s.energy), module_length=np.asarray(s.height), tendons=tendons,
        message=s.message)
