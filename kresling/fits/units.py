"""Units of the columns of laboratory records: parsing them from headers and converting to
the package's units (mm, N, s, rad; crease stiffness in N/rad, bending stiffness in N*m/rad).

A header carries its unit in one of three spellings: ``force (N)``, ``force [N]`` or
``force_N``; ``_per_`` reads as ``/`` (``stiffness_N_per_rad`` is ``N/rad``).
"""

from __future__ import annotations

import math
import re

__all__ = ["CANONICAL", "conversion_factor", "normalize_unit", "split_header"]

# Factor from each accepted spelling to the canonical unit of its dimension.
_FACTORS = {
    "length": {"mm": 1.0, "cm": 10.0, "m": 1000.0, "um": 1e-3, "µm": 1e-3, "in": 25.4},
    "force": {"N": 1.0, "mN": 1e-3, "kN": 1e3, "lbf": 4.4482216152605},
    "time": {"s": 1.0, "ms": 1e-3, "min": 60.0},
    "angle": {"rad": 1.0, "deg": math.pi / 180.0},
    # Marker coordinates: eqn 17 only uses ratios of distances, so pixels and lengths are
    # equally good as long as one run uses one unit (the crease reader checks that).
    "image": {"px": 1.0, "pixel": 1.0, "pixels": 1.0, "mm": 1.0, "cm": 1.0, "m": 1.0},
    # Crease stiffness per unit crease length: N*mm/(rad*mm) = N/rad.
    "crease stiffness": {"N/rad": 1.0, "mN/rad": 1e-3, "N*mm/rad/mm": 1.0, "N*m/rad/m": 1.0},
    "bending stiffness": {"N*m/rad": 1.0, "Nm/rad": 1.0, "N*mm/rad": 1e-3, "Nmm/rad": 1e-3},
}

#: The unit every value of a dimension is converted to.
CANONICAL = {
    "length": "mm", "force": "N", "time": "s", "angle": "rad", "image": "(as recorded)",
    "crease stiffness": "N/rad", "bending stiffness": "N*m/rad",
}

_BRACKETED = re.compile(r"^(?P<name>.*?)\s*[\(\[]\s*(?P<unit>[^\)\]]*?)\s*[\)\]]$")


def normalize_unit(text: str) -> str:
    """Canonical spelling of a unit as written in a header.

    ``"N_per_rad"`` -> ``"N/rad"``, ``"N·m/rad"`` -> ``"N*m/rad"``, ``" mm "`` -> ``"mm"``.
    Case is kept: ``mN`` and ``MN`` are different units.
    """
    unit = text.strip().replace("_per_", "/").replace("·", "*").replace(" ", "")
    return unit


def split_header(header: str, names) -> tuple[str, str | None] | None:
    """Match a header against accepted column names and split off its unit.

    Parameters
    ----------
    header : str
        A header cell, e.g. ``"Load (lbf)"`` or ``"force_N"``.
    names : sequence of str
        Accepted names of the column (compared case-insensitively).

    Returns
    -------
    (name, unit) or None
        The matched name as written in ``names`` and the unit (None when the header has no
        unit); None when the header is not this column.
    """
    text = header.strip()
    bracketed = _BRACKETED.match(text)
    for name in names:
        if text.lower() == name.lower():
            return name, None
        if bracketed and bracketed.group("name").lower() == name.lower():
            return name, normalize_unit(bracketed.group("unit"))
        prefix = name.lower() + "_"
        if text.lower().startswith(prefix) and len(text) > len(prefix):
            return name, normalize_unit(text[len(prefix):])
    return None


def conversion_factor(unit: str, dimension: str) -> float:
    """Factor converting values in ``unit`` to the canonical unit of ``dimension``.

    Raises
    ------
    ValueError
        If ``unit`` is not a unit of ``dimension``; the message lists the accepted ones.
    """
    accepted = _FACTORS[dimension]
    if unit not in accepted:
        raise ValueError(f"unit {unit!r} is not a {dimension} unit; "
                         f"accepted: {', '.join(accepted)}")
    return accepted[unit]
