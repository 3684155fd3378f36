"""The linearised (infinitesimal) bar-and-hinge model (Schenk and Guest; thesis Appendix A)."""

from __future__ import annotations

import numpy as np

from kresling import _core
from kresling.assembly import _displacement


def condensed_stiffness(model, dofs, u=None) -> np.ndarray:
    """Stiffness seen at ``dofs`` with the supports held and every other DOF free.

    ``S = K_pp - K_pf K_ff^-1 K_fp`` of the tangent at ``u`` (the linear model when ``u`` is a
    stress-free state): ``S @ u_p`` is the force needed to impose ``u_p`` on ``dofs``.

    Parameters
    ----------
    model : kresling.model.Model
    dofs : sequence of int
        Distinct, unsupported DOFs.
    u : array_like, shape (3N,), optional
        State to linearise about (default: the reference state).

    Returns
    -------
    ndarray, shape (len(dofs), len(dofs))
        [N/mm].

    Raises
    ------
    ValueError
        For bad DOFs, or when the free part is singular (a mechanism the supports allow).
    """
    dofs = [int(d) for d in dofs]
    S, singular = _core.solvers.condensed_stiffness(model._core, _displacement(model, u), dofs)
    if singular:
        raise ValueError("condensed_stiffness: the free DOFs form a mechanism (K_ff is "
                         "singular); add supports")
    return np.asarray(S)
