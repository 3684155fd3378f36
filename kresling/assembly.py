"""Global internal force, tangent stiffness and energy of a model (C++ core).

A model is immutable; what assembling it needs besides the model - the tangent's sparsity
pattern and the slot map that says where each element's entries go - is a :class:`Workspace`.
:func:`assemble` builds one for its call unless it is given one: repeated evaluations (many
displacements, or many designs of one polygon size and cell count) pass the same workspace
and build the pattern once. The solvers keep theirs internally.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_bool, as_finite_real, as_float_array

__all__ = ["Assembly", "Workspace", "assemble", "tangent_stiffness"]


@dataclass(frozen=True)
class Assembly:
    """One evaluation of a model at a displacement.

    Attributes
    ----------
    energies : dict
        Stored energy of each element family of the model, by its name ("bars",
        "hinges", "cables", ...), in assembly order [N*mm].
    force : ndarray, shape (3N,)
        Internal force at every DOF [N] (the gradient of the energy).
    stiffness : scipy.sparse.csc_matrix, shape (3N, 3N) or None
        Symmetrised tangent (supports ignored) [N/mm], plus ``shift`` on the diagonal.
    """

    energies: dict
    force: np.ndarray
    stiffness: sp.csc_matrix | None

    @property
    def energy(self) -> float:
        """The total stored energy [N*mm] (the families' energies summed in order)."""
        return float(sum(self.energies.values(), 0.0))

    @property
    def energy_bars(self) -> float:
        """The bars' stored energy [N*mm]."""
        return self.energies["bars"]

    @property
    def energy_hinges(self) -> float:
        """The hinges' stored energy [N*mm]."""
        return self.energies["hinges"]


class Workspace:
    """The sparsity pattern and slot map of a model's tangent, reusable across evaluations.

    It serves the model it was built from and every model of the same connectivity (the
    same number of nodes and the same bars, hinges and cables, node for node, in order:
    e.g. every design of one polygon size and cell count); their geometry, areas,
    stiffnesses and laws may differ. It keeps no reference to a model. :func:`assemble`
    refuses it, with a ValueError, for a model of another connectivity. One workspace is
    not to be used by two threads at once.

    Parameters
    ----------
    model : kresling.model.Model

    Examples
    --------
    >>> from kresling import Design
    >>> from kresling.model import kresling_specimen
    >>> cell = kresling_specimen(Design(n=6, lam=0.8, Lc=20.0), [1]).model
    >>> other = kresling_specimen(Design(n=6, lam=0.7, Lc=25.0), [1]).model
    >>> w = Workspace(cell)
    >>> w.fits(other), assemble(other, workspace=w).energy
    (True, 0.0)
    """

    def __init__(self, model):
        self._core = _core.assembly.Workspace(_model_core(model))

    def fits(self, model) -> bool:
        """Whether ``model`` has the connectivity this workspace was built for."""
        return bool(self._core.fits(_model_core(model)))

    def __repr__(self):
        return f"Workspace({self._core.size} DOFs)"


def _model_core(model):
    core = getattr(model, "_core", None)
    if not isinstance(core, _core.model.Model):
        raise ValueError(f"model = {model!r} is invalid: must be a kresling.model.Model")
    return core


def displacement_vector(model, u):
    """``u`` as the model's flat vector of 3N displacements [mm] (zeros for None); a
    ValueError for another size."""
    if u is None:
        return np.zeros(model.num_dofs)
    u = as_float_array("u", u).ravel()
    if u.shape != (model.num_dofs,):
        raise ValueError(f"u has {u.size} entries: must have {model.num_dofs} (3 per node)")
    if not np.isfinite(u).all():
        raise ValueError("u contains NaN or inf")
    return u


def assemble(model, u=None, *, stiffness=True, shift=0.0, workspace=None) -> Assembly:
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
    workspace : Workspace, optional
        The pattern to assemble through (built for ``model`` or one of the same
        connectivity); by default one is built for this call. The values are the same
        either way, to the last bit.

    Raises
    ------
    ValueError
        For a ``u`` of the wrong size or with NaN, or one where the energy or force is not
        finite (a degenerate element, a hinge folded flat, an overflow): never a silent NaN;
        for a ``workspace`` that is not a :class:`Workspace` or was built for a model of
        another connectivity.
    """
    u = displacement_vector(model, u)
    if workspace is not None and not isinstance(workspace, Workspace):
        raise ValueError(f"workspace = {workspace!r} is invalid: must be a "
                         "kresling.assembly.Workspace or None")
    energies, force, K = _core.assembly.assemble(model._core, u, as_finite_real("shift", shift),
                                              as_bool("stiffness", stiffness),
                                              None if workspace is None else workspace._core)
    force = np.asarray(force)
    energies = dict(zip(model._core.families, np.asarray(energies).tolist()))
    if not (np.isfinite(list(energies.values())).all() and np.isfinite(force).all()):
        raise ValueError("u is invalid: the energy or the internal force is not finite there (an "
                         "element degenerated, a hinge folded flat, or the displacement is "
                         "beyond what a float holds)")
    matrix = None
    if K is not None:
        import scipy.sparse as sp  # here: a command that assembles no matrix needs no scipy

        data, indices, indptr, shape = K
        matrix = sp.csc_matrix((np.asarray(data), np.asarray(indices), np.asarray(indptr)),
                               shape=tuple(shape))
    return Assembly(energies, force, matrix)


def tangent_stiffness(model, u=None, *, shift=0.0) -> sp.csc_matrix:
    """Tangent stiffness (3N, 3N) at ``u`` [N/mm]; at a stress-free state it is the linear
    (Schenk-Guest) bar-and-hinge stiffness."""
    return assemble(model, u, stiffness=True, shift=shift).stiffness
