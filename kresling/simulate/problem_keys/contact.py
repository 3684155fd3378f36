"""``[contact]``: rigid planes the pattern's nodes may not pass, and panels that may not
pass through each other (``self = true``), the panels optionally of a thickness: the model's
``contact`` and ``self_contact`` families, and history.csv's ``min_gap`` and the planes'
reaction."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import (boolean, in_range, number, positive, raw, string,
                                             vector3)

__all__ = ["KEY", "Contact", "auto_barrier_stiffness", "TANGENTS"]

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
    definite, projected at the iterates where it is not); ``thickness``: t [mm], the panels'
    thickness: their mid-surfaces are kept at least t apart and t/2 off the planes, d_hat
    measured from the faces (0: the mid-surfaces themselves)."""

    distance: float
    stiffness: float | None
    planes: tuple
    self_contact: bool = False
    tangent: str = "adaptive"
    thickness: float = 0.0


def read_contact(t, context) -> dict:
    """The ``[contact]`` table."""
    distance = t.get("distance", positive, required=True,
                     allowed="d_hat [mm]: the barrier acts at gaps below it")
    given = t.get("stiffness", raw, "auto")
    stiffness = None if given == "auto" else positive(t, "stiffness", given)
    self_contact = t.get("self", boolean, False)
    tangent = t.get("tangent", string, "adaptive", choices=TANGENTS)
    thickness = t.get("thickness", _thickness, 0.0)
    planes = t.get("planes", raw, [], required=not self_contact,
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
    return {"contact": Contact(distance, stiffness, tuple(out), bool(self_contact), tangent,
                               thickness)}


def _thickness(t, key, value, allowed=None):
    """The panels' thickness [mm]: a finite number >= 0."""
    value = number(t, key, value)
    if value < 0:
        t.fail(key, f"= {value!r} is invalid: must be >= 0 [mm] (0: panels without thickness)")
    return in_range(t, key, value, zero=True)


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


def _barrier_stiffness(problem, model) -> float:
    """kappa [N/mm^3] of ``[contact]``: its number, or "auto" from the model's mean diagonal
    stiffness at rest (docs/simulate.md, '[contact]')."""
    from kresling.assembly import assemble

    contact = problem.contact
    if contact.stiffness is not None:
        return contact.stiffness
    diagonal = assemble(model).stiffness.diagonal()[~model.fixed.ravel()]
    return auto_barrier_stiffness(float(np.mean(diagonal)), contact.distance)


def _contact_table(problem, model) -> dict:
    """The contact family's columns: every node against every plane."""
    contact = problem.contact
    return {"nodes": np.arange(model.num_nodes, dtype=np.int64),
            "origin": np.array([p for p, _ in contact.planes], dtype=float),
            "normal": np.array([n for _, n in contact.planes], dtype=float),
            "distance": np.array([contact.distance]),
            "stiffness": np.array([_barrier_stiffness(problem, model)]),
            **_thickness_column(contact)}


def _self_contact_table(problem, pm) -> dict:
    """The self-contact family's columns: the pattern's triangles (N5B8 centre nodes
    included), kept off each other."""
    table = {"triangles": np.asarray(pm.elements.triangles, dtype=np.int64),
             "distance": np.array([problem.contact.distance]),
             "stiffness": np.array([_barrier_stiffness(problem, pm.model)]),
             **_thickness_column(problem.contact)}
    if problem.contact.tangent != "adaptive":
        table["tangent"] = np.array([float(TANGENTS.index(problem.contact.tangent))])
    joined = _joined_at_rest(pm.model.nodes)
    if joined is not None:
        table["joined"] = joined
    return table


def _thickness_column(contact) -> dict:
    """The families' ``thickness`` column: none for panels without thickness (the families'
    default), so that their tables are those of a problem without the key."""
    return {"thickness": np.array([contact.thickness])} if contact.thickness > 0 else {}


def _check_thickness(problem, pm):
    """Refuse a thickness no smaller than a panel: the shortest edge of the pattern's
    triangles at rest [mm]. (A thickness two panels are closer than at rest is refused by
    the self-contact family, which measures their distances.)"""
    thickness = problem.contact.thickness
    if thickness == 0:
        return
    nodes, triangles = pm.model.nodes, np.asarray(pm.elements.triangles)
    edges = nodes[np.roll(triangles, -1, axis=1)] - nodes[triangles]
    shortest = float(np.linalg.norm(edges, axis=2).min())
    if thickness >= shortest:
        raise ValueError(f"{problem.source}: [contact] key 'thickness' = {thickness:g} mm is "
                         f"invalid: must be below the size of every panel, here the shortest "
                         f"edge of its triangles at rest, {shortest:.6g} mm")


def _joined_at_rest(nodes):
    """Each node's representative among the nodes at its place at rest (the two sides of
    a cut, separated into copies of its vertices), or None where no two coincide: the
    contact barrier counts them as one node, so that a cut is not a contact."""
    from kresling.io.cuts import DUPLICATE_TOLERANCE
    from kresling.io.planar_graph import merge_points

    # "At one place" as a pattern's own vertices are judged (kresling.io.cuts).
    size = float(np.linalg.norm(np.ptp(nodes, axis=0)))
    joined = merge_points(nodes, DUPLICATE_TOLERANCE * size).astype(np.int64)
    return joined if np.any(joined != np.arange(len(nodes))) else None


def _contact_columns(model, path) -> dict:
    """The contact columns of ``history.csv`` along ``path``: ``min_gap`` [mm] (with planes
    or panel contact: the smallest gap between two panels' faces or a panel's face and a
    plane, the mid-surfaces' distance less the thickness t, a node's distance from a plane
    less t / 2) and, with planes, ``reaction_planes_x/y/z`` [N], the planes' force on
    the model (the barrier's force on its nodes, summed over every node and plane)."""
    if not {"contact", "self_contact"} & set(path.families):
        return {}
    states = [model.element_state(u) for u in path.displacement]
    columns = {}
    gaps = [_min_gap(state) for state in states]
    if None not in gaps:  # (a mesh of one panel has no pair to measure)
        columns["min_gap"] = np.array(gaps)
    if "contact" in path.families:
        reaction = np.array([state["contact_force"].reshape(-1, 3).sum(axis=0)
                             for state in states]).reshape(-1, 3)
        for k, axis in enumerate("xyz"):
            columns[f"reaction_planes_{axis}"] = reaction[:, k]
    return columns


def _min_gap(state: dict) -> float | None:
    """The smallest node-plane and panel-panel gap of an element state (the distances less
    the thickness, t / 2 from a plane) [mm], or None when there is neither."""
    gaps = [state[k].min() for k in ("contact_gap", "self_contact_gap")
            if k in state and state[k].size]
    return float(min(gaps)) if gaps else None


def contact_families(problem, pattern_model) -> dict:
    """The contact families' tables: every node against every plane, and the panels'
    triangles kept off each other."""
    families = {}
    if problem.contact is not None:
        _check_thickness(problem, pattern_model)
    if problem.contact is not None and problem.contact.planes:
        families["contact"] = _contact_table(problem, pattern_model.model)
    if problem.contact is not None and problem.contact.self_contact:
        families["self_contact"] = _self_contact_table(problem, pattern_model)
    return families


def contact_history(simulation) -> dict:
    """history.csv's contact columns."""
    return _contact_columns(simulation.model, simulation.path)


KEY = ProblemKey("contact", rank=110, read=read_contact, absent={"contact": None},
                 families=contact_families, history=contact_history)
