"""Natural frequencies and mode shapes about an equilibrium (see docs/dynamics.md).

The free DOFs' tangent ``K`` at ``u`` and the lumped (diagonal) mass ``M`` give the
generalised eigenproblem ``K phi = omega^2 M phi``; its lowest ``k`` pairs are found by
scipy's Lanczos solver in shift-invert mode (``scipy.sparse.linalg.eigsh`` with ``sigma``),
which factorises ``K - sigma M`` once and so serves models of 100,000 DOFs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling._validation import as_float_array, as_integer
from kresling.assembly import assemble

__all__ = ["Modes", "vibration_modes", "RIGID_TOLERANCE"]

#: An eigenvalue omega^2 with ``|omega^2| < RIGID_TOLERANCE * trace(K) / trace(M)`` (the
#: mean eigenvalue) is a rigid-body or mechanism mode: round-off in the factorisation puts
#: zero eigenvalues at about 1e-16 of the largest, far below this.
RIGID_TOLERANCE = 1e-9


@dataclass(frozen=True)
class Modes:
    """The lowest vibration modes of a model about an equilibrium.

    Attributes
    ----------
    frequencies_hz : ndarray, shape (k,)
        Natural frequencies ``omega / (2 pi)`` [Hz], ascending; an unstable equilibrium's
        negative eigenvalue ``omega^2 < 0`` is given as ``-sqrt(-omega^2) / (2 pi)``.
    eigenvalues : ndarray, shape (k,)
        ``omega^2`` [1/s^2].
    shapes : ndarray, shape (k, 3N)
        Mode shapes, mass-normalised (``phi^T M phi = 1`` [1/t]), zero on supported DOFs.
    participation : ndarray, shape (k, 3)
        Participation factors ``phi^T M r`` along x, y, z [t^0.5] (``r``: a unit motion of
        every free DOF along that axis).
    effective_mass_fraction : ndarray, shape (k, 3)
        Effective mass of each mode along each axis over the free mass along it.
    rigid : ndarray of bool, shape (k,)
        Rigid-body or mechanism modes (near-zero eigenvalues, :data:`RIGID_TOLERANCE`).
    free_mass : ndarray, shape (3,)
        Mass on the free DOFs along x, y, z [t].
    """

    frequencies_hz: np.ndarray
    eigenvalues: np.ndarray
    shapes: np.ndarray
    participation: np.ndarray
    effective_mass_fraction: np.ndarray
    rigid: np.ndarray
    free_mass: np.ndarray

    @property
    def count(self) -> int:
        return len(self.frequencies_hz)


def _mass_diagonal(model, masses, free):
    m = as_float_array("masses", masses).ravel()
    if m.shape != (model.num_nodes,):
        raise ValueError(f"masses has {m.size} entries: must have {model.num_nodes} (one per "
                         "node) [t]")
    if not np.isfinite(m).all() or (m < 0).any():
        bad = int(np.flatnonzero(~np.isfinite(m) | (m < 0))[0])
        raise ValueError(f"masses[{bad}] = {m[bad]!r} is invalid: must be a finite mass >= 0 [t]")
    diagonal = np.repeat(m, 3)[free]
    massless = np.unique(free[diagonal == 0] // 3)
    if massless.size:
        # A free DOF without mass has no inertia: its equation is static, and M is singular.
        raise ValueError(f"masses are zero at free node(s) {massless[:10].tolist()}"
                         f"{' ...' if massless.size > 10 else ''}: every free DOF needs a "
                         "mass (give the nodes a [[mass]] or support them)")
    return diagonal


def vibration_modes(model, masses, k=10, u=None, *, sigma=None) -> Modes:
    """The ``k`` lowest natural frequencies and mode shapes about the state ``u``.

    Parameters
    ----------
    model : kresling.model.Model
        Supports (``model.fixed``) are removed from the problem.
    masses : array_like, shape (N,)
        Lumped node masses [t] (:func:`kresling.model.masses.lumped_masses`); every free
        node needs a mass > 0.
    k : int, default 10
        Number of modes; at most the free DOFs' count.
    u : array_like, shape (3N,) or (N, 3), optional
        The equilibrium the modes are about [mm] (the rest state, a loaded state, a point
        of a path); zero by default. Its tangent includes the stress stiffness. ``u`` must
        be an equilibrium of ``model`` as given: a fold's step is one of the model with its
        creases' rest angles there (:meth:`kresling.simulate.Simulation.model_at`;
        :func:`kresling.simulate.modes_at` does both).
    sigma : float, optional
        Shift of the shift-invert solve [1/s^2]; the modes nearest it are found. Default:
        ``-1e-8`` times the mean eigenvalue ``trace(K) / trace(M)``, just below zero, so
        ``K - sigma M`` is non-singular with rigid-body modes and the lowest are found.

    Returns
    -------
    Modes

    Raises
    ------
    ValueError
        For masses of the wrong size, negative, or zero at a free node (naming the nodes),
        ``k`` out of range, or a ``u`` the assembly refuses.
    """
    import scipy.linalg
    import scipy.sparse.linalg as sla

    free = np.asarray(model.free_dofs, dtype=np.int64)
    k = as_integer("k", k, minimum=1)
    if k > free.size:
        raise ValueError(f"k = {k} is invalid: the model has {free.size} free DOFs")
    diagonal = _mass_diagonal(model, masses, free)
    K = assemble(model, u).stiffness.tocsc()[free][:, free]
    K = ((K + K.T) * 0.5).tocsc()   # symmetric to the last bit for the Lanczos solver
    scale = K.diagonal().sum() / diagonal.sum()
    if k >= free.size - 1:   # all but one mode: ARPACK cannot, a dense solve can
        values, vectors = scipy.linalg.eigh(K.toarray(), np.diag(diagonal),
                                            subset_by_index=[0, k - 1])
    else:
        import scipy.sparse as sp

        shift = -1e-8 * scale if sigma is None else float(sigma)
        # A fixed start vector: the same modes, to the last bit, from run to run (ARPACK's
        # default start is random, which moves rigid modes' round-off values).
        start = np.random.default_rng(0).standard_normal(free.size)
        values, vectors = sla.eigsh(K, k=k, M=sp.diags(diagonal).tocsc(), sigma=shift,
                                    which="LM", v0=start)
    order = np.argsort(values)
    values, vectors = values[order], vectors[:, order]
    vectors = vectors / np.sqrt(np.einsum("ij,i,ij->j", vectors, diagonal, vectors))
    return _modes(model, free, diagonal, values, vectors, scale)


def _modes(model, free, diagonal, values, vectors, scale) -> Modes:
    shapes = np.zeros((len(values), model.num_dofs))
    shapes[:, free] = vectors.T
    axis = free % 3
    r = np.stack([(axis == a).astype(float) for a in range(3)], axis=1)   # (F, 3)
    free_mass = diagonal @ r
    participation = vectors.T @ (diagonal[:, None] * r)
    with np.errstate(invalid="ignore", divide="ignore"):
        fraction = np.where(free_mass > 0, participation ** 2 / free_mass, 0.0)
    frequencies = np.sign(values) * np.sqrt(np.abs(values)) / (2 * np.pi)
    return Modes(frequencies_hz=frequencies, eigenvalues=values, shapes=shapes,
                 participation=participation, effective_mass_fraction=fraction,
                 rigid=np.abs(values) < RIGID_TOLERANCE * scale, free_mass=free_mass)
