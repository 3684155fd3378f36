"""Equilibria of the arm under tendon pulls and tip loads; switching by pulling; load
capacity. The paths run in the C++ core (``cpp/kresling/analyses/arm_analysis.hpp``).

Inputs are **pulls** (how much each tendon's rest length is shortened from its slack length,
the path length as built [mm]; a pull is never negative: a tendon cannot push) and a **tip
load** on the tip guide's centre [N]. A path ramps them in increments, each a Newton solve;
an increment is accepted when Newton converges, the equilibrium is stable (positive definite
tangent) and every cell keeps its state (a cell is extended while its height, the distance
between its polygons' centroids, exceeds ``(Le + Lc) / 2``). A failing increment is halved
down to 1/4096 of its size; what still fails there is where the arm loses equilibrium (a
module snaps): the path ends there, a result with its increment and never an error.

**Pretension.** Just-taut tendons (as built) respond bilinearly: under a transverse tip load
the tendons on the shortening side go slack at once, so the response is neither linear nor
symmetric. Tip loads are therefore carried with every tendon pretensioned (1 N by default,
an assumption: the thesis gives no value); pretension pulls are found by Newton's method on
the pulls with the exact tension sensitivities.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, as_integer, as_real, show
from kresling.arm.structure import Arm

__all__ = ["ArmState", "ArmSolver", "EquilibriumNotReached", "DEFAULT_PRETENSION", "TipLoadResult", "tip_load",
           "SnapResult", "pull_until_snap", "CapacityResult", "load_capacity",
           "arm_summary"]

#: Tension of each tendon before a tip load is applied [N] (an assumption, see above).
DEFAULT_PRETENSION = float(_core.analyses.DEFAULT_PRETENSION)


class EquilibriumNotReached(RuntimeError):
    """The solver did not reach the equilibrium asked for (Newton did not converge, or the
    arm lost stability on the way): the input is valid, this arm cannot be brought there.

    A ``RuntimeError``, so that code catching that keeps working.

    Attributes
    ----------
    target : str
        What was asked for, e.g. ``"pretension 1.0 N"``.
    reason : str
        Why the solver stopped.
    """

    def __init__(self, target: str, reason: str):
        super().__init__(f"{target} not reached: {reason}")
        self.target, self.reason = target, reason


@dataclass(frozen=True)
class ArmState:
    """One equilibrium of the arm.

    Attributes
    ----------
    pulls : ndarray (3,)
        Tendon pulls [mm].
    load : ndarray (3,)
        Tip load [N].
    tip_position, tip_displacement : ndarray (3,)
        The tip guide's centre and its displacement from the built arm [mm].
    tension, tendon_length : ndarray (3,)
        Tendon tensions [N] (0 when slack) and path lengths [mm].
    cell_height : ndarray (2 m,)
        Distance between each cell's polygon centroids [mm].
    module_length : ndarray (m,)
        Distance between each module's guide centres [mm].
    cell_states : tuple of int
        Per cell, 1 extended / 0 contracted (by height).
    negative_eigenvalues : int
        Of the free tangent (0: stable; -1: unknown).
    energy : float
        Strain energy, tendons included [N mm].
    displacement : ndarray (3 N,)
        Every DOF [mm].
    """

    pulls: np.ndarray
    load: np.ndarray
    tip_position: np.ndarray
    tip_displacement: np.ndarray
    tension: np.ndarray
    tendon_length: np.ndarray
    cell_height: np.ndarray
    module_length: np.ndarray
    cell_states: tuple
    negative_eigenvalues: int
    energy: float
    displacement: np.ndarray = field(repr=False)
    _core: object = field(repr=False)

    @classmethod
    def from_core(cls, s) -> "ArmState":
        return cls(np.asarray(s.pulls, dtype=float), np.asarray(s.load, dtype=float),
                   np.asarray(s.tip_position), np.asarray(s.tip_displacement),
                   np.asarray(s.tension, dtype=float), np.asarray(s.tendon_length, dtype=float),
                   np.asarray(s.cell_height), np.asarray(s.module_length),
                   tuple(int(v) for v in s.cell_states), int(s.negative_eigenvalues),
                   float(s.energy), np.asarray(s.displacement), s)

    @property
    def configuration(self) -> str:
        """Module states from the cells': '0', '1', or 'x' for a module whose two cells are
        in different states."""
        c = self.cell_states
        return "".join(str(c[i]) if c[i] == c[i + 1] else "x" for i in range(0, len(c), 2))

    @property
    def tension_sum(self) -> float:
        return float(self.tension.sum())


def _pulls(name, value, allow_negative=False) -> list:
    array = as_float_array(name, value) if value is not None else np.zeros(3)
    if array.shape != (3,):
        raise ValueError(f"{name} = {show(value)} is invalid: must be three values [mm], one per tendon")
    if not allow_negative:
        for t, v in enumerate(array):
            if not v >= 0:
                raise ValueError(f"{name}[{t}] = {float(v)!r} mm is invalid: makes tendon {t + 1} longer "
                                 "than its slack length; a pull must be >= 0 (a tendon cannot push)")
    return [float(v) for v in array]


def _vector(name, value) -> list:
    array = as_float_array(name, value) if value is not None else np.zeros(3)
    if array.shape != (3,) or not np.isfinite(array).all():
        raise ValueError(f"{name} = {show(value)} is invalid: must be three finite values")
    return [float(v) for v in array]


class ArmSolver:
    """Path following on one arm (reusable: the sparsity pattern is built once).

    Parameters
    ----------
    arm : Arm
    steps : int, default 10
        Nominal increments of a path.
    max_bisections : int, default 12
        An increment may be halved this many times.
    tolerance : float, default 1e-6
        Newton tolerance on the correction [mm].
    max_iterations : int, default 30
        Newton iterations of an increment before it is halved.
    """

    def __init__(self, arm: Arm, *, steps: int = 10, max_bisections: int = 12,
                 tolerance: float = 1e-6, max_iterations: int = 30):
        if not isinstance(arm, Arm):
            raise ValueError(f"arm = {show(arm)} is invalid: must be a kresling.arm.Arm")
        o = _core.analyses.ArmOptions()
        o.steps = as_integer("steps", steps, minimum=1)
        o.max_bisections = as_integer("max_bisections", max_bisections, minimum=0)
        o.tolerance = as_real("tolerance", tolerance)
        o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
        self.arm = arm
        self._core = _core.analyses.ArmSolver(arm._core, o)

    def built(self) -> ArmState:
        """The built, unloaded arm."""
        return ArmState.from_core(self._core.built())

    def state_at(self, displacement, pulls, load=None) -> ArmState:
        """The arm at ``displacement`` (3 N,) [mm] with ``pulls`` (3,) [mm] (negative: let
        out) and tip ``load`` (3,) [N]: its tensions, heights, cell states and energy there,
        whether or not it is an equilibrium (e.g. one under loads the arm solver does not
        carry, such as the arm's weight)."""
        u = as_float_array("displacement", displacement).ravel()
        if u.shape != (self.arm.model.num_dofs,) or not np.isfinite(u).all():
            raise ValueError(f"displacement = {show(displacement)} is invalid: must be "
                             f"{self.arm.model.num_dofs} finite displacements [mm]")
        return ArmState.from_core(self._core.evaluate(u, _pulls("pulls", pulls,
                                                                allow_negative=True),
                                                      _vector("load", load)))

    def ramp(self, start: ArmState, pulls=None, load=None) -> list:
        """Equilibria from ``start`` to ``pulls``/``load`` (straight ramp; a pull may be
        negative here: the tendon let out beyond its slack length). Returns ``(states,
        completed, message)``."""
        path = self._core.ramp(start._core, _pulls("pulls", pulls, allow_negative=True),
                               _vector("load", load))
        return [ArmState.from_core(s) for s in path.states], bool(path.completed), path.message

    def pretension(self, tension: float, start: ArmState | None = None) -> ArmState:
        """The equilibrium with every tendon at ``tension`` [N] (from the built arm).

        Raises
        ------
        ValueError
            For a tension that is not a number.
        EquilibriumNotReached
            Where the solver does not get there (say, tendons so stiff that the pulls'
            Newton iteration does not converge).
        """
        tension = as_real("pretension", tension)
        start = self.built() if start is None else start
        path = self._core.pretension(start._core, tension)
        if not path.completed:
            raise EquilibriumNotReached(f"pretension {tension} N", path.message)
        return ArmState.from_core(path.states[-1])

    def release(self, start: ArmState, pulls=None) -> tuple:
        """Where the arm comes to rest from ``start`` with ``pulls`` (default: ``start``'s;
        a pull may be negative: the tendon let out) and no tip load: energy descent to a
        stable equilibrium. Returns ``(state, converged, message)``."""
        pulls = start.pulls if pulls is None else pulls
        r = self._core.release(start._core, _pulls("pulls", pulls, allow_negative=True))
        return ArmState.from_core(r.state), bool(r.converged), r.message

    def tip_compliance(self, state: ArmState) -> np.ndarray:
        """d(tip displacement)/d(tip load) at ``state``, (3, 3) [mm/N] (the tangent's)."""
        return np.asarray(self._core.tip_compliance(state._core))

    def tension_sensitivity(self, state: ArmState) -> np.ndarray:
        """d tension_i / d pull_j at ``state``, (3, 3) [N/mm]."""
        return np.asarray(self._core.tension_sensitivity(state._core))


@dataclass(frozen=True)
class TipLoadResult:
    """The arm under a tip load.

    Attributes
    ----------
    load : ndarray (3,)
        [N]
    pretension : float
        Tension of each tendon before the load [N].
    completed : bool
        The whole load was carried; otherwise the arm lost equilibrium (see ``message``)
        and ``state`` is the last equilibrium.
    state : ArmState
        The loaded equilibrium (the last one reached).
    unloaded : ArmState
        The pretensioned arm before the load.
    tip_displacement : ndarray (3,)
        Tip motion caused by the load (from ``unloaded``) [mm].
    compliance : ndarray (3, 3)
        Tip compliance of the unloaded (pretensioned) arm [mm/N], symmetric.
    load_factor : float
        Fraction of the load carried.
    lost_between : (float, float) or None
        When the arm lost equilibrium: the load factors of the last equilibrium and of the
        increment that found none (its resolution: 1/4096 of a tenth of the load).
    snapped_module : int
        Then, the module of the cell that jumped, or whose height changes most along the
        mode losing its stiffness (0-based from the base); -1 otherwise.
    message : str
    """

    load: np.ndarray
    pretension: float
    completed: bool
    state: ArmState
    unloaded: ArmState
    tip_displacement: np.ndarray
    compliance: np.ndarray
    load_factor: float
    lost_between: tuple | None
    snapped_module: int
    message: str


def tip_load(arm: Arm, load, *, pulls=None, pretension: float = DEFAULT_PRETENSION,
             solver: ArmSolver | None = None) -> TipLoadResult:
    """Equilibrium of ``arm`` under a tip force, tendons pretensioned first.

    Parameters
    ----------
    arm : Arm
    load : array_like (3,)
        Tip force [N] on the tip guide's centre.
    pulls : array_like (3,), optional
        Further pulls of the tendons, ramped with the load [mm] (>= 0).
    pretension : float, default :data:`DEFAULT_PRETENSION`
        Tension of each tendon before the load [N]; 0 leaves them just taut.

    Examples
    --------
    >>> from kresling.arm import build_arm
    >>> r = tip_load(build_arm("1"), [0.05, 0.0, 0.0])
    >>> r.completed, round(float(r.tip_displacement[0]), 2), round(float(r.compliance[0, 0]), 2)
    (True, 0.25, 4.96)
    """
    load = _vector("load", load)
    pulls = _pulls("pulls", pulls)
    pretension = as_real("pretension", pretension)
    if not (math.isfinite(pretension) and pretension >= 0):
        raise ValueError(f"pretension = {pretension!r} is invalid: must be >= 0 (N per tendon)")
    solver = ArmSolver(arm) if solver is None else solver
    r = _core.analyses.arm_tip_load(solver._core, load, pulls, pretension)
    unloaded = ArmState.from_core(r.pretensioned)
    states = r.path.states
    state = ArmState.from_core(states[-1]) if states else unloaded
    factor = float(r.path.parameter[-1]) if len(r.path.parameter) else 0.0
    lost = (factor, float(r.path.end_parameter)) if r.path.lost else None
    return TipLoadResult(np.asarray(load), pretension, bool(r.completed), state, unloaded,
                         state.tip_position - unloaded.tip_position,
                         solver.tip_compliance(unloaded), factor, lost,
                         r.path.critical_cell // 2 if r.path.lost and r.path.critical_cell >= 0
                         else -1, r.message)


@dataclass(frozen=True)
class SnapResult:
    """Pulling tendons until a module snaps.

    Attributes
    ----------
    snapped : bool
    direction : ndarray (3,)
        Relative pulls (largest 1).
    pull : float
        The largest tendon pull at the snap [mm] (NaN if none).
    pulls, tension : ndarray (3,)
        Every tendon's pull [mm] and tension [N] at the last stable state before the snap.
    tension_sum : float
        Sum of the three tensions there [N].
    snapped_module : int
        The module that snapped, 0-based from the base (-1 if none).
    snapped_cells : tuple of int
    configuration_before, configuration_after : str
        Module states before and after ('x': the two cells of a module in different states:
        a pulled module snaps one cell at a time, its tendons slacken and the other cell
        re-extends).
    states : list of ArmState
        The path.
    after : ArmState or None
        Where the released arm came to rest.
    message : str
    """

    snapped: bool
    direction: np.ndarray
    pull: float
    pulls: np.ndarray
    tension: np.ndarray
    tension_sum: float
    snapped_module: int
    snapped_cells: tuple
    configuration_before: str
    configuration_after: str
    states: list
    after: ArmState | None
    message: str


def pull_until_snap(arm: Arm, direction=(1.0, 1.0, 1.0), *, max_pull: float | None = None,
                    start: ArmState | None = None,
                    solver: ArmSolver | None = None) -> SnapResult:
    """Pull the tendons (all together, or some) until a module snaps.

    Parameters
    ----------
    arm : Arm
    direction : array_like (3,), default (1, 1, 1)
        Relative pulls, each >= 0 (``(1, 0, 0)``: tendon 1 alone).
    max_pull : float, optional
        Largest pull of any tendon [mm]; default ``2 (Le - Lc)`` per extended module (the
        travel of switching them all), at least ``2 (Le - Lc)``, below the slack length.
    start : ArmState, optional
        Where to start (default: the built arm).

    Examples
    --------
    >>> from kresling.arm import build_arm
    >>> r = pull_until_snap(build_arm("1"))
    >>> r.snapped, r.snapped_module, round(r.tension_sum, 2), r.configuration_after
    (True, 0, 8.11, 'x')
    """
    d = _pulls("direction", direction)
    if max(d) <= 0:
        raise ValueError(f"direction = {show(direction)} is invalid: pull at least one tendon")
    solver = ArmSolver(arm) if solver is None else solver
    start = solver.built() if start is None else start
    if max_pull is None:
        travel = 2.0 * (arm.design.Le - arm.design.Lc)
        max_pull = max(travel, travel * arm.configuration.count("1"))
        max_pull = min(max_pull, 0.9 * float(np.min(arm.slack_length - start.pulls)))
    max_pull = as_real("max_pull", max_pull)
    r = _core.analyses.arm_pull_until_snap(solver._core, start._core, d, max_pull)
    states = [ArmState.from_core(s) for s in r.path.states]
    after = ArmState.from_core(r.after) if r.snapped and len(r.cell_states_after) else None
    return SnapResult(bool(r.snapped), np.asarray(d) / max(d), float(r.pull),
                      np.asarray(r.pulls, dtype=float), np.asarray(r.tension, dtype=float),
                      float(r.tension_sum), int(r.snapped_module), tuple(r.snapped_cells),
                      start.configuration, r.configuration_after or start.configuration,
                      states, after, r.message)


@dataclass(frozen=True)
class CapacityResult:
    """The largest tip load along one direction.

    Attributes
    ----------
    direction : ndarray (3,)
        Unit vector.
    load : float
        Magnitude at the limit [N] (``max_load`` when none is reached).
    limit : str
        ``"slack"`` (a tendon that was taut went slack), ``"snap"`` (equilibrium lost: a
        module snaps), ``"none"`` (neither up to ``max_load``).
    tendon : int
        The tendon that went slack (0-based; -1 otherwise).
    module : int
        The module that snapped when known (0-based; -1 otherwise).
    tip_displacement : ndarray (3,)
        Tip motion at the limit [mm].
    message : str
    """

    direction: np.ndarray
    load: float
    limit: str
    tendon: int
    module: int
    tip_displacement: np.ndarray
    message: str


#: Directions of the load-capacity table: pushing the tip towards the base, and sideways
#: towards tendon 1 (+x), away from it (-x) and across (+y).
CAPACITY_DIRECTIONS = {"-z": (0.0, 0.0, -1.0), "+x": (1.0, 0.0, 0.0), "-x": (-1.0, 0.0, 0.0),
                       "+y": (0.0, 1.0, 0.0)}


def load_capacity(arm: Arm, direction, *, pretension: float = DEFAULT_PRETENSION,
                  max_load: float = 30.0, solver: ArmSolver | None = None,
                  pretensioned: ArmState | None = None) -> CapacityResult:
    """The largest tip load along ``direction`` before a module snaps or a taut tendon goes
    slack, from the arm pretensioned to ``pretension`` N per tendon (> 0: a just-taut tendon
    has no slack margin).

    Raises
    ------
    EquilibriumNotReached
        Where the pretension itself is not reached (see :meth:`ArmSolver.pretension`).

    Examples
    --------
    >>> from kresling.arm import build_arm
    >>> r = load_capacity(build_arm("1"), (1, 0, 0))
    >>> r.limit, r.tendon, round(r.load, 2)
    ('slack', 0, 0.98)
    """
    pretension = as_real("pretension", pretension)
    if not (math.isfinite(pretension) and pretension > 0):
        raise ValueError(f"pretension = {pretension!r} is invalid: must be > 0 (N per tendon): a "
                         "just-taut tendon goes slack under any load that shortens it")
    max_load = as_real("max_load", max_load)
    solver = ArmSolver(arm) if solver is None else solver
    start = solver.pretension(pretension) if pretensioned is None else pretensioned
    r = _core.analyses.arm_load_capacity(solver._core, start._core, _vector("direction", direction),
                                    max_load)
    last = r.path.states[-1]
    e = np.asarray(direction, dtype=float)
    return CapacityResult(e / np.linalg.norm(e), float(r.load), r.limit, int(r.tendon),
                          int(r.module), np.asarray(last.tip_position) - start.tip_position,
                          r.message)


def arm_summary(arm: Arm, state: ArmState) -> dict:
    """The JSON-able essentials of a state of ``arm`` (as ``kresling arm --json`` prints)."""
    return {
        "configuration": arm.configuration,
        "tip_position": state.tip_position.tolist(),
        "tip_height_built": arm.tip_height,
        "tension": state.tension.tolist(),
        "pulls": state.pulls.tolist(),
        "module_length": state.module_length.tolist(),
        "cell_height": state.cell_height.tolist(),
        "cell_states": list(state.cell_states),
        "stable": state.negative_eigenvalues == 0,
    }
