"""``[[hinge]]``: rotational springs on the dihedral angle of any four nodes, with their own
stiffness, rest angle and law (members given one by one: a linkage's joints, a hinge whose
wings are not a panel's corners; see :class:`kresling.model.Members`).

Two conventions name the nodes and the rest angle (``convention``):

- ``"fold"`` (the default): ``nodes = [a, b, c, d]``, the axis ``a -> b`` and the wings ``c``
  and ``d``; ``rest_angle_deg`` is a fold angle in FOLD's convention, in [-180, 180]: 0 flat,
  positive a valley (as a crease's: the sign is read from the panel that holds ``a``, ``b``
  and ``d``, and for a hinge of no panel, fold angle = 180 - dihedral angle).
- ``"simfast"``: ``nodes = [i, j, k, l]`` as Sim-FAST's (and MERLIN2's) rotational springs
  order them, the axis ``j -> k`` and the wings ``i`` and ``l``; ``rest_angle_deg`` is the
  dihedral angle in [0, 360): 180 flat.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.laws import SPRING_LAWS
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import node_rows, number, raw, stiffnesses, string

__all__ = ["KEY", "MemberHinges", "HINGE_CONVENTIONS"]

#: The ``convention`` key's choices, and where each puts the axis and the wings in
#: ``nodes``: the order that makes them (a, b, c, d) (axis a -> b, wings c, d).
HINGE_CONVENTIONS = {"fold": (0, 1, 2, 3), "simfast": (1, 2, 0, 3)}


@dataclass(frozen=True)
class MemberHinges:
    """One ``[[hinge]]`` entry.

    Attributes
    ----------
    nodes : ndarray of int, shape (H, 4)
        ``(a, b, c, d)``: axis ``a -> b``, wings ``c``, ``d`` (whatever the convention).
    stiffness : float
        Moment per radian [N mm/rad] of each hinge.
    rest_angle_deg : ndarray, shape (H,), or None
        In the entry's ``convention`` [deg]; None: the angle as built (stress-free).
    convention : str
        ``"fold"`` or ``"simfast"`` (:data:`HINGE_CONVENTIONS`).
    law : str
        One of :data:`kresling.laws.SPRING_LAWS`.
    """

    nodes: np.ndarray
    stiffness: float
    rest_angle_deg: np.ndarray | None
    convention: str
    law: str


def read_hinges(entries, context) -> dict:
    """The ``[[hinge]]`` entries."""
    out = []
    for t in entries:
        convention = t.get("convention", string, "fold", choices=tuple(HINGE_CONVENTIONS))
        given = node_rows(t, "nodes", 4, context.num_nodes,
                          "a hinge: [a, b, c, d] (axis a -> b, wings c, d)"
                          if convention == "fold" else
                          "a hinge: [i, j, k, l] (Sim-FAST's order: axis j -> k, wings i, l)")
        nodes = given[:, list(HINGE_CONVENTIONS[convention])]
        stiffness = t.get("stiffness", stiffnesses, required=True,
                          allowed="the moment per radian [N mm/rad] (>= 0)")
        if isinstance(stiffness, np.ndarray):
            t.fail("stiffness", "must be one number [N mm/rad] (an entry per stiffness)")
        rest = _rest_angles(t, convention, len(nodes))
        law = t.get("law", string, "linear", choices=tuple(SPRING_LAWS))
        t.finish()
        out.append(MemberHinges(nodes, stiffness, rest, convention, law))
    return {"member_hinges": tuple(out)}


def _rest_angles(t, convention, count):
    """``rest_angle_deg``: a number for every hinge of the entry, one per hinge, or absent
    (the angles as built)."""
    value = t.get("rest_angle_deg", raw, None)
    if value is None:
        return None
    values = value if isinstance(value, list) else [value] * count
    if len(values) != count:
        t.fail("rest_angle_deg", f"has {len(values)} angles: must be one number or {count} "
                                 "(one per hinge)")
    angles = np.array([number(t, "rest_angle_deg", v) for v in values])
    low, high, words = ((-180.0, 180.0, "a fold angle in [-180, 180] deg (0 flat)")
                        if convention == "fold" else
                        (0.0, 360.0, "a dihedral angle in [0, 360) deg (180 flat)"))
    bad = (angles < low) | (angles > high) | ((angles == high) & (convention == "simfast"))
    if bad.any():
        t.fail("rest_angle_deg", f"has {angles[bad][0]!r}: must be {words}")
    return angles


KEY = ProblemKey("hinge", rank=31, read=read_hinges, array=True)
