"""Displacement control as MERLIN2 runs it: the thesis's loading mode."""

from __future__ import annotations

from kresling import _core
from kresling.solvers._inputs import cholesky_choice, dof_vector
from kresling._validation import as_bool, as_integer, as_positive_real, as_real
from kresling.solvers.path import PathResult

#: The core's defaults (the options struct declares them once).
#: The defaults, as the core declares them (not restated here).
_DEFAULTS = _core.solvers.DisplacementControlOptions()


def solve_displacement_control(model, prescribed, steps, *, tolerance=_DEFAULTS.tolerance,
                               max_iterations=_DEFAULTS.max_iterations,
                               reject_iterations=_DEFAULTS.reject_iterations,
                               max_bisections=_DEFAULTS.max_bisections, shift=_DEFAULTS.shift,
                               extrapolation=_DEFAULTS.extrapolation, initial=None,
                               merlin2_steps=_DEFAULTS.merlin2_steps,
                               adaptive=_DEFAULTS.adaptive,
                               adaptive_tolerance=_DEFAULTS.adaptive_tolerance,
                               cholesky="auto", stop=None, keep_knots=False) -> PathResult:
    """Impose a displacement in equal increments and follow the equilibrium path.

    Only the non-zero entries of ``prescribed`` are imposed (zero entries stay free, as in
    MERLIN2). Each increment moves the imposed DOFs, then Newton runs on the free DOFs until
    the correction's 2-norm is at most ``tolerance``. An increment needing
    ``reject_iterations`` or more iterations is retried as two halves, recursively, up to
    ``max_bisections`` times; past that the path ends with ``completed = False``.

    Parameters
    ----------
    model : kresling.model.Model
    prescribed : array_like, shape (3N,) or (N, 3)
        Total displacement of the imposed DOFs [mm].
    steps : int
        Number of equal increments, 1 to 100 000 (the path keeps every one).
    tolerance : float
        Newton tolerance on ||du_free||_2 [mm] (MERLIN2: 1e-6).
    max_iterations, reject_iterations : int
        At most :data:`kresling._core.solvers.MAX_ITERATIONS` (10 000).
    max_bisections : int
        0 to 30: an increment may be cut to 1/2^max_bisections of its size.
    shift : float
        Added to the tangent's diagonal (MERLIN2: 1e-8); 0 to 1e-3 N/mm.
    extrapolation : {0, 1, 2, 3}
        Starting guess of each increment's free DOFs: the previous equilibrium (0, MERLIN2's
        iteration sequence), or a linear (1), quadratic (2) or cubic (3) extrapolation along
        the path through the last 2, 3 or 4 equilibria. The equilibrium found is the same to
        the Newton tolerance; 2 typically needs one iteration per increment instead of
        three. Where Newton converges only linearly (MERLIN2's super-linear bend law on
        nearly flat panels) the cubic saves most: MERLIN2's GMiura point load takes 1,877,
        626 and 481 iterations in its 200 increments with 0, 2 and 3.
    initial : array_like, optional
        Starting displacement (default zero).
    merlin2_steps : bool, default False
        MERLIN2 v1.1's step control instead of bisection: a rejected increment halves the
        step size, each accepted one brings it 10 % back towards nominal, and the path runs
        while the accumulated fraction of the motion is <= 1 (so with 10 steps it takes 11
        increments and ends at 1.1 of ``prescribed``, as MERLIN2 does). For reproducing
        MERLIN2's runs increment for increment.
    adaptive : bool, default False
        Keep the ``steps`` equal samples but follow the path between them in increments
        chosen by an error estimate, the samples inside an increment read off cubic Hermite
        curves through its converged ends (displacements, forces and energies with their
        exact path derivatives; 0 iterations); stability changes and hinges crossing a limit
        of the enhanced linear law are located before the path steps on. The drive's force
        (``sum_k F_k U_k / max|U|``, the summed reaction of a uniform drive) agrees with the
        fixed steps' to about ``adaptive_tolerance`` of its largest value; its shares among
        the driven DOFs only to the Newton tolerance, as between fixed-step runs. Faster
        where the path is smooth over many samples; models with cables keep fixed steps. A
        path they cannot finish is followed again in fixed steps (from ``extrapolation``'s
        start), whose result is returned with the attempts of both runs counted
        (docs/model.md, 'Displacement control').
    adaptive_tolerance : float, default 1e-9
        The adaptive samples' estimated error of the drive's force relative to its largest
        value on the path so far, in (0, 1e-4].
    cholesky : {"auto", "dense", "simplicial", "supernodal"}, default "auto"
        How positive definite tangents are factorised: by the measured cost model ("auto":
        dense below 32 free DOFs, else supernodal), or forced: dense (Eigen), simplicial
        (CHOLMOD) or supernodal (Eigen's dense kernels on CHOLMOD's symbolic analysis). The
        path is the same to rounding, except past a bifurcation, where rounding picks the
        branch the path follows.
    stop : callable, optional
        ``stop(load_factor, displacement) -> bool``, asked after every accepted increment
        (``displacement`` of shape (3N,)); True ends the path there (completed).
    keep_knots : bool, default False
        With ``adaptive``: keep the converged points the samples were read from
        (``PathResult.knots``), so that :func:`~kresling.solvers.path_sensitivity`
        differentiates the path at those points only (a path that fell back to fixed steps
        has none).

    Returns
    -------
    PathResult
        ``constraint_force`` holds, per step, the force at each imposed DOF (``-f_int``).

    Raises
    ------
    ValueError
        For bad input: shapes, NaN, nothing prescribed, a prescribed DOF that is also
        supported, a count or the shift out of its range.
    """
    options = displacement_control_options(
        tolerance=tolerance, max_iterations=max_iterations, reject_iterations=reject_iterations,
        max_bisections=max_bisections, shift=shift, extrapolation=extrapolation,
        merlin2_steps=merlin2_steps, adaptive=adaptive, adaptive_tolerance=adaptive_tolerance,
        cholesky=cholesky,
        stop=stop, keep_knots=keep_knots)
    d = _core.solvers.displacement_control(
        model._core, dof_vector(model, "prescribed", prescribed),
        as_integer("steps", steps, minimum=1),
        options, dof_vector(model, "initial", initial, allow_none=True))
    return PathResult._from_core(d)


def displacement_control_options(*, tolerance=1e-6, max_iterations=50, reject_iterations=25,
                                 max_bisections=10, shift=_DEFAULTS.shift, extrapolation=0,
                                 merlin2_steps=False, adaptive=False, adaptive_tolerance=1e-9,
                                 cholesky="auto", stop=None, keep_knots=False):
    """Checked C++ options object (see :func:`solve_displacement_control` for meanings)."""
    if extrapolation not in (0, 1, 2, 3) or isinstance(extrapolation, bool):
        raise ValueError(f"extrapolation = {extrapolation!r} is invalid: must be 0, 1, 2 or 3")
    o = _core.solvers.DisplacementControlOptions()
    o.tolerance = as_positive_real("tolerance", tolerance)
    o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
    o.reject_iterations = as_integer("reject_iterations", reject_iterations, minimum=1)
    o.max_bisections = as_integer("max_bisections", max_bisections, minimum=0)
    o.shift = as_real("shift", shift)
    o.extrapolation = int(extrapolation)
    o.merlin2_steps = as_bool("merlin2_steps", merlin2_steps)
    o.adaptive = as_bool("adaptive", adaptive)
    o.adaptive_tolerance = as_positive_real("adaptive_tolerance", adaptive_tolerance)
    o.cholesky = cholesky_choice(cholesky)
    if stop is not None and not callable(stop):
        raise ValueError(f"stop = {stop!r} is invalid: must be None or a callable")
    o.stop = stop
    o.keep_knots = as_bool("keep_knots", keep_knots)
    return o
