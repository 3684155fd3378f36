"""Implicit time integration: Newmark's average acceleration and HHT-alpha (C++ core).

Units are mm, N and s, so masses are in tonnes (t) and accelerations in mm/s^2. Each time
step is a Newton solve of the model with the step's inertia and damping terms; a step that
fails is halved (up to ``max_halvings`` times) and the step grows back after it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, as_integer, as_positive_real, as_real
from kresling.solvers._inputs import cholesky_choice, dof_vector
from kresling.solvers.path import PathResult

__all__ = ["solve_dynamics", "TimeHistory"]


@dataclass(frozen=True)
class TimeHistory:
    """A motion in time, one row per time step.

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
        the average acceleration scheme).
    """

    path: PathResult
    velocity: np.ndarray
    kinetic: np.ndarray
    strain: np.ndarray
    dissipated: np.ndarray
    work: np.ndarray

    @property
    def time(self) -> np.ndarray:
        """The time of each step [s]."""
        return self.path.load_factor

    @property
    def completed(self) -> bool:
        return self.path.completed


def solve_dynamics(model, masses, time_step, duration, *, forces=None, gravity=None,
                   load_table=None,
                   hht_alpha=0.0, mass_damping=0.0, stiffness_damping=0.0, tolerance=1e-6,
                   max_iterations=50, max_halvings=10, initial=None, initial_velocity=None,
                   stop=None, cholesky="auto") -> TimeHistory:
    """Integrate the model's motion ``M a + C v + f_int(u) = f(t)`` in time.

    Parameters
    ----------
    model : kresling.model.Model
    masses : array_like, shape (N,) or (3N,)
        Lumped masses [t], per node or per DOF; every free DOF needs one > 0.
    time_step, duration : float
        The step and the time to integrate over [s].
    forces : array_like, shape (3N,) or (N, 3), optional
        The load [N] (gravity: the masses times g, e.g. -9810 mm/s^2 along z).
    gravity : array_like, shape (3,), optional
        A body load: the acceleration of gravity [mm/s^2] (e.g. ``(0, 0, -9810)``), added
        to ``forces`` as every DOF's mass times it, and scaled with them by the table.
    load_table : array_like, shape (K, 2), optional
        ``[t, factor]`` rows: the load's factor, piecewise linear in t and constant beyond
        the table's ends (a step: ``[[0, 1]]``; a ramp: ``[[0, 0], [T, 1]]``). Default: 1.
    hht_alpha : float in [-1/3, 0]
        0: the average acceleration scheme (no numerical damping); below 0, HHT-alpha's
        damping of the modes the step does not resolve.
    mass_damping, stiffness_damping : float
        Rayleigh damping ``C = mass_damping M + stiffness_damping K0`` [1/s, s], K0 the
        tangent at the start.
    stop : callable, optional
        ``stop(time, displacement) -> bool`` after every step; True ends the motion there.

    Returns
    -------
    TimeHistory
    """
    masses = as_float_array("masses", masses).ravel()
    if masses.shape == (model.num_nodes,):
        masses = np.repeat(masses, 3)
    if masses.shape != (model.num_dofs,):
        raise ValueError(f"masses has {masses.size} entries: must have one per node "
                         f"({model.num_nodes}) or per DOF ({model.num_dofs})")
    if not np.isfinite(masses).all() or (masses < 0).any():
        raise ValueError("masses must be finite and >= 0 [t]")
    table = np.zeros((0, 2)) if load_table is None else as_float_array("load_table", load_table)
    if table.ndim != 2 or table.shape[1] != 2 or (len(table) and
                                                   (np.diff(table[:, 0]) <= 0).any()):
        raise ValueError("load_table must be rows [t, factor] with increasing t")
    o = _core.solvers.TimeIntegrationOptions()
    o.time_step = as_positive_real("time_step", time_step)
    o.duration = as_positive_real("duration", duration)
    o.hht_alpha = as_real("hht_alpha", hht_alpha)
    o.mass_damping = as_real("mass_damping", mass_damping)
    o.stiffness_damping = as_real("stiffness_damping", stiffness_damping)
    o.tolerance = as_positive_real("tolerance", tolerance)
    o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
    o.max_halvings = as_integer("max_halvings", max_halvings, minimum=0)
    o.cholesky = cholesky_choice(cholesky)
    if stop is not None and not callable(stop):
        raise ValueError(f"stop = {stop!r} is invalid: must be None or a callable")
    o.stop = stop
    load = np.zeros(model.num_dofs) if forces is None else dof_vector(model, "forces", forces)
    if gravity is not None:
        g = as_float_array("gravity", gravity).ravel()
        if g.shape != (3,) or not np.isfinite(g).all():
            raise ValueError(f"gravity has shape {g.shape}: must be 3 finite numbers [mm/s^2]")
        load = load + masses * np.tile(g, model.num_nodes)
    core = _core.solvers.integrate_newmark(
        model._core, np.ascontiguousarray(masses), load, np.ascontiguousarray(table[:, 0]),
        np.ascontiguousarray(table[:, 1]), o,
        dof_vector(model, "initial", initial, allow_none=True),
        dof_vector(model, "initial_velocity", initial_velocity, allow_none=True))
    return TimeHistory(PathResult._from_core(core.path), np.asarray(core.velocity),
                       np.asarray(core.kinetic), np.asarray(core.strain),
                       np.asarray(core.dissipated), np.asarray(core.work))
