"""A problem's model: the pattern's bar-and-hinge model with its supports, and the element
families its keys add (springs, contact, ...)."""

from __future__ import annotations

import dataclasses

import numpy as np

from kresling.model import ManualProperties, Members, PatternModel, build_pattern_model
from kresling.model.fold_angles import hinge_fold_signs, rest_angles_for
from kresling.simulate.problem import load_problem
from kresling.simulate.problem_keys import problem_keys
from kresling.simulate.problem_keys.material import MATERIAL_KEY_OF_FIELD
from kresling.simulate.problem_keys.pattern import node_count
from kresling.simulate.problem_table import AXES
from kresling.simulate.stages import StagedProblem

__all__ = ["build_problem_model"]


def build_problem_model(problem) -> PatternModel:
    """The problem's pattern model with its supports (no loads); for a problem in stages,
    the model every stage starts from."""
    problem = load_problem(problem)
    if isinstance(problem, StagedProblem):   # the stages share the pattern and members
        problem = problem.stages[0][1]
    # The supports go in with the model (not added to a copy afterwards: the copy was 28 %
    # of the model's cost); the node count is the one the problem was checked against
    # (pattern vertices and the split's centres).
    count = problem.num_nodes or node_count(problem.pattern, problem.split, problem.centre)
    fixed = np.zeros((count, 3), dtype=bool)
    for support in problem.supports:
        for axis in support.axes:
            fixed[support.node, AXES[axis]] = True
    members = _members(problem)
    # A structure of members alone has no panels: its material calibrates nothing.
    material = problem.material if problem.material is not None else _NO_PANELS
    try:
        pm = build_pattern_model(problem.pattern, material=material,
                                 split=problem.split, centre=problem.centre, laws=problem.laws,
                                 fixed=fixed, merlin2_compat=problem.merlin2_compat,
                                 assignments=problem.assignments, members=members)
    except ValueError as error:  # a value the model cannot take: name the problem's key
        raise ValueError(f"{problem.source}: {_where(str(error))}: {error}") from None
    pm = _with_member_fold_angles(problem, pm)
    by_key = [(key, key.families(problem, pm)) for key in problem_keys()
              if key.families is not None]
    families = {name: table for _, tables in by_key for name, table in tables.items()}
    if not families:
        _check_model(problem, pm.model)
        return pm
    try:
        # The pattern model's own families (the faces' angle springs) stay beside these.
        model = pm.model.with_families(families)
    except ValueError as error:
        for key, tables in by_key:  # which key's families the model refuses
            try:
                pm.model.with_families(tables)
            except ValueError as own:
                raise ValueError(f"{problem.source}: {key.label}: {own}") from None
        raise ValueError(f"{problem.source}: {error}") from None
    _check_model(problem, model)
    return dataclasses.replace(pm, model=model)


#: The material of a pattern without panels (never used: there is nothing to calibrate).
_NO_PANELS = ManualProperties(bar_modulus=1.0, bar_area=1.0)


def _members(problem) -> Members | None:
    """The ``[[bar]]`` and ``[[hinge]]`` entries as the model's members (rest angles given
    in FOLD's convention are set once the hinges' signs are known: NaN here)."""
    bars, hinges = getattr(problem, "member_bars", ()), getattr(problem, "member_hinges", ())
    if not bars and not hinges:
        return None
    rest = [np.radians(h.rest_angle_deg) if h.convention == "simfast" and
            h.rest_angle_deg is not None else np.full(len(h.nodes), np.nan) for h in hinges]
    return Members(
        bars=np.vstack([b.nodes for b in bars]) if bars else np.zeros((0, 2), dtype=np.int64),
        bar_modulus=np.concatenate([np.full(len(b.nodes), b.modulus) for b in bars] or [[]]),
        bar_area=np.concatenate([np.full(len(b.nodes), b.area) for b in bars] or [[]]),
        bar_law=tuple(b.law for b in bars for _ in b.nodes),
        hinges=np.vstack([h.nodes for h in hinges]) if hinges
        else np.zeros((0, 4), dtype=np.int64),
        hinge_stiffness=np.concatenate([np.full(len(h.nodes), h.stiffness) for h in hinges]
                                       or [[]]),
        hinge_rest_angle=np.concatenate(rest or [[]]),
        hinge_law=tuple(h.law for h in hinges for _ in h.nodes))


def _with_member_fold_angles(problem, pm):
    """The member hinges' rest angles given as fold angles, through each hinge's sign
    between fold and dihedral angle (read from the panel it lies on, as a crease's)."""
    hinges = getattr(problem, "member_hinges", ())
    if not any(h.convention == "fold" and h.rest_angle_deg is not None for h in hinges):
        return pm
    first = len(pm.model.hinges) - sum(len(h.nodes) for h in hinges)
    signs = hinge_fold_signs(pm)
    rest = np.array(pm.model.hinge_rest_angle)
    for h in hinges:
        span = slice(first, first + len(h.nodes))
        if h.convention == "fold" and h.rest_angle_deg is not None:
            rest[span] = rest_angles_for(h.rest_angle_deg, signs[span])
        first += len(h.nodes)
    return dataclasses.replace(pm, model=pm.model.replace(hinge_rest_angle=rest))


def _check_model(problem, model):
    """Every key's refusals that need the built model."""
    for key in problem_keys():
        if key.model_check is not None:
            key.model_check(problem, model)


def _where(message: str) -> str:
    """The table and key of the problem a model-building message is about."""
    if message.startswith(("member bars", "member hinges")):
        return "[[bar]]" if message.startswith("member bars") else "[[hinge]]"
    name = message.split(" ", 1)[0]
    if name in MATERIAL_KEY_OF_FIELD:
        return f"[material] key {MATERIAL_KEY_OF_FIELD[name]!r}"
    return "[pattern] with its [material] (building the model)"
