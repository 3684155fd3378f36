"""The problem file's ``[contact]`` table: rigid planes the pattern's nodes may not pass,
and panels that may not pass through each other (``self = true``), read as
:mod:`kresling.simulate.problem` reads every table."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Contact", "read_contact", "auto_barrier_stiffness", "TANGENTS"]

#: The ``tangent`` key's choices, in the order of the self-contact family's ``tangent``
#: column codes (0, 1, 2).
TANGENTS = ("projected", "exact", "adaptive")


@dataclass(frozen=True)
class Contact:
    """``distance``: d_hat [mm], the gap below which the barrier acts; ``stiffness``: kappa
    [N/mm^3] or None for "auto"; ``planes``: tuples (point, normal), possibly none;
    ``self_contact``: whether panels are kept off each other; ``tangent``: how the panel
    pairs' Hessians enter Newton's tangent: ``"projected"`` onto the positive semi-definite
    cone, ``"exact"``, or ``"adaptive"`` (exact where the whole tangent is positive
    definite, projected at the iterates where it is not)."""

    distance: float
    stiffness: float | None
    planes: tuple
    self_contact: bool = False
    tangent: str = "adaptive"


def read_contact(t, number, positive, boolean, vector3, string):
    """The ``[contact]`` table ``t`` (a reader of the problem's tables)."""
    distance = t.get("distance", positive, required=True,
                     allowed="d_hat [mm]: the barrier acts at gaps below it")
    raw = t.get("stiffness", lambda t_, k, v, a: v, "auto")
    stiffness = None if raw == "auto" else positive(t, "stiffness", raw)
    self_contact = t.get("self", boolean, False)
    tangent = t.get("tangent", string, "adaptive", choices=TANGENTS)
    planes = t.get("planes", lambda t_, k, v, a: v, [], required=not self_contact,
                   allowed="an array of { point = [x, y, z], normal = [nx, ny, nz] }")
    if not isinstance(planes, list) or not (planes or self_contact):
        t.fail("planes", f"= {planes!r} is invalid: must be a non-empty array of "
                         "{ point = [x, y, z], normal = [nx, ny, nz] } (or set self = true "
                         "for contact between panels alone)")
    out = []
    for plane in planes:
        if not isinstance(plane, dict) or set(plane) != {"point", "normal"}:
            t.fail("planes", f"has {plane!r}: each plane is {{ point = [x, y, z], normal = "
                             "[nx, ny, nz] }")
        point, normal = vector3(t, "planes", plane["point"]), vector3(t, "planes", plane["normal"])
        if not np.linalg.norm(normal) > 0:
            t.fail("planes", f"has normal {list(normal)}: must not be zero")
        out.append((point, normal))
    t.finish()
    return Contact(distance, stiffness, tuple(out), bool(self_contact), tangent)


def _barrier_curvature(d_hat: float) -> float:
    """d^2/dd^2 of b(d^2) = -(d^2 - d_hat^2)^2 ln(d^2 / d_hat^2) at d = d_hat / 2 [mm^2]."""
    s_hat = d_hat ** 2
    s = s_hat / 4
    db = -2 * (s - s_hat) * np.log(s / s_hat) - (s - s_hat) ** 2 / s
    d2b = -2 * np.log(s / s_hat) - 4 * (s - s_hat) / s + (s - s_hat) ** 2 / s ** 2
    return d2b * 4 * s + 2 * db


def auto_barrier_stiffness(diagonal_stiffness: float, d_hat: float) -> float:
    """The "auto" kappa [N/mm^3]: the barrier's stiffness at half the distance d_hat equals
    the structure's mean diagonal stiffness (``diagonal_stiffness`` [N/mm])."""
    return diagonal_stiffness / _barrier_curvature(d_hat)
