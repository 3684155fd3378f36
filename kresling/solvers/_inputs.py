"""Shared checks of solver inputs."""

from __future__ import annotations

import numpy as np

from kresling._validation import as_float_array


def dof_vector(model, name, value, *, allow_none=False):
    """A per-DOF vector from an array of shape (3N,) or (N, 3); None -> empty (core's 'none')."""
    if value is None:
        if allow_none:
            return np.zeros(0)
        raise ValueError(f"{name} is required")
    array = as_float_array(name, value)
    if array.shape not in ((model.num_dofs,), (model.num_nodes, 3)):
        raise ValueError(f"{name} has shape {array.shape}: must be ({model.num_dofs},) or "
                         f"({model.num_nodes}, 3)")
    if not np.isfinite(array).all():
        raise ValueError(f"{name} contains NaN or inf")
    return np.ascontiguousarray(array.ravel())


#: The tangent's Cholesky factorisations a solver can be told to use (index: the core's).
CHOLESKY_CHOICES = ("auto", "dense", "simplicial", "supernodal")


def cholesky_choice(value) -> int:
    """The core's index of a ``cholesky`` option, or a ValueError naming what is allowed."""
    if not isinstance(value, str) or value not in CHOLESKY_CHOICES:
        raise ValueError(f"cholesky = {value!r} is invalid: must be one of "
                         + ", ".join(repr(c) for c in CHOLESKY_CHOICES))
    return CHOLESKY_CHOICES.index(value)
