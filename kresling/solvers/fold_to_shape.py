"""Folding by gradient: the rest angles that fold a sheet so that chosen nodes reach target
positions.

The forward problem is a fold (:func:`~kresling.solvers.solve_fold`): hinges' rest angles
driven from the model's own to ``theta``, the sheet followed to its equilibrium ``u(theta)``.
The inverse problem is a nonlinear least-squares one,

    min_theta  1/2 sum_i |X_i + u_i(theta) - target_i|^2     over the chosen nodes i,

solved by SciPy's trust-region reflective least squares on the exact Jacobian
``du/dtheta`` (:func:`~kresling.solvers.equilibrium_sensitivity`: one factorisation of the
folded state's tangent and one solve per hinge). Every evaluation folds again from the
model's reference, so that each ``u(theta)`` is the equilibrium the fold reaches, on the
same branch as a forward fold.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling._validation import as_float_array, as_integer, as_positive_real
from kresling.solvers.fold import solve_fold
from kresling.solvers.path import PathResult
from kresling.solvers.sensitivity import Parameter, equilibrium_sensitivity, with_parameter

__all__ = ["ShapeFold", "fold_to_shape"]

#: Newton's tolerance of the folds [mm]: far below the shapes' precision, so that the
#: Jacobian is that of converged equilibria.
TOLERANCE = 1e-10


@dataclass(frozen=True)
class ShapeFold:
    """The rest angles found by :func:`fold_to_shape`.

    Attributes
    ----------
    rest_angles : ndarray, shape (K,)
        The hinges' rest angles [rad], in the order the hinges were given.
    path : PathResult
        The fold to them from the model's reference.
    positions : ndarray, shape (M, 3)
        Where the chosen nodes end [mm].
    error : ndarray, shape (M,)
        Their distance from the targets [mm].
    evaluations : int
        Folds computed (each with its Jacobian).
    success : bool
    message : str
    """

    rest_angles: np.ndarray
    path: PathResult
    positions: np.ndarray
    error: np.ndarray
    evaluations: int
    success: bool
    message: str

    @property
    def rms_error(self) -> float:
        """Root mean square of :attr:`error` [mm]."""
        return float(np.sqrt(np.mean(self.error ** 2)))


def fold_to_shape(model, hinges, nodes, targets, *, initial=None, steps=10, xtol=1e-12,
                  max_evaluations=100) -> ShapeFold:
    """The rest angles of ``hinges`` that fold ``model`` so that ``nodes`` reach ``targets``.

    Parameters
    ----------
    model : kresling.model.Model
        Held by its supports (a fold needs no rigid-body motion left free).
    hinges : array_like of int, shape (K,)
        The hinges whose rest angles are sought.
    nodes : array_like of int, shape (M,)
        The nodes whose positions are prescribed.
    targets : array_like, shape (M, 3)
        Their target positions [mm].
    initial : array_like, shape (K,), optional
        The first guess of the rest angles [rad, in (0, 2 pi)]; default the model's own.
    steps : int, default 10
        Increments of each fold (more for folds far from the reference).
    xtol : float, default 1e-12
        The least squares' tolerance on the change of the rest angles (relative).
    max_evaluations : int, default 100

    Returns
    -------
    ShapeFold

    Raises
    ------
    ValueError
        For hinges or nodes out of range, targets of the wrong shape, or a fold that does
        not complete (its rest angles are then out of the sheet's reach from the
        reference: the message names them).
    """
    from scipy.optimize import least_squares

    hinges = _indices("hinges", hinges, len(model.hinges))
    nodes = _indices("nodes", nodes, model.num_nodes)
    targets = as_float_array("targets", targets).reshape(-1, 3) if np.size(targets) else None
    if targets is None or targets.shape != (nodes.size, 3):
        raise ValueError(f"targets must have shape ({nodes.size}, 3): one position per node")
    steps = as_integer("steps", steps, minimum=1)
    xtol = as_positive_real("xtol", xtol)
    max_evaluations = as_integer("max_evaluations", max_evaluations, minimum=1)
    rest = np.asarray(model.hinge_rest_angle, dtype=float)
    theta0 = rest[hinges] if initial is None else as_float_array("initial", initial).ravel()
    if theta0.shape != hinges.shape:
        raise ValueError(f"initial has {theta0.size} entries: must have one per hinge "
                         f"({hinges.size})")
    dofs = (3 * nodes[:, None] + np.arange(3)).ravel()
    X = np.asarray(model.nodes, dtype=float)[nodes]
    parameters = [Parameter("hinges", "rest_angle", entry=int(h)) for h in hinges]
    cache = {}

    def folded(theta):
        key = theta.tobytes()
        if key not in cache:
            path = solve_fold(model, [(hinges, theta)], steps, tolerance=TOLERANCE,
                              extrapolation=2, shift=0.0)
            if not path.completed:
                raise ValueError(f"the fold to rest angles {np.round(theta, 6).tolist()} did not "
                                 f"complete ({path.message})")
            u = path.displacement[-1]
            values = rest.copy()
            values[hinges] = theta
            sens = equilibrium_sensitivity(with_parameter(model, "hinges.rest_angle", values),
                                           u, parameters)
            cache.clear()  # least_squares asks for the residual, then the Jacobian, of one point
            cache[key] = (path, u[dofs].reshape(-1, 3) + X, sens.displacement[dofs])
        return cache[key]

    def residual(theta):
        return (folded(theta)[1] - targets).ravel()

    def jacobian(theta):
        return folded(theta)[2]

    result = least_squares(residual, theta0, jac=jacobian, method="trf", xtol=xtol,
                           ftol=1e-15, gtol=1e-15, max_nfev=max_evaluations,
                           bounds=(1e-9, 2 * np.pi - 1e-9))
    path, positions, _ = folded(result.x)
    error = np.linalg.norm(positions - targets, axis=1)
    return ShapeFold(rest_angles=result.x, path=path, positions=positions, error=error,
                     evaluations=int(result.nfev), success=bool(result.success),
                     message=str(result.message))


def _indices(name, values, size) -> np.ndarray:
    values = np.asarray(values)
    if values.size == 0 or not np.issubdtype(values.dtype, np.integer):
        raise ValueError(f"{name} must be a non-empty list of integer indices")
    values = values.astype(np.int64).ravel()
    if values.min() < 0 or values.max() >= size or len(set(values.tolist())) != values.size:
        raise ValueError(f"{name} = {values.tolist()} is invalid: must be distinct indices in "
                         f"[0, {size})")
    return values
