"""Time integration (C++ core): Newmark's average acceleration, HHT-alpha and explicit
central differences.

Units are mm, N and s, so masses are in tonnes (t) and accelerations in mm/s^2. An implicit
step (``scheme = "newmark"`` or ``"hht"``) is a Newton solve of the model with the step's
inertia and damping terms; a step that fails is halved (up to ``max_halvings`` times) and
the step grows back after it. An explicit step (``scheme = "explicit"``) is one evaluation
of the internal force, at most the stable step (:func:`stable_time_step`) long.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, as_integer, as_positive_real, as_real
from kresling.solvers._inputs import cholesky_choice, dof_vector
from kresling.solvers.path import PathResult

__all__ = ["solve_dynamics", "stable_time_step", "time_factor", "TimeHistory", "StableStep",
           "SCHEMES", "DAMPING_TANGENTS"]

#: The time integration schemes.
SCHEMES = ("newmark", "hht", "explicit")
#: The tangent in the stiffness-proportional damping: the start's or each step's start's.
DAMPING_TANGENTS = ("initial", "current")


@dataclass(frozen=True)
class TimeHistory:
    """A motion in time, one row per (recorded) time step.

    Attributes
    ----------
    path : PathResult
        ``load_factor`` holds the time [s]; ``displacement`` (S, 3N) [mm];
        ``constraint_force`` the support reactions [N].
    velocity : ndarray, shape (S, 3N)
        [mm/s].
    kinetic, strain, dissipated, work : ndarray, shape (S,)
        Kinetic energy, the model's stored energy, the energy the damping has dissipated
        and the work the loads have done, up to each step [N*mm]: kinetic + strain +
        dissipated - work - actuation_work stays at its initial value (exactly, for a
        linear model under the average acceleration scheme; to O((w dt)^2) under the
        explicit one).
    actuation_work : ndarray, shape (S,)
        The work the driven creases' rest angles have done on the sheet up to each step
        [N*mm] (zeros without an actuation).
    stable_time_step : float
        The explicit scheme's stable step at the start [s]; NaN for the implicit schemes.
    time_step : float
        The step taken [s] (explicit: the duration in whole steps of at most ``time_step``;
        implicit: the nominal step).
    scheme : str
        One of :data:`SCHEMES`.
    """

    path: PathResult
    velocity: np.ndarray
    kinetic: np.ndarray
    strain: np.ndarray
    dissipated: np.ndarray
    work: np.ndarray
    actuation_work: np.ndarray
    stable_time_step: float = float("nan")
    time_step: float = float("nan")
    scheme: str = "newmark"

    @property
    def time(self) -> np.ndarray:
        """The time of each step [s]."""
        return self.path.load_factor

    @property
    def completed(self) -> bool:
        return self.path.completed


@dataclass(frozen=True)
class StableStep:
    """The explicit scheme's stable step (see :func:`stable_time_step`).

    Attributes
    ----------
    time_step : float
        [s]; inf for a model without stiffness or damping.
    omega_max : float
        The highest natural frequency, by power iteration [rad/s].
    omega_bound : float
        Gershgorin's upper bound of it [rad/s].
    iterations : int
        Power iterations taken.
    """

    time_step: float
    omega_max: float
    omega_bound: float
    iterations: int


def _dof_masses(model, masses):
    masses = as_float_array("masses", masses).ravel()
    if masses.shape == (model.num_nodes,):
        masses = np.repeat(masses, 3)
    if masses.shape != (model.num_dofs,):
        raise ValueError(f"masses has {masses.size} entries: must have one per node "
                         f"({model.num_nodes}) or per DOF ({model.num_dofs})")
    if not np.isfinite(masses).all() or (masses < 0).any():
        raise ValueError("masses must be finite and >= 0 [t]")
    return np.ascontiguousarray(masses)


def stable_time_step(model, masses, u=None, *, mass_damping=0.0,
                     stiffness_damping=0.0) -> StableStep:
    """The largest step explicit central differences take stably at displacement ``u``.

    ``2 / (sqrt(w^2 + s^2) + s)`` with ``s = (mass_damping + stiffness_damping w^2) / 2``
    at the highest natural frequency ``w`` of the tangent at ``u`` with the lumped masses
    (``2 / w`` undamped), ``w`` by a power iteration on ``M^-1/2 K M^-1/2``.

    Parameters
    ----------
    model : kresling.model.Model
    masses : array_like, shape (N,) or (3N,)
        Lumped masses [t]; every free DOF needs one > 0.
    u : array_like, shape (3N,) or (N, 3), optional
        The state [mm] (default: the rest state).
    mass_damping, stiffness_damping : float
        Rayleigh damping [1/s, s].

    Returns
    -------
    StableStep
    """
    masses = _dof_masses(model, masses)
    free = ~np.asarray(model.fixed, bool).ravel()
    if (masses[free] <= 0).any():
        node = int(np.flatnonzero(free & (masses <= 0))[0]) // 3
        raise ValueError(f"masses: node {node} is free and has no mass: every free DOF needs "
                         "a mass > 0")
    core = _core.solvers.stable_time_step(
        model._core, masses, dof_vector(model, "u", u, allow_none=True),
        as_real("mass_damping", mass_damping), as_real("stiffness_damping", stiffness_damping))
    return StableStep(core.time_step, core.omega_max, core.omega_bound, core.iterations)


def _time_function(value, name="a load's time", table_name="load_table"):
    """A time function as the core's (times, factors, amplitude, frequency_hz,
    end_frequency_hz, sweep_time): None (the factor 1), a ``[t, factor]`` table,
    ``{"harmonic": (amplitude, frequency_hz)}`` or ``{"chirp": (amplitude, f0_hz, f1_hz,
    sweep_s)}``."""
    empty = np.zeros(0)
    if value is None:
        return empty, empty, 0.0, 0.0, 0.0, 0.0
    if isinstance(value, dict):
        kind = next(iter(value)) if len(value) == 1 else None
        size = {"harmonic": 2, "chirp": 4}.get(kind)
        numbers = None if size is None else as_float_array(f"{name}: {kind}",
                                                           value[kind]).ravel()
        if numbers is None or numbers.shape != (size,) or not np.isfinite(numbers).all() or \
                (numbers[1:] <= 0).any():
            raise ValueError(f"{name} = {value!r} is invalid: must be "
                             "{'harmonic': (amplitude, frequency_hz)} or {'chirp': (amplitude, "
                             "f0_hz, f1_hz, sweep_s)}, its frequencies and sweep > 0")
        if kind == "harmonic":
            return empty, empty, float(numbers[0]), float(numbers[1]), 0.0, 0.0
        return (empty, empty, *(float(x) for x in numbers))
    table = as_float_array(table_name, value)
    if table.ndim != 2 or table.shape[1] != 2 or not len(table) or \
            not np.isfinite(table).all() or (np.diff(table[:, 0]) <= 0).any():
        raise ValueError(f"{table_name} must be rows [t, factor] with increasing t")
    return (np.ascontiguousarray(table[:, 0]), np.ascontiguousarray(table[:, 1]), 0.0, 0.0,
            0.0, 0.0)


def time_factor(time, times) -> np.ndarray:
    """A time function (as ``loads`` and ``actuation`` of :func:`solve_dynamics` take it)
    at ``times`` [s], shape (T,), as the integrator evaluates it."""
    return np.asarray(_core.solvers.time_factor(
        _time_function(time), np.ascontiguousarray(np.atleast_1d(times), dtype=float)))


def _load_terms(model, masses, forces, gravity, load_table, loads):
    """The core's load terms: ``forces`` and gravity under ``load_table``, then ``loads``."""
    load = np.zeros(model.num_dofs) if forces is None else dof_vector(model, "forces", forces)
    if gravity is not None:
        g = as_float_array("gravity", gravity).ravel()
        if g.shape != (3,) or not np.isfinite(g).all():
            raise ValueError(f"gravity has shape {g.shape}: must be 3 finite numbers [mm/s^2]")
        load = load + masses * np.tile(g, model.num_nodes)
    terms = [(load, _time_function(load_table))]
    for i, entry in enumerate(loads or ()):
        if not isinstance(entry, (tuple, list)) or len(entry) != 2:
            raise ValueError(f"loads[{i}] must be a pair (forces, time)")
        terms.append((dof_vector(model, f"loads[{i}] forces", entry[0]),
                      _time_function(entry[1])))
    return terms


def _actuation_terms(model, actuation):
    """The core's rest-angle terms (hinges, start, delta, time function) of ``actuation``."""
    rest = np.asarray(model.hinge_rest_angle, dtype=float)
    terms = []
    for i, entry in enumerate(actuation or ()):
        if not isinstance(entry, (tuple, list)) or len(entry) != 3:
            raise ValueError(f"actuation[{i}] must be a triple (hinges, delta, time)")
        hinges = np.asarray(entry[0]).ravel()
        if not len(hinges) or not np.issubdtype(hinges.dtype, np.integer) or \
                hinges.min() < 0 or hinges.max() >= len(rest):
            raise ValueError(f"actuation[{i}] hinges = {entry[0]!r} is invalid: must be "
                             f"model hinge indices in [0, {len(rest)})")
        delta = as_float_array(f"actuation[{i}] delta", entry[1]).ravel()
        if delta.shape != hinges.shape or not np.isfinite(delta).all():
            raise ValueError(f"actuation[{i}] delta has shape {delta.shape}: must be one "
                             f"finite rest-angle change [rad] per hinge ({len(hinges)})")
        hinges = hinges.astype(np.int64)
        terms.append((hinges.tolist(), np.ascontiguousarray(rest[hinges]), delta,
                      _time_function(entry[2], f"actuation[{i}] time",
                                     f"actuation[{i}] time")))
    return terms


def _scheme(scheme, hht_alpha):
    if scheme is None:
        return "hht" if hht_alpha != 0 else "newmark"
    if scheme not in SCHEMES:
        raise ValueError(f"scheme = {scheme!r} is invalid: must be one of {list(SCHEMES)}")
    if scheme != "hht" and hht_alpha != 0:
        raise ValueError(f"hht_alpha = {hht_alpha!r} applies only with scheme = 'hht'")
    return scheme


#: The defaults, as the core declares them (not restated here).
_IMPLICIT = _core.solvers.TimeIntegrationOptions()
_EXPLICIT = _core.solvers.ExplicitOptions()


def solve_dynamics(model, masses, time_step, duration, *, forces=None, gravity=None,
                   load_table=None, loads=None, scheme=None,
                   hht_alpha=_IMPLICIT.hht_alpha, mass_damping=_IMPLICIT.mass_damping,
                   stiffness_damping=_IMPLICIT.stiffness_damping, damping_tangent="initial",
                   actuation=None, tolerance=_IMPLICIT.tolerance, max_iterations=_IMPLICIT.max_iterations,
                   max_halvings=_IMPLICIT.max_halvings, record_every=_EXPLICIT.record_every,
                   initial=None, initial_velocity=None, stop=None,
                   cholesky="auto") -> TimeHistory:
    """Integrate the model's motion ``M a + C v + f_int(u) = f(t)`` in time.

    Parameters
    ----------
    model : kresling.model.Model
    masses : array_like, shape (N,) or (3N,)
        Lumped masses [t], per node or per DOF; every free DOF needs one > 0.
    time_step, duration : float
        The step and the time to integrate over [s]. The explicit scheme refuses a step
        above :func:`stable_time_step` and takes the duration in whole steps.
    forces : array_like, shape (3N,) or (N, 3), optional
        The load [N].
    gravity : array_like, shape (3,), optional
        A body load: the acceleration of gravity [mm/s^2] (e.g. ``(0, 0, -9810)``), added
        to ``forces`` as every DOF's mass times it, and scaled with them by the table.
    load_table : array_like, shape (K, 2), optional
        ``[t, factor]`` rows: the factor of ``forces`` and gravity, piecewise linear in t
        and constant beyond the table's ends (a step: ``[[0, 1]]``; a ramp:
        ``[[0, 0], [T, 1]]``). Default: 1.
    loads : sequence of (forces, time), optional
        More loads, each with its own time function: None (1), a ``[t, factor]`` table,
        ``{"harmonic": (amplitude, frequency_hz)}`` (``amplitude sin(2 pi f t)``) or
        ``{"chirp": (amplitude, f0_hz, f1_hz, sweep_s)}`` (``amplitude sin(phi(t))``, the
        frequency ``phi'(t) / 2 pi`` going linearly from f0 at t = 0 to f1 at
        ``sweep_s``, and held at f1 beyond, the phase continuous).
    scheme : {"newmark", "hht", "explicit"}, optional
        Default: "hht" when ``hht_alpha`` is non-zero, else "newmark".
    hht_alpha : float in [-1/3, 0]
        HHT-alpha's parameter: below 0 it damps the modes the step does not resolve.
    mass_damping, stiffness_damping : float
        Rayleigh damping ``C = mass_damping M + stiffness_damping K`` [1/s, s].
    damping_tangent : {"initial", "current"}
        K in the damping: the tangent at the start ("initial": C is constant), or the
        tangent of the state each step starts from, held over the step ("current", the
        implicit schemes only).
    actuation : sequence of (hinges, delta, time), optional
        Creases driven in time (the implicit schemes only): the rest angle of each of
        ``hinges`` (model hinge indices, shape (K,)) is its rest angle in ``model`` plus
        ``factor(t) * delta`` (``delta`` shape (K,) [rad]), ``time`` a time function as
        ``loads`` take it; a hinge in two entries follows the later. The internal force
        of each step uses the rest angles at its end; a rest angle leaving [0, 2 pi) (a
        fold beyond flat) ends the run with a ValueError naming the entry and the time.
    record_every : int
        The explicit scheme keeps every ``record_every``-th step (and the last).
    stop : callable, optional
        ``stop(time, displacement) -> bool`` after every (recorded) step; True ends the
        motion there.

    Returns
    -------
    TimeHistory
    """
    masses = _dof_masses(model, masses)
    hht_alpha = as_real("hht_alpha", hht_alpha)
    scheme = _scheme(scheme, hht_alpha)
    terms = _load_terms(model, masses, forces, gravity, load_table, loads)
    if stop is not None and not callable(stop):
        raise ValueError(f"stop = {stop!r} is invalid: must be None or a callable")
    start = (dof_vector(model, "initial", initial, allow_none=True),
             dof_vector(model, "initial_velocity", initial_velocity, allow_none=True))
    if damping_tangent not in DAMPING_TANGENTS:
        raise ValueError(f"damping_tangent = {damping_tangent!r} is invalid: must be one of "
                         f"{list(DAMPING_TANGENTS)}")
    schedule = _actuation_terms(model, actuation)
    if scheme == "explicit":
        if schedule:
            raise ValueError("actuation: the explicit scheme drives no creases: use scheme "
                             "'newmark' or 'hht'")
        if damping_tangent != "initial":
            raise ValueError(f"damping_tangent = {damping_tangent!r} is invalid with the "
                             "explicit scheme: must be 'initial'")
        o = _core.solvers.ExplicitOptions()
        o.record_every = as_integer("record_every", record_every, minimum=1)
    else:
        o = _core.solvers.TimeIntegrationOptions()
        o.hht_alpha = hht_alpha
        o.tolerance = as_positive_real("tolerance", tolerance)
        o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
        o.max_halvings = as_integer("max_halvings", max_halvings, minimum=0)
        o.cholesky = cholesky_choice(cholesky)
        o.damping_current_tangent = damping_tangent == "current"
        o.actuation = schedule
    o.time_step = as_positive_real("time_step", time_step)
    o.duration = as_positive_real("duration", duration)
    o.mass_damping = as_real("mass_damping", mass_damping)
    o.stiffness_damping = as_real("stiffness_damping", stiffness_damping)
    o.stop = stop
    integrate = (_core.solvers.integrate_explicit if scheme == "explicit"
                 else _core.solvers.integrate_newmark)
    core = integrate(model._core, masses, terms, o, *start)
    stable = core.stable_time_step if scheme == "explicit" else float("nan")
    return TimeHistory(PathResult._from_core(core.path), np.asarray(core.velocity),
                       np.asarray(core.kinetic), np.asarray(core.strain),
                       np.asarray(core.dissipated), np.asarray(core.work),
                       np.asarray(core.actuation_work), stable,
                       core.time_step, scheme)
