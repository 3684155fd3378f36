"""The problem file's crease actuation (``[[actuation]]``) and elastic supports
(``[[spring]]``), read as :mod:`kresling.simulate.problem` reads every table: a ValueError
naming the file, the line, the table and the key for anything wrong."""

from __future__ import annotations

from dataclasses import dataclass

from kresling.model.crease_kinds import FOLD_FAMILIES

__all__ = ["Actuation", "Spring", "ACTUATION_FAMILIES", "read_actuations", "read_springs"]

#: The families an actuation may name: a fold family, or "fold" for every fold hinge.
ACTUATION_FAMILIES = FOLD_FAMILIES + ("join", "fold")


@dataclass(frozen=True)
class Actuation:
    """A group of creases driven together to a fold angle.

    Attributes
    ----------
    edges : tuple of (int, int), or None
        The creases by their two end vertices (0-based), or None with ``family``.
    family : str or None
        A whole family (:data:`ACTUATION_FAMILIES`).
    fold_angle_deg : float or None
        Target fold angle [deg], FOLD's convention (+ valley, - mountain, 0 flat); None:
        the pattern file's ``edges_foldAngle``.
    stage : int
        Stages fold one after another, 1 first.
    """

    edges: tuple | None
    family: str | None
    fold_angle_deg: float | None
    stage: int = 1


@dataclass(frozen=True)
class Spring:
    """A zero-length spring tying ``node`` to ``anchor`` [mm] with ``stiffness`` [N/mm] per
    axis (x, y, z)."""

    node: int
    stiffness: tuple
    anchor: tuple


def read_actuations(entries, table, number, integer, string, num_vertices):
    """The ``[[actuation]]`` entries; ``table(entry, i)`` makes the reader of entry i and
    ``number``, ``integer``, ``string`` read values as the problem reader does."""
    out = []
    for i, entry in enumerate(entries):
        t = table(entry, i)
        if t.has("edges") == t.has("family"):
            t.fail(None, f"(entry {i}) needs exactly one of 'edges' (creases by their end "
                         "vertices) or 'family' (one of " + ", ".join(ACTUATION_FAMILIES) + ")")
        edges = family = None
        if t.has("edges"):
            value = t.get("edges", lambda t_, k, v, a: v)
            if not isinstance(value, list) or not value:
                t.fail("edges", f"= {value!r} is invalid: must be a non-empty list of [u, v] "
                                "vertex pairs")
            pairs = []
            for pair in value:
                if not isinstance(pair, list) or len(pair) != 2:
                    t.fail("edges", f"has {pair!r}: each crease is a pair [u, v] of vertices")
                u, v = (integer(t, "edges", x) for x in pair)
                for x in (u, v):
                    if not 0 <= x < num_vertices:
                        t.fail("edges", f"has vertex {x}: out of range, the pattern's vertices "
                                        f"are 0 to {num_vertices - 1}")
                if u == v:
                    t.fail("edges", f"has [{u}, {v}]: a crease joins two different vertices")
                pairs.append((min(u, v), max(u, v)))
            edges = tuple(pairs)
        else:
            family = t.get("family", string, choices=ACTUATION_FAMILIES)
        if not t.has("fold_angle_deg"):
            t.fail("fold_angle_deg", "is missing: must be a target fold angle in [-180, 180] "
                                     "deg, or \"file\" for the pattern's edges_foldAngle")
        raw = t.get("fold_angle_deg", lambda t_, k, v, a: v)
        if raw == "file":
            angle = None
        else:
            if isinstance(raw, str):
                t.fail("fold_angle_deg", f"= {raw!r} is invalid: must be a number of degrees "
                                         "or \"file\"")
            angle = number(t, "fold_angle_deg", raw)
            if not -180.0 <= angle <= 180.0:
                t.fail("fold_angle_deg", f"= {angle!r} is invalid: must be in [-180, 180] deg "
                                         "(+ valley, - mountain)")
        stage = t.get("stage", integer, 1)
        if not 1 <= stage <= 1000:
            t.fail("stage", f"= {stage!r} is invalid: must be an integer in [1, 1000]")
        t.finish()
        out.append(Actuation(edges, family, angle, stage))
    return tuple(out)


def read_springs(entries, table, number, node_list, vector3):
    """The ``[[spring]]`` entries (each ``node`` or ``nodes``, ``stiffness`` [kx, ky, kz]
    N/mm >= 0 or one number for all three, ``anchor`` [x, y, z] mm, default: the node's own
    position, given as None here)."""
    out = []
    for i, entry in enumerate(entries):
        t = table(entry, i)
        nodes = node_list(t)
        value = t.get("stiffness", lambda t_, k, v, a: v, required=True,
                      allowed="[kx, ky, kz] N/mm, or one number for every axis")
        k = vector3(t, "stiffness", value) if isinstance(value, list) else \
            (number(t, "stiffness", value),) * 3
        if min(k) < 0:
            t.fail("stiffness", f"= {value!r} is invalid: must be >= 0 [N/mm]")
        anchor = t.get("anchor", vector3)
        t.finish()
        out.extend(Spring(node, tuple(k), anchor) for node in nodes)
    return tuple(out)
