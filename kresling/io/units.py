"""Length units of pattern files, converted to the package's millimetres.

FOLD's ``frame_unit`` names the unit of a file's coordinates (``"unit"``, the default, has
no physical meaning); a problem file's ``[pattern] unit`` and ``scale`` may override it.
Every pattern is converted to mm when it is read, so the rest of the package works in mm.
"""

from __future__ import annotations

import math

__all__ = ["UNITS", "mm_per_unit"]

#: Millimetres per unit of each FOLD ``frame_unit`` (FOLD specification 1.2), ``"unit"``
#: (no physical meaning) taken as 1 mm unless a scale says otherwise.
UNITS = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "pt": 25.4 / 72.0, "um": 1e-3,
         "nm": 1e-6, "unit": 1.0}


def mm_per_unit(unit: str, scale=None, *, name: str = "unit") -> float:
    """Millimetres per unit of a pattern's coordinates.

    Parameters
    ----------
    unit : str
        One of :data:`UNITS`.
    scale : float, optional
        With ``unit="unit"`` only: millimetres per unit (default 1).
    name : str
        The parameter's name in messages.

    Returns
    -------
    float
        The factor from the file's coordinates to mm (> 0).

    Raises
    ------
    ValueError
        An unknown unit, a scale with a physical unit, or a scale that is not a finite
        number > 0.
    """
    if not isinstance(unit, str) or unit not in UNITS:
        raise ValueError(f"{name} = {unit!r} is invalid: must be one of {list(UNITS)}")
    if scale is None:
        return UNITS[unit]
    if unit != "unit":
        raise ValueError(f"scale = {scale!r} is invalid with {name} = {unit!r}: a scale [mm "
                         "per unit] applies only to unit = 'unit' (coordinates without a "
                         "physical unit)")
    if isinstance(scale, bool) or not isinstance(scale, (int, float)) or \
            not math.isfinite(scale) or scale <= 0:
        raise ValueError(f"scale = {scale!r} is invalid: must be a finite number > 0 (mm per "
                         "unit)")
    return float(scale)
