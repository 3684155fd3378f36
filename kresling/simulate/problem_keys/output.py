"""The ``[output]`` table of a problem file: which increments the output files keep, and
the curve the view plots.

``every = k`` keeps every k-th increment (and the last) in history.csv, displacements.csv,
path.fold and view.html; ``curve = { x = "...", y = "..." }`` names the view's curve (see
:mod:`kresling.simulate.curve`); ``formats = ["stl", "obj"]`` writes the end state's
triangles as folded.stl and folded.obj too.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import raw

__all__ = ["KEY", "Output", "FORMATS"]

#: The formats the end state may be written in: ``folded.stl``, ``folded.obj``.
FORMATS = ("stl", "obj")

#: The quantities a curve may name: history.csv's columns and any node's displacement.
_NAMED = re.compile(r"step|load_factor|iterations|energy_(?:bars|folds|bends|total)|"
                    r"time|energy_(?:kinetic|strain|damping)|work_external|"
                    r"(u|reaction)_(\d+)_([xyz])")
#: The quantities of a motion in time (``method = "dynamic"``) only.
_IN_TIME = ("time", "energy_kinetic", "energy_strain", "energy_damping", "work_external")


@dataclass(frozen=True)
class Output:
    """What a run writes: every ``every``-th increment (the last always), and the view's
    curve ``(x, y)`` named by quantity (None: the method's default)."""

    every: int = 1
    curve: tuple | None = None
    #: The end state's files besides the path's: any of FORMATS.
    formats: tuple = ()


def read_output(table, context) -> dict:
    """The ``[output]`` table: a curve's quantities are checked against the model's node
    count, the method (a reaction is a column of a driven DOF under displacement control, a
    time and the kinetic energy belong to a motion in time) and the driven DOFs."""
    num_nodes, method = context.num_nodes, context.method  # read and checked (rank 60)
    driven = {(node, axis) for load in context.loads if load.kind == "displacement"
              for node in load.nodes for axis, value in zip("xyz", load.vector) if value}
    every = table.get("every", _every, 1)
    formats = table.get("formats", _formats, ())
    curve = table.get("curve", raw)
    if curve is not None:
        if not isinstance(curve, dict) or set(curve) != {"x", "y"}:
            table.fail("curve", f"= {curve!r} is invalid: must be a table with exactly the "
                                'keys x and y, e.g. { x = "u_24_z", y = "reaction_24_z" }')
        for axis in ("x", "y"):
            _check_quantity(table, axis, curve[axis], num_nodes, method, driven)
        curve = (curve["x"], curve["y"])
    table.finish()
    return {"output": Output(every=every, curve=curve, formats=formats)}


def _check_quantity(table, axis, name, num_nodes, method, driven):
    allowed = ("must be step, load_factor, iterations, energy_bars, energy_folds, "
               "energy_bends, energy_total, u_<node>_<axis>, (displacement control) "
               "reaction_<node>_<axis> of a driven DOF or (method = 'dynamic') time, "
               "energy_kinetic, energy_strain, energy_damping or work_external")
    match = _NAMED.fullmatch(name) if isinstance(name, str) else None
    if match is None:
        table.fail("curve", f"{axis} = {name!r} is invalid: {allowed}")
    if match.group(1) is None:
        if not method.in_time and name in _IN_TIME:
            table.fail("curve", f"{axis} = {name!r} is a quantity of a motion in time: "
                                "[analysis] method = 'dynamic' only")
        return
    node, where = int(match.group(2)), (int(match.group(2)), match.group(3))
    if node >= num_nodes:
        table.fail("curve", f"{axis} = {name!r} names node {node}, out of range: nodes are "
                            f"numbered 0 to {num_nodes - 1}")
    if match.group(1) == "reaction" and (not method.drives_displacements or
                                         where not in driven):
        table.fail("curve", f"{axis} = {name!r} is invalid: a reaction is a column of a "
                            "driven DOF under displacement control (driven: "
                            f"{[f'reaction_{n}_{a}' for n, a in sorted(driven)]})")


def _formats(table, key, value, allowed=None):
    if not isinstance(value, list) or any(v not in FORMATS for v in value) or \
            len(set(value)) != len(value):
        table.fail(key, f"= {value!r} is invalid: must be a list of distinct formats among "
                        f"{list(FORMATS)} (the end state's files besides the path's)")
    return tuple(value)


def _every(table, key, value, allowed=None):
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        table.fail(key, f"= {value!r} is invalid: must be an integer >= 1 (keep every k-th "
                        "increment, the last always)")
    return value


KEY = ProblemKey("output", rank=70, read=read_output, default={})
