"""A problem's model: the pattern's bar-and-hinge model with its supports, and the element
families its keys add (springs, contact, ...)."""

from __future__ import annotations

import dataclasses

import numpy as np

from kresling.model import PatternModel, build_pattern_model
from kresling.simulate.problem import load_problem
from kresling.simulate.problem_keys import problem_keys
from kresling.simulate.problem_keys.material import MATERIAL_KEY_OF_FIELD
from kresling.simulate.problem_keys.pattern import node_count
from kresling.simulate.problem_table import AXES

__all__ = ["build_problem_model"]


def build_problem_model(problem) -> PatternModel:
    """The problem's pattern model with its supports (no loads)."""
    problem = load_problem(problem)
    # The supports go in with the model (not added to a copy afterwards: the copy was 28 %
    # of the model's cost); the node count is the one the problem was checked against
    # (pattern vertices and the split's centres).
    count = problem.num_nodes or node_count(problem.pattern, problem.split, problem.centre)
    fixed = np.zeros((count, 3), dtype=bool)
    for support in problem.supports:
        for axis in support.axes:
            fixed[support.node, AXES[axis]] = True
    try:
        pm = build_pattern_model(problem.pattern, material=problem.material,
                                 split=problem.split, centre=problem.centre, laws=problem.laws,
                                 fixed=fixed, merlin2_compat=problem.merlin2_compat,
                                 assignments=problem.assignments)
    except ValueError as error:  # a value the model cannot take: name the problem's key
        raise ValueError(f"{problem.source}: {_where(str(error))}: {error}") from None
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


def _check_model(problem, model):
    """Every key's refusals that need the built model."""
    for key in problem_keys():
        if key.model_check is not None:
            key.model_check(problem, model)


def _where(message: str) -> str:
    """The table and key of the problem a model-building message is about."""
    name = message.split(" ", 1)[0]
    if name in MATERIAL_KEY_OF_FIELD:
        return f"[material] key {MATERIAL_KEY_OF_FIELD[name]!r}"
    return "[pattern] with its [material] (building the model)"
