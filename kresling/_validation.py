"""Checks on user input shared by the Python API: messages name the parameter, the value
given and what is allowed, matching the C++ core's std::invalid_argument messages."""

from __future__ import annotations

import numbers

import numpy as np


def show(value) -> str:
    """A value as messages print it: numpy scalars as plain Python numbers."""
    if isinstance(value, np.generic):
        value = value.item()
    return repr(value)


def as_integer(name: str, value, minimum: int | None = None) -> int:
    """Return ``value`` as an ``int``, rejecting non-integral values and bools.

    Integral floats (``10.0``, as read from a CSV file) are accepted.
    """
    allowed = "an integer" + (f" >= {minimum}" if minimum is not None else "")
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} = {show(value)} is invalid: must be {allowed}")
    if not np.isfinite(value) or float(value) != int(value):
        raise ValueError(f"{name} = {show(value)} is invalid: must be {allowed}")
    result = int(value)
    if minimum is not None and result < minimum:
        raise ValueError(f"{name} = {result} is invalid: must be {allowed}")
    return result


def as_integer_array(name: str, values) -> np.ndarray:
    """Return ``values`` as an int32 array; every entry must be integral and finite."""
    array = np.asarray(values)
    if array.dtype == bool or not (np.issubdtype(array.dtype, np.number)):
        raise ValueError(f"{name} has dtype {array.dtype}: must be integers")
    if np.issubdtype(array.dtype, np.floating):
        bad = ~np.isfinite(array) | (array != np.round(array))
        if bad.any():
            index = tuple(int(i) for i in np.argwhere(bad)[0])
            where = ", ".join(str(i) for i in index)
            raise ValueError(f"{name}[{where}] = {show(array[index])} is invalid: must be an integer")
    if array.size and (array.max() > np.iinfo(np.int32).max or array.min() < np.iinfo(np.int32).min):
        raise ValueError(f"{name} has entries outside the 32-bit integer range")
    return array.astype(np.int32)


def as_positive_real(name: str, value) -> float:
    """Return ``value`` as a float that is finite and > 0 (a tolerance, a step size)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} = {show(value)} is invalid: must be a finite number > 0")
    value = float(value)
    if not (np.isfinite(value) and value > 0):
        raise ValueError(f"{name} = {value!r} is invalid: must be a finite number > 0")
    return value


def as_real(name: str, value) -> float:
    """Return ``value`` as a float; the core checks ranges and finiteness."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Real):
        raise ValueError(f"{name} = {show(value)} is invalid: must be a real number")
    return float(value)
