"""A problem's ``[[actuation]]`` entries as the fold solver's stages: which hinges each
stage drives and to which rest angles (docs/folding.md)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.model.fold_angles import hinge_fold_signs, rest_angles_for
from kresling.model.crease_kinds import FOLD_FAMILIES
from kresling.model.pattern_model import MEMBER
from kresling.model.rigid_closure import RigidClosure, rigid_closure
from kresling.simulate.problem_keys.dynamics import OSCILLATING

__all__ = ["FoldPlan", "fold_plan", "actuated_creases"]

#: What family = "fold" drives: every fold family and the joins.
_FOLD_FAMILIES = FOLD_FAMILIES + ("join",)
#: How far from its target a driven crease may end and the fold still reach its end [deg],
#: unless the analysis's ``target_tolerance_deg`` says otherwise.
FOLD_TOLERANCE_DEG = 1.0


@dataclass(frozen=True)
class FoldPlan:
    """The stages of a fold.

    Attributes
    ----------
    stages : tuple of (ndarray of int, ndarray)
        Per stage, the driven hinges and their target rest angles [rad].
    hinges : ndarray of int, shape (K,)
        Every driven hinge, in the order first driven.
    target_deg : ndarray, shape (K,)
        The last target fold angle of each [deg], FOLD's convention (scaled by the
        analysis's ``fold_percent``).
    signs : ndarray, shape (H,)
        Every hinge's sign between fold angle and dihedral angle
        (:func:`kresling.model.fold_angles.hinge_fold_signs`).
    closure : RigidClosure or None
        The pattern's interior vertices whose creases are all driven, and how far from
        closing each is at the last targets: whether rigid panels can reach them
        (:func:`kresling.model.rigid_closure.rigid_closure`); None for a pattern that is not
        flat.
    """

    stages: tuple
    hinges: np.ndarray
    target_deg: np.ndarray
    signs: np.ndarray
    closure: RigidClosure | None = None


def _fold_hinge_of_edge(pattern_model) -> dict:
    """(u, v), u < v -> the model hinge on that crease (a member hinge: on its axis)."""
    folds = pattern_model.elements.folds
    out = {}
    for h, (family, element) in enumerate(zip(pattern_model.hinge_family,
                                               pattern_model.hinge_element)):
        if family == MEMBER:
            a, b = (int(n) for n in pattern_model.model.hinges[h][:2])
        elif family != "bend":
            a, b = int(folds[element][0]), int(folds[element][1])
        else:
            continue
        out[(min(a, b), max(a, b))] = h
    return out


def actuated_creases(problem, pattern_model) -> list:
    """Per ``[[actuation]]`` entry, its creases as a dict {(u, v): (model hinge, target fold
    angle [deg] or None)} (None: an entry whose harmonic or chirp drives to no target). A
    ValueError names an entry that drives no hinge (an edge that is no crease, a family
    with no member, no fold angle in the file)."""
    by_edge = _fold_hinge_of_edge(pattern_model)
    pattern = problem.pattern
    file_angle = {(int(min(u, v)), int(max(u, v))): float(a)
                  for (u, v), a in zip(pattern.edges, pattern.edges_fold_angle)}
    out = []
    for i, entry in enumerate(problem.actuations):
        where = f"{problem.source}: actuation[{i}]"
        if entry.edges is not None:
            edges = entry.edges
            missing = [e for e in edges if e not in by_edge]
            if missing:
                raise ValueError(f"{where} key 'edges': {list(missing[0])} is not a crease "
                                 "with a hinge (a boundary, a cut, or no edge at all)")
        else:
            wanted = _FOLD_FAMILIES if entry.family == "fold" else (entry.family,)
            edges = [e for e, h in by_edge.items() if pattern_model.hinge_family[h] in wanted]
            if not edges:
                raise ValueError(f"{where} key 'family': the pattern has no "
                                 f"{entry.family!r} crease")
        swings = entry.time is not None and entry.time.kind in OSCILLATING
        creases = {}
        for edge in edges:
            angle = entry.fold_angle_deg
            if angle is None and not swings:
                angle = file_angle.get(edge, np.nan)
                if not np.isfinite(angle):
                    raise ValueError(f"{where} key 'fold_angle_deg': = \"file\" but the "
                                     f"pattern gives crease {list(edge)} no "
                                     "edges_foldAngle")
            creases[edge] = (by_edge[edge], angle)
        out.append(creases)
    return out


def fold_plan(problem, pattern_model) -> FoldPlan:
    """The problem's actuation as stages; a ValueError names an entry that drives no hinge
    (:func:`actuated_creases`)."""
    creases = actuated_creases(problem, pattern_model)
    signs = hinge_fold_signs(pattern_model)
    fraction = problem.analysis.fold_percent / 100.0
    stages, order, last = [], [], {}
    for stage in range(1, max(a.stage for a in problem.actuations) + 1):
        targets = {}
        for entry, driven in zip(problem.actuations, creases):
            if entry.stage != stage:
                continue
            for hinge, angle in driven.values():
                targets[hinge] = fraction * angle  # a later entry overrides
        if not targets:
            continue
        hinges = np.array(sorted(targets), dtype=np.int64)
        angles = np.array([targets[h] for h in hinges])
        stages.append((hinges, rest_angles_for(angles, signs[hinges])))
        for h, a in zip(hinges, angles):
            if h not in last:
                order.append(int(h))
            last[int(h)] = float(a)
    hinges = np.array(order, dtype=np.int64)
    return FoldPlan(tuple(stages), hinges, np.array([last[h] for h in order]), signs,
                    _closure_at_targets(problem.pattern, creases, last))


def _closure_at_targets(pattern, creases, last) -> RigidClosure | None:
    """:func:`rigid_closure` of the pattern at the driven creases' last targets (``last``:
    hinge -> fold angle [deg]), the creases not driven left free."""
    target = {}
    for driven in creases:
        for edge, (hinge, _) in driven.items():
            target[edge] = last[hinge]
    angles = [target.get((int(min(u, v)), int(max(u, v))), np.nan)
              for u, v in np.asarray(pattern.edges).tolist()]
    return rigid_closure(pattern.vertices, pattern.edges, angles, pattern.faces)
