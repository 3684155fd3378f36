"""Checks on fabrication parameters; messages name the parameter, the value and what is allowed."""

from __future__ import annotations

import math
import numbers

from kresling._validation import show


def _real(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        raise ValueError(f"{name} = {show(value)} is invalid: must be a finite number")
    return float(value)


def positive(name: str, value) -> float:
    """``value`` as a float; it must be finite and > 0 (a length in mm)."""
    if _real(name, value) <= 0.0:
        raise ValueError(f"{name} = {show(value)} is invalid: must be > 0 (mm)")
    return float(value)


def non_negative(name: str, value) -> float:
    """``value`` as a float; it must be finite and >= 0 (a length in mm)."""
    if _real(name, value) < 0.0:
        raise ValueError(f"{name} = {show(value)} is invalid: must be >= 0 (mm)")
    return float(value)
