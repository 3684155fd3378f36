"""``[sensitivity]``: the exact derivatives of a path's history by the problem's parameters,
written as sensitivities.csv.

``parameters`` names what the history is differentiated by: a material key of the problem
(``"bar_modulus"``, ``"E"``, ``"fold_stiffness"``, ...: any key of ``[material]`` the model's
stiffnesses are linear in, seen through the calibration), a parameter column of an element
family (``"bars.area"``, ``"hinges.rest_angle[3]"``: :func:`kresling.solvers.parameter_names`
lists a model's), or ``"vertices"``: every coordinate of every pattern vertex (the shape; the
rest lengths and angles that hold the reference geometry move with it, and N5B8 centre nodes
with their corners). Each step of the path is an equilibrium at its own control value (the
prescribed motion's fraction, the load factor, the fold's fraction), and its derivative is
that equilibrium's (:func:`kresling.solvers.path_sensitivity`,
:func:`kresling.solvers.fold_sensitivity`; docs/sensitivities.md).

sensitivities.csv has ``step``, ``load_factor`` and a column ``d(<column>)/d(<parameter>)``
for every differentiable history.csv column (the driven DOFs' reactions, the monitored
displacement, ``energy_total``) and every parameter, at the increments history.csv keeps.
"""

from __future__ import annotations

import dataclasses
import logging
import re
from pathlib import Path

import numpy as np

from kresling.model.panel_elements import build_panel_elements
from kresling.simulate.outputs import write_csv
from kresling.simulate.problem_model import build_problem_model
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_keys.material import MATERIAL_KEY_OF_FIELD
from kresling.simulate.problem_table import raw
# The package, its sensitivities read when first used (every problem loads this key).
from kresling import solvers

__all__ = ["KEY", "Sensitivity"]

logger = logging.getLogger("kresling.simulate.run")

#: The field of the material behind each material key a parameter may name.
_FIELD_OF_KEY = {key: field for field, key in MATERIAL_KEY_OF_FIELD.items()}
#: history.csv's columns of one node's DOF: a driven DOF's reaction, a monitored displacement.
_NODE_COLUMN = re.compile(r"(reaction|u)_(\d+)_([xyz])")
#: How far apart the models are built to read a material key's or a vertex's direction
#: (a linear map's difference is exact at any step; linearity is checked to this tolerance).
_LINEAR_TOLERANCE = 1e-9


@dataclasses.dataclass(frozen=True)
class Sensitivity:
    """The ``[sensitivity]`` table: the parameters, as written."""

    parameters: tuple


def read_sensitivity(t, context) -> dict:
    value = t.get("parameters", raw, required=True,
                  allowed="a list of material keys, 'family.column' parameters or 'vertices'")
    if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
        t.fail("parameters", f"= {value!r} is invalid: must be a non-empty list of strings "
                             "(material keys such as \"bar_modulus\", parameter columns such as "
                             "\"bars.area\" or \"hinges.rest_angle[3]\", or \"vertices\")")
    if len(set(value)) != len(value):
        t.fail("parameters", f"= {value!r} names a parameter twice")
    for name in value:
        if name == "vertices" or "." in name:
            if name != "vertices":
                try:
                    solvers.Parameter.parse(name)
                except ValueError as error:
                    t.fail("parameters", f"has {name!r}: {error}")
            continue
        field = _FIELD_OF_KEY.get(name)
        current = getattr(context.material, field, None) if field else None
        if current is None or not np.isscalar(current):
            allowed = sorted(k for k, f in _FIELD_OF_KEY.items()
                             if np.isscalar(getattr(context.material, f, None) or []))
            t.fail("parameters", f"has {name!r}: not a number of this problem's [material] "
                                 f"(its material keys: {allowed}; or 'family.column', or "
                                 "'vertices')")
    t.finish()
    return {"sensitivity": Sensitivity(tuple(value))}


def check_sensitivity(problem):
    """A path's history is differentiated: not modes, not a motion in time."""
    if problem.sensitivity is not None and not problem.method.follows_path:
        raise ValueError(f"{problem.source}: [sensitivity] differentiates a path: it applies "
                         f"to displacement_control, force_control, mgdcm and fold (given: "
                         f"method = {problem.analysis.method!r})")


def _linear_difference(build, value: float):
    """``(build(2 value) - build(value)) / value``, a linear map's derivative, checked to be
    the same as ``(build(3 value) - build(2 value)) / value``; None where it is not."""
    at = [build(k * value) for k in (1.0, 2.0, 3.0)]
    first, second = at[1] - at[0], at[2] - at[1]
    scale = max(float(np.abs(first).max(initial=0.0)), np.finfo(float).tiny)
    if np.abs(second - first).max(initial=0.0) > _LINEAR_TOLERANCE * scale:
        return None
    return first / value


def _material_direction(simulation, name) -> solvers.Direction:
    """d(parameter columns)/d(material key), through the calibration of the model."""
    problem, field = simulation.problem, _FIELD_OF_KEY[name]
    columns = [c.split(".") for c in solvers.parameter_names(simulation.model)]

    def build(value):
        material = dataclasses.replace(problem.material, **{field: value})
        model = build_problem_model(problem.replace(material=material)).model
        return np.concatenate([np.asarray(model.family(f)[c], dtype=float).ravel()
                               for f, c in columns])

    derivative = _linear_difference(build, float(getattr(problem.material, field)))
    if derivative is None:
        raise ValueError(f"{problem.source}: [sensitivity] key 'parameters': {name!r} enters "
                         "the model non-linearly (through the calibration): give the columns it "
                         "sets ('family.column') instead")
    out, start = {}, 0
    for family, column in columns:
        size = np.asarray(simulation.model.family(family)[column]).size
        part = derivative[start:start + size]
        start += size
        if np.any(part):
            out[f"{family}.{column}"] = part
    return solvers.Direction(name, columns=out)


def _vertex_directions(simulation) -> list:
    """Every pattern vertex coordinate as a direction of the model's node positions (N5B8
    centre nodes move with their corners)."""
    problem, model = simulation.problem, simulation.model
    vertices = np.asarray(problem.pattern.vertices, dtype=float)
    count = len(vertices)
    size = float(np.linalg.norm(np.ptp(vertices, axis=0))) or 1.0
    directions = []
    for i in range(count):
        for axis, letter in enumerate("xyz"):
            positions = np.zeros((model.num_nodes, 3))
            positions[i, axis] = 1.0
            if model.num_nodes > count:   # centre nodes: how they follow this vertex
                def centres(step, i=i, axis=axis):
                    moved = vertices.copy()
                    moved[i, axis] += step
                    return build_panel_elements(moved, problem.pattern.faces,
                                                split=problem.split,
                                                centre=problem.centre).nodes[count:]
                derivative = _linear_difference(centres, 1e-3 * size)
                if derivative is None:
                    raise ValueError(f"{problem.source}: [sensitivity] 'vertices': the centre "
                                     "nodes follow their corners non-linearly (MERLIN2's rule); "
                                     "use [pattern] centre = \"mean\" or split = \"N4B5\"")
                positions[count:] = derivative
            directions.append(solvers.Direction(f"vertices[{i}].{letter}",
                                        positions=positions.ravel()))
    return directions


def _directions(simulation) -> list:
    out = []
    for name in simulation.problem.sensitivity.parameters:
        if name == "vertices":
            out.extend(_vertex_directions(simulation))
        elif "." in name:
            out.append(solvers.Parameter.parse(name))
        else:
            out.append(_material_direction(simulation, name))
    return out


def check_parameters(problem, model):
    """Every 'family.column' names a parameter of the built model (before the run)."""
    if problem.sensitivity is None:
        return
    known = set(solvers.parameter_names(model))
    for name in problem.sensitivity.parameters:
        if "." in name and name.split("[", 1)[0] not in known:
            raise ValueError(f"{problem.source}: [sensitivity] key 'parameters': {name!r} is "
                             f"not a parameter of this model (its parameters: {sorted(known)})")


def write_sensitivities(simulation, directory, rows) -> dict:
    """sensitivities.csv, at the history's kept increments (nothing for a path that did not
    complete: its derivatives would be those of another problem; a warning says so)."""
    problem = simulation.problem
    if problem.sensitivity is None:
        return {}
    if not simulation.path.completed or simulation.interrupted:
        logger.warning("%s: sensitivities.csv not written: the path did not complete, so its "
                       "derivatives are refused", problem.source)
        return {}
    directions = _directions(simulation)
    try:
        if simulation.fold is not None:
            found = solvers.fold_sensitivity(simulation.model, simulation.fold.stages, simulation.path,
                                     directions)
        else:
            found = solvers.path_sensitivity(simulation.model, simulation.path, directions)
    except ValueError as error:
        raise ValueError(f"{problem.source}: [sensitivity]: {error}") from None
    columns = {"step": np.arange(1, simulation.path.num_steps + 1),
               "load_factor": simulation.path.load_factor}
    history = simulation.history_columns()
    dofs = list(np.asarray(simulation.path.constraint_dofs))
    for name in history:
        match = _NODE_COLUMN.fullmatch(name)
        dof = None if match is None else 3 * int(match.group(2)) + "xyz".index(match.group(3))
        for j, label in enumerate(found.parameters):
            if match is not None and match.group(1) == "reaction":
                columns[f"d({name})/d({label})"] = found.constraint_force[:, dofs.index(dof), j]
            elif match is not None:
                columns[f"d({name})/d({label})"] = found.displacement[:, dof, j]
            elif name == "energy_total":
                columns[f"d({name})/d({label})"] = found.energy[:, j]
    path = Path(directory) / "sensitivities.csv"
    names = list(columns)
    write_csv(path, names, zip(*(np.asarray(columns[n])[rows].tolist() for n in names)))
    return {"sensitivities": path}


KEY = ProblemKey("sensitivity", rank=130, read=read_sensitivity, absent={"sensitivity": None},
                 check=check_sensitivity, model_check=check_parameters,
                 outputs=write_sensitivities)
