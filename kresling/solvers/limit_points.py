"""A limit point of a load-controlled equilibrium path, located exactly, and the derivative
of its load with respect to the elements' parameters.

Under force control the free DOFs are in equilibrium when ``r(u, p) = lambda f``, with
``r = f_int`` on the free DOFs. At a limit point the free tangent ``K_ff`` has a null vector
phi (the critical mode) and the load factor is extremal along the path. The point is found
by Newton's method on the extended system (Wriggers, Wagner and Miehe 1988)

    r_f(u, p) - lambda f_f = 0,      K_ff(u) phi = 0,      l . phi = 1,

whose Jacobian is regular at a simple limit point. Along the limit points of a family of
structures, ``phi . (K_ff du/dp + dr_f/dp - dlambda_c/dp f_f) = 0`` and ``phi . K_ff = 0``,
so ``dlambda_c/dp = phi . (dr_f/dp) / (phi . f_f)``: one scalar product per parameter
(docs/sensitivities.md, 'A limit point').
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling._validation import as_finite_real, as_integer, as_positive_real
from kresling.assembly import Workspace, assemble
from kresling.solvers._inputs import dof_vector
from kresling.solvers.path import PathResult
from kresling.solvers.sensitivity import Direction, residual_derivative

__all__ = ["LimitPoint", "limit_point"]

#: ``|phi . f|`` below this fraction of ``|phi| |f|``: the critical point is a bifurcation.
#: The load factor's derivative divides by ``phi . f``, and rounding leaves it about 1e-14
#: of ``|f|`` at a symmetric bifurcation, far below a limit point's O(1).
BIFURCATION = 1e-8

#: Above this many free DOFs the starting mode is found by sparse shift-invert iterations,
#: below it by a dense eigendecomposition.
_DENSE_EIGEN = 1500


@dataclass(frozen=True)
class LimitPoint:
    """A limit point of the path of ``lambda * forces`` and the derivative of its load.

    Attributes
    ----------
    load_factor : float
        lambda_c, the limit load as a multiple of the load pattern ``forces``.
    displacement : ndarray, shape (3N,)
        The state at the limit point [mm].
    mode : ndarray, shape (3N,)
        The critical mode phi: ``K_ff phi = 0``, of unit length, zero at the supports, its
        sign such that ``phi . f > 0`` (the direction in which the structure gives way
        under the load).
    load_alignment : float
        ``phi . f / |f|`` over the free DOFs, in (0, 1]: how directly the load drives the
        critical mode (0 at a bifurcation).
    parameters : tuple of str, length P
    load_factor_derivative : ndarray, shape (P,)
        d lambda_c / dp [per unit of each parameter]; the limit load's derivative is
        ``load_factor_derivative[j] * forces``.
    iterations : int
        Newton iterations on the extended system.
    """

    load_factor: float
    displacement: np.ndarray
    mode: np.ndarray
    load_alignment: float
    parameters: tuple
    load_factor_derivative: np.ndarray
    iterations: int


def limit_point(model, forces, near, parameters=(), *, load_factor=None, tolerance=1e-10,
                max_iterations=30) -> LimitPoint:
    """Locate the limit point of the path of ``lambda * forces`` next to a path or a state,
    and differentiate its load factor.

    The point is the solution of the extended system ``r_f(u) = lambda f_f``,
    ``K_ff(u) phi = 0``, ``l . phi = 1`` (``l`` the starting mode), solved by Newton's
    method from a nearby equilibrium: every iteration is exact but for the derivative of
    ``K_ff phi`` in u, a central difference of the tangent along phi over a millionth of the
    model's size (which makes the convergence linear with a ratio far below one). Then

        dlambda_c/dp = phi . (d f_int/dp)_f / (phi . f_f),

    in which phi's length and sign cancel: lambda_c grows with p where the internal force's
    change pushes back along the critical mode (``phi . d f_int/dp > 0``, phi taken with
    ``phi . f > 0``).

    Parameters
    ----------
    model : kresling.model.Model
    forces : array_like, shape (3N,) or (N, 3)
        The load pattern f [N] (its entries at supported DOFs do nothing).
    near : PathResult or array_like, shape (3N,)
        A force-controlled path (:func:`~kresling.solvers.solve_mgdcm`, which follows a
        path through its limit points, or :func:`~kresling.solvers.solve_force_control`):
        Newton starts from the step of its first critical point, where the load factor
        turns or the number of negative eigenvalues changes. Or an equilibrium
        under ``load_factor * forces`` near the limit point [mm].
    parameters : sequence of str, Parameter or Direction, length P
        What to differentiate by (a Direction's ``drive`` has no meaning under force
        control and is refused).
    load_factor : float
        The load factor of ``near`` when it is a state; not allowed with a path.
    tolerance : float
        Newton stops when its correction of the displacement is at most this [mm].
    max_iterations : int

    Returns
    -------
    LimitPoint

    Raises
    ------
    ValueError
        When the path has no limit point (its load factor never turns and its stability
        never changes); at a bifurcation (the critical mode orthogonal to the load,
        ``|phi . f| <= 1e-8 |phi| |f|``), where the load factor has no extremum to
        differentiate; when Newton does not converge (``near`` too far from the limit
        point); for a displacement-controlled path, or other bad input.
    """
    f = dof_vector(model, "forces", forces)
    free = model.free_dofs
    f_free = f[free]
    if not np.any(f_free):
        raise ValueError("forces is zero on every free DOF: there is no load to limit")
    tolerance = as_positive_real("tolerance", tolerance)
    max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
    parameters = tuple(parameters)
    for p in parameters:
        if isinstance(p, Direction) and p.drive is not None:
            raise ValueError(f"parameter {p.label!r} has a drive: a prescribed motion has no "
                             "place in a load-controlled limit point (give its positions and "
                             "columns alone)")
    u, lam = _start(model, near, load_factor)
    u, lam, phi, iterations = _extended_newton(model, f_free, u, lam, tolerance,
                                               max_iterations)
    mode = np.zeros(model.num_dofs)
    mode[free] = phi
    dforce, _, labels = residual_derivative(model, u, parameters)
    alignment = float(phi @ f_free)
    return LimitPoint(load_factor=float(lam), displacement=u, mode=mode,
                      load_alignment=alignment / float(np.linalg.norm(f_free)),
                      parameters=labels,
                      load_factor_derivative=(phi @ dforce[free]) / alignment,
                      iterations=iterations)


def _extended_newton(model, f_free, u, lam, tolerance, max_iterations):
    """Newton on the extended system from (u, lam): the limit point's state (3N,), load
    factor, unit mode over the free DOFs (phi . f > 0) and the iterations taken."""
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    free = model.free_dofs
    nf = len(free)
    size = float(np.linalg.norm(np.ptp(np.asarray(model.nodes), axis=0)))
    h = 1e-6 * size  # the step of the tangent's difference along the unit mode [mm]
    workspace = Workspace(model)

    def tangent(state):
        try:
            evaluated = assemble(model, state, workspace=workspace)
        except ValueError as error:
            raise ValueError(f"Newton on the extended system diverged: {error}") from None
        return evaluated.force, evaluated.stiffness[free][:, free].tocsc()

    force, K = tangent(u)
    phi = _nearest_null_vector(K, spla)
    phi = phi if phi @ f_free >= 0 else -phi
    _refuse_bifurcation(phi, f_free, "at the starting state")
    l = phi.copy()
    along = np.zeros(model.num_dofs)
    for iterations in range(1, max_iterations + 1):
        # d(K_ff phi)/du is the energy's third derivative along phi, symmetric: the
        # derivative of K_ff along phi, differenced.
        unit = np.linalg.norm(phi)
        along[free] = phi / unit
        _, K_plus = tangent(u + h * along)
        _, K_minus = tangent(u - h * along)
        H = (K_plus - K_minus) * (unit / (2 * h))
        J = sp.bmat([[K, None, sp.csc_matrix(-f_free.reshape(-1, 1))],
                     [H, K, None],
                     [None, sp.csr_matrix(l.reshape(1, -1)), None]], format="csc")
        G = np.concatenate([force[free] - lam * f_free, K @ phi, [l @ phi - 1.0]])
        try:
            step = spla.splu(J).solve(-G)
        except RuntimeError:
            raise ValueError(_bifurcation_or(phi, f_free, "the extended system is singular "
                                             f"at Newton iteration {iterations}")) from None
        if not np.all(np.isfinite(step)):
            raise ValueError(_bifurcation_or(phi, f_free, "the extended system gave a "
                                             f"non-finite correction at iteration {iterations}"))
        du = step[:nf]
        u = u.copy()
        u[free] += du
        phi = phi + step[nf:2 * nf]
        lam += step[-1]
        force, K = tangent(u)
        if np.abs(du).max() <= tolerance:
            phi = phi / np.linalg.norm(phi)
            _refuse_bifurcation(phi, f_free, "where Newton converged")
            return u, lam, phi, iterations
    raise ValueError(_bifurcation_or(phi, f_free, f"Newton on the extended system did not "
                                     f"converge in {max_iterations} iterations (last "
                                     f"correction {np.abs(du).max():.3g} mm > tolerance "
                                     f"{tolerance:g} mm): start nearer the limit point"))


def _start(model, near, load_factor):
    """The state (3N,) and load factor Newton starts from."""
    if isinstance(near, PathResult):
        if load_factor is not None:
            raise ValueError(f"load_factor = {load_factor!r} is given with a path: the path's "
                             "steps carry their own (give it with a state only)")
        supports = set(np.flatnonzero(np.asarray(model.fixed).ravel()).tolist())
        if not all(int(d) in supports for d in near.constraint_dofs):
            raise ValueError("near is a displacement-controlled path (its constraint DOFs are "
                             "imposed, not supported): its load factor is the drive's "
                             "fraction; give a force-controlled path of these forces")
        k = _first_critical_step(near)
        return np.array(near.displacement[k], dtype=float), float(near.load_factor[k])
    if load_factor is None:
        raise ValueError("load_factor is required when near is a state: the multiple of "
                         "forces it is in equilibrium under")
    return dof_vector(model, "near", near).copy(), as_finite_real("load_factor", load_factor)


def _first_critical_step(path) -> int:
    """The step nearest the first critical point along a path: the extremum of the load
    factor where it first turns, or the step before the negative eigenvalues' count first
    changes, whichever comes first."""
    lam = np.asarray(path.load_factor, dtype=float)
    count = np.asarray(path.negative_eigenvalues)
    for k in range(len(lam) - 1):
        if k >= 1 and (lam[k] - lam[k - 1]) * (lam[k + 1] - lam[k]) < 0:
            return k
        if count[k] >= 0 and count[k + 1] >= 0 and count[k] != count[k + 1]:
            return k if abs(lam[k]) >= abs(lam[k + 1]) else k + 1
    raise ValueError(f"the path has no limit point: over its {len(lam)} steps its load factor "
                     "never turns and its number of negative eigenvalues never changes "
                     "(follow it past the limit with solve_mgdcm, or pass a state near it)")


def _nearest_null_vector(K, spla):
    """The unit eigenvector of K (symmetric) whose eigenvalue is nearest zero."""
    if K.shape[0] <= _DENSE_EIGEN:
        values, vectors = np.linalg.eigh(K.toarray())
        return vectors[:, int(np.argmin(np.abs(values)))]
    _, vectors = spla.eigsh(K, k=1, sigma=0.0, which="LM")
    return vectors[:, 0] / np.linalg.norm(vectors[:, 0])


def _alignment(phi, f_free) -> float:
    return float(abs(phi @ f_free) / (np.linalg.norm(phi) * np.linalg.norm(f_free)))


def _bifurcation(alignment, where) -> str:
    return (f"the critical point is a bifurcation, not a limit point: {where} the critical "
            f"mode is orthogonal to forces (|phi . f| = {alignment:.3g} |phi| |f| <= "
            f"{BIFURCATION:g}), so the load factor has no extremum there to differentiate")


def _refuse_bifurcation(phi, f_free, where):
    alignment = _alignment(phi, f_free)
    if alignment <= BIFURCATION:
        raise ValueError(_bifurcation(alignment, where))


def _bifurcation_or(phi, f_free, message) -> str:
    """A bifurcation's refusal if the last iterate's mode is orthogonal to the load, else
    ``message``."""
    alignment = _alignment(phi, f_free)
    return _bifurcation(alignment, "near the last iterate") if alignment <= BIFURCATION \
        else message
