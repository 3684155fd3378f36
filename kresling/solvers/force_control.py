"""Path following under force control: load-stepped Newton and MGDCM."""

from __future__ import annotations

from kresling import _core
from kresling.solvers._inputs import cholesky_choice, dof_vector
from kresling._validation import as_integer, as_positive_real, as_real
from kresling.solvers.path import PathResult


#: The defaults, as the core declares them (not restated here).
_FORCE = _core.solvers.ForceControlOptions()
_MGDCM = _core.solvers.MgdcmOptions()


def solve_force_control(model, forces, steps, *, tolerance=_FORCE.tolerance,
                        max_iterations=_FORCE.max_iterations,
                        max_bisections=_FORCE.max_bisections, shift=_FORCE.shift, initial=None,
                        stop=None, cholesky="auto") -> PathResult:
    """Newton equilibrium under ``lambda * forces`` for lambda = 1/steps, ..., 1.

    A failed load step is halved up to ``max_bisections`` times. Past a limit point there is
    no nearby equilibrium: Newton either fails (the path stops, ``completed = False``) or
    converges to a distant one (a snap-through, visible as a jump in ``displacement``). To
    follow the path through limit points use :func:`solve_mgdcm`.

    Parameters
    ----------
    forces : array_like, shape (3N,) or (N, 3)
        Reference load [N].
    stop : callable, optional
        ``stop(load_factor, displacement) -> bool`` after every accepted step; True ends
        the path there (completed).
    cholesky : {"auto", "dense", "simplicial", "supernodal"}, default "auto"
        The tangent's factorisation, as in :func:`solve_displacement_control`.

    Returns
    -------
    PathResult
        ``constraint_force``: the support reactions at the supported DOFs.
    """
    o = _core.solvers.ForceControlOptions()
    o.cholesky = cholesky_choice(cholesky)
    o.tolerance = as_positive_real("tolerance", tolerance)
    o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
    o.max_bisections = as_integer("max_bisections", max_bisections, minimum=0)
    o.shift = as_real("shift", shift)
    o.stop = _stop(stop)
    core = _core.solvers.force_control(
        model._core, dof_vector(model, "forces", forces), as_integer("steps", steps, minimum=1),
        o, dof_vector(model, "initial", initial, allow_none=True))
    return PathResult._from_core(core)


def solve_mgdcm(model, forces, *, initial_load_factor=_MGDCM.initial_load_factor,
                max_increments=_MGDCM.max_increments, max_load_factor=_MGDCM.max_load_factor,
                monitor_dof=None, max_displacement=_MGDCM.max_displacement,
                max_step_factor=_MGDCM.max_step_factor, tolerance=_MGDCM.tolerance,
                max_iterations=_MGDCM.max_iterations, shift=_MGDCM.shift, initial=None,
                stop=None, cholesky="auto") -> PathResult:
    """Modified generalized displacement control (Leon, Paulino et al. 2011).

    Follows the equilibrium path of ``lambda * forces`` through limit points and
    snap-backs: the load factor is an unknown, the first iteration of each increment is
    scaled by the generalized stiffness parameter (its sign flips where the path turns),
    later iterations stay orthogonal to the first predictor. The step grows by 1.5 after an
    increment of fewer than 3 iterations and is halved (the increment retried) after one
    of more than 15. An increment whose corrections stall just above ``tolerance`` (rounding
    near a singular tangent, at a bifurcation or limit point) is retried with a step 4, then
    16 times longer, to land past the singular point; if that stalls too the path ends and
    ``message`` gives the size the corrections stalled at.

    Parameters
    ----------
    forces : array_like, shape (3N,) or (N, 3)
        Reference load [N].
    initial_load_factor : float
        First load-factor increment (MERLIN2's ``b_lambda``); its sign sets the direction.
    max_increments : int
        Accepted increments at most.
    max_load_factor : float
        Stop once ``|lambda|`` exceeds it.
    monitor_dof : int, optional
        With ``max_displacement``: stop once ``|u[monitor_dof]|`` exceeds it [mm].
    max_step_factor : float
        Cap on the step factor's growth, for a finely resolved path (MERLIN2 has none).
    stop : callable, optional
        ``stop(load_factor, displacement) -> bool`` after every accepted increment
        (``displacement`` of shape (3N,)); True ends the path there (completed).
    cholesky : {"auto", "dense", "simplicial", "supernodal"}, default "auto"
        The tangent's factorisation, as in :func:`solve_displacement_control`.

    Returns
    -------
    PathResult
        ``completed`` is True when a stopping criterion was met (or, without one, when all
        increments ran); otherwise ``message`` says why the path ended.
    """
    if monitor_dof is None:
        monitor_dof = -1
    else:
        monitor_dof = as_integer("monitor_dof", monitor_dof, minimum=0,
                                 maximum=model.num_dofs - 1)
    o = _core.solvers.MgdcmOptions()
    o.initial_load_factor = as_real("initial_load_factor", initial_load_factor)
    o.max_increments = as_integer("max_increments", max_increments, minimum=1)
    o.max_load_factor = as_real("max_load_factor", max_load_factor)
    o.monitor_dof = monitor_dof
    o.max_displacement = as_real("max_displacement", max_displacement)
    o.max_step_factor = as_real("max_step_factor", max_step_factor)
    o.tolerance = as_positive_real("tolerance", tolerance)
    o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
    o.shift = as_real("shift", shift)
    o.cholesky = cholesky_choice(cholesky)
    o.stop = _stop(stop)
    core = _core.solvers.mgdcm(model._core, dof_vector(model, "forces", forces), o,
                               dof_vector(model, "initial", initial, allow_none=True))
    return PathResult._from_core(core)


def _stop(stop):
    if stop is not None and not callable(stop):
        raise ValueError(f"stop = {stop!r} is invalid: must be None or a callable")
    return stop
