"""Global internal force, tangent stiffness and energy of a model (C++ core).

The C++ assembler builds the sparsity pattern and slot map once and refills values; this
module exposes one evaluation at a time, e.g. for checks, linear analyses and plotting.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from kresling import _core
from kresling._validation import as_bool, as_finite_real, as_float_array

__all__ = ["Assembly", "assemble", "tangent_stiffness"]


@dataclass(frozen=True)
class Assembly:
    """One evaluation of a model at a displacement.

    Attributes
    ----------
    energy_bars, energy_hinges : float
        Stored energy by element family [N*mm].
    force : ndarray, shape (3N,)
        Internal force at every DOF [N] (the gradient of the energy).
    stiffness : scipy.sparse.csc_matrix, shape (3N, 3N) or None
        Symmetrised tangent (supports ignored) [N/mm], plus ``shift`` on the diagonal.
    """

    energy_bars: float
    energy_hinges: float
    force: np.ndarray
    stiffness: sp.csc_matrix | None

    @property
    def energy(self) -> float:
        return self.energy_bars + self.energy_hinges


def _displacement(model, u):
    if u is None:
        return np.zeros(model.num_dofs)
    u = as_float_array("u", u).ravel()
    if u.shape != (model.num_dofs,):
        raise ValueError(f"u has {u.size} entries: must have {model.num_dofs} (3 per node)")
    if not np.isfinite(u).all():
        raise ValueError("u contains NaN or inf")
    return u


def assemble(model, u=None, *, stiffness=True, shift=0.0) -> Assembly:
    """Evaluate energy, internal force and (optionally) the tangent at displacement ``u``.

    Parameters
    ----------
    model : kresling.model.Model
    u : array_like, shape (3N,) or (N, 3), optional
        Displacement [mm]; zero by default.
    stiffness : bool, default True
        Also assemble the tangent.
    shift : float, default 0
        Added to the tangent's diagonal (MERLIN2's solvers use 1e-8).

    Raises
    ------
    ValueError
        For a ``u`` of the wrong size or with NaN, or one where the energy or force is not
        finite (a degenerate element, a hinge folded flat, an overflow): never a silent NaN.
    """
    u = _displacement(model, u)
    eb, eh, force, K = _core.assembly.assemble(model._core, u, as_finite_real("shift", shift),
                                              as_bool("stiffness", stiffness))
    force = np.asarray(force)
    if not (np.isfinite(eb) and np.isfinite(eh) and np.isfinite(force).all()):
        raise ValueError("u is invalid: the energy or the internal force is not finite there (an "
                         "element degenerated, a hinge folded flat, or the displacement is "
                         "beyond what a float holds)")
    matrix = None
    if K is not None:
        data, indices, indptr, shape = K
        matrix = sp.csc_matrix((np.asarray(data), np.asarray(indices), np.asarray(indptr)),
                               shape=tuple(shape))
    return Assembly(eb, eh, force, matrix)


def tangent_stiffness(model, u=None, *, shift=0.0) -> sp.csc_matrix:
    """Tangent stiffness (3N, 3N) at ``u`` [N/mm]; at a stress-free state it is the linear
    (Schenk-Guest) bar-and-hinge stiffness."""
    return assemble(model, u, stiffness=True, shift=shift).stiffness
