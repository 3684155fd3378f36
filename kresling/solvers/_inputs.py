"""Shared checks of solver inputs."""

from __future__ import annotations

import numpy as np


def dof_vector(model, name, value, *, allow_none=False):
    """A per-DOF vector from an array of shape (3N,) or (N, 3); None -> empty (core's 'none')."""
    if value is None:
        if allow_none:
            return np.zeros(0)
        raise ValueError(f"{name} is required")
    array = np.asarray(value, dtype=float)
    if array.shape not in ((model.num_dofs,), (model.num_nodes, 3)):
        raise ValueError(f"{name} has shape {array.shape}: must be ({model.num_dofs},) or "
                         f"({model.num_nodes}, 3)")
    if not np.isfinite(array).all():
        raise ValueError(f"{name} contains NaN or inf")
    return np.ascontiguousarray(array.ravel())


def positive_int(name, value, minimum=1):
    if isinstance(value, bool) or int(value) != value or value < minimum:
        raise ValueError(f"{name} = {value!r} is invalid: must be an integer >= {minimum}")
    return int(value)


def positive_float(name, value):
    value = float(value)
    if not (np.isfinite(value) and value > 0):
        raise ValueError(f"{name} = {value!r} is invalid: must be a finite number > 0")
    return value
