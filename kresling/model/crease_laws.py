"""The laws of a crease pattern's bars and of each family of its hinges."""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from kresling.laws import BAR_LAWS, SPRING_LAWS
from kresling.model.crease_kinds import FOLD_FAMILIES

__all__ = ["HingeLaw", "CreaseLaws"]


@dataclass(frozen=True)
class HingeLaw:
    """The law of a family of hinges.

    Parameters
    ----------
    law : str
        One of ``kresling.laws.SPRING_LAWS``: "enhanced_linear", "linear",
        "super_linear_bend".
    limits_deg : (float, float)
        Limits of the enhanced-linear law's linear range [deg], 0 < theta1 < theta2 < 360.
    stiffness : float, optional
        Stiffness per unit length [N*mm/rad/mm] for every hinge of the family, replacing the
        calibrated (or manual) one.
    """

    law: str = "enhanced_linear"
    limits_deg: tuple = (45.0, 315.0)
    stiffness: float | None = None

    def __post_init__(self):
        if self.law not in SPRING_LAWS:
            raise ValueError(f"law = {self.law!r} is invalid: must be one of {sorted(SPRING_LAWS)}")
        limits = tuple(float(x) for x in np.asarray(self.limits_deg, dtype=float).ravel())
        if len(limits) != 2 or not 0.0 < limits[0] < limits[1] < 360.0:
            raise ValueError(f"limits_deg = {list(self.limits_deg)!r} is invalid: must be two "
                             "angles 0 < theta1 < theta2 < 360 [deg]")
        object.__setattr__(self, "limits_deg", limits)
        if self.stiffness is not None and not (np.isfinite(self.stiffness) and self.stiffness >= 0):
            raise ValueError(f"stiffness = {self.stiffness!r} is invalid: must be a finite "
                             "number >= 0")


@dataclass(frozen=True)
class CreaseLaws:
    """Laws of the bars and of every hinge family.

    Parameters
    ----------
    bar : {"ogden", "linear"}
    fold : HingeLaw
        Every fold family without an entry in ``families``. Default: enhanced-linear with
        limits 45 and 315 deg (MERLIN2's).
    bend : HingeLaw, optional
        Bend hinges. Default: super-linear for a calibrated sheet, enhanced-linear 45/315
        for manual properties (MERLIN2's defaults).
    families : mapping of str to HingeLaw
        Per fold family ("mountain", "valley", "flat", "unassigned") overrides.
    """

    bar: str = "ogden"
    fold: HingeLaw = HingeLaw()
    bend: HingeLaw | None = None
    families: dict = field(default_factory=dict)

    def __post_init__(self):
        if self.bar not in BAR_LAWS:
            raise ValueError(f"bar = {self.bar!r} is invalid: must be one of {sorted(BAR_LAWS)}")
        unknown = sorted(set(self.families) - set(FOLD_FAMILIES))
        if unknown:
            raise ValueError(f"families: {unknown[0]!r} is not a fold family: must be one of "
                             f"{list(FOLD_FAMILIES)}")
        object.__setattr__(self, "families", MappingProxyType(dict(self.families)))

    def for_family(self, family: str, calibrated: bool) -> HingeLaw:
        if family == "bend":
            if self.bend is not None:
                return self.bend
            return HingeLaw("super_linear_bend") if calibrated else HingeLaw()
        return self.families.get(family, self.fold)
