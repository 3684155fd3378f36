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

__all__ = ["solve_dynamics", "stable_time_step", "TimeHistory", "StableStep", "SCHEMES"]

#: The time integration schemes.
SCHEMES = ("newmark", "hht", "explicit")


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
        dissipated - work stays at its initial value (exactly, for a linear model under
        the average acceleration scheme; to O((w dt)^2) under the explicit one).
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


def _time_function(value):
    """A load's time function as the core's (times, factors, amplitude, frequency_hz)."""
    empty = np.zeros(0)
    if value is None:
        return empty, empty, 0.0, 0.0
    if isinstance(value, dict):
        harmonic = value.get("harmonic") if set(value) == {"harmonic"} else None
        pair = None if harmonic is None else as_float_array("harmonic", harmonic).ravel()
        if pair is None or pair.shape != (2,) or not np.isfinite(pair).all() or pair[1] <= 0:
            raise ValueError(f"a load's time = {value!r} is invalid: must be "
                             "{'harmonic': (amplitude, frequency_hz)} with a frequency > 0")
        amplitude, frequency = pair.tolist()
        return empty, empty, float(amplitude), float(frequency)
    table = as_float_array("load_table", value)
    if table.ndim != 2 or table.shape[1] != 2 or not len(table) or \
            not np.isfinite(table).all() or (np.diff(table[:, 0]) <= 0).any():
        raise ValueError("load_table must be rows [t, factor] with increasing t")
    return np.ascontiguousarray(table[:, 0]), np.ascontiguousarray(table[:, 1]), 0.0, 0.0


def _load_terms(model, masses, forces, gravity, load_table, loads):
    """The core's load terms: ``forces`` and gravity under ``load_table``, then ``loads``."""
    load = np.zeros(model.num_dofs) if forces is None else dof_vector(model, "forces", forces)
    if gravity is not None:
        g = as_float_array("gravity", gravity).ravel()
        if g.shape != (3,) or not np.isfinite(g).all():
            raise ValueError(f"gravity has shape {g.shape}: must be 3 finite numbers [mm/s^2]")
        load = load + masses * np.tile(g, model.num_nodes)
    terms = [(load, *_time_function(load_table))]
    for i, entry in enumerate(loads or ()):
        if not isinstance(entry, (tuple, list)) or len(entry) != 2:
            raise ValueError(f"loads[{i}] must be a pair (forces, time)")
        terms.append((dof_vector(model, f"loads[{i}] forces", entry[0]),
                      *_time_function(entry[1])))
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
                   stiffness_damping=_IMPLICIT.stiffness_damping,
                   tolerance=_IMPLICIT.tolerance, max_iterations=_IMPLICIT.max_iterations,
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
        More loads, each with its own time function: None (1), a ``[t, factor]`` table or
        ``{"harmonic": (amplitude, frequency_hz)}`` (``amplitude sin(2 pi f t)``).
    scheme : {"newmark", "hht", "explicit"}, optional
        Default: "hht" when ``hht_alpha`` is non-zero, else "newmark".
    hht_alpha : float in [-1/3, 0]
        HHT-alpha's parameter: below 0 it damps the modes the step does not resolve.
    mass_damping, stiffness_damping : float
        Rayleigh damping ``C = mass_damping M + stiffness_damping K0`` [1/s, s], K0 the
        tangent at the start.
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
    if scheme == "explicit":
        o = _core.solvers.ExplicitOptions()
        o.record_every = as_integer("record_every", record_every, minimum=1)
    else:
        o = _core.solvers.TimeIntegrationOptions()
        o.hht_alpha = hht_alpha
        o.tolerance = as_positive_real("tolerance", tolerance)
        o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
        o.max_halvings = as_integer("max_halvings", max_halvings, minimum=0)
        o.cholesky = cholesky_choice(cholesky)
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
                       np.asarray(core.dissipated), np.asarray(core.work), stable,
                       core.time_step, scheme)
