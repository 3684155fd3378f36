"""The linearised (infinitesimal) bar-and-hinge model (Schenk and Guest; thesis Appendix A)."""

from __future__ import annotations

import numpy as np

from kresling import _core
from kresling._validation import as_integer, show
from kresling.assembly import displacement_vector


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
    if isinstance(dofs, (str, bytes)) or not hasattr(dofs, "__iter__"):
        raise ValueError(f"dofs = {show(dofs)} is invalid: must be a sequence of DOF indices")
    dofs = [as_integer(f"dofs[{k}]", d, minimum=0, maximum=model.num_dofs - 1)
            for k, d in enumerate(dofs)]
    S, singular = _core.solvers.condensed_stiffness(model._core, displacement_vector(model, u), dofs)
    if singular:
        raise ValueError("condensed_stiffness: the free DOFs form a mechanism (K_ff is "
                         "singular); add supports")
    return np.asarray(S)
