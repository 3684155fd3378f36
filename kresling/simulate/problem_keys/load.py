"""``[[load]]``: a force [N] or a prescribed displacement [mm] on some nodes, with (in a
motion in time) its factor in time."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_keys.dynamics import read_load_time
from kresling.simulate.problem_table import node_list, vector3

__all__ = ["KEY", "Load", "load_vector"]


@dataclass(frozen=True)
class Load:
    """A force [N] or a prescribed displacement [mm] on each of ``nodes``; ``time`` (a
    :class:`~kresling.simulate.problem_keys.dynamics.LoadTime`, ``method = "dynamic"``
    only) its factor in time, None when the entry names none."""

    nodes: tuple
    kind: str  # "force" | "displacement"
    vector: tuple
    time: object = None


def read_loads(entries, context) -> dict:
    loads = []
    for i, t in enumerate(entries):
        if t.has("force") == t.has("displacement"):
            t.fail(None, f"(entry {i}) needs exactly one of 'force' [N] or 'displacement' [mm]")
        kind = "force" if t.has("force") else "displacement"
        vector = t.get(kind, vector3)
        time = read_load_time(t)
        loads.append(Load(node_list(t, context.num_nodes), kind, vector, time))
        t.finish()
    return {"loads": tuple(loads)}


def load_vector(problem, num_dofs) -> np.ndarray:
    """The loads' vectors summed per DOF, shape (num_dofs,): forces [N] or the prescribed
    motion [mm]."""
    vector = np.zeros(num_dofs)
    for load in problem.loads:
        for node in load.nodes:
            vector[3 * node:3 * node + 3] += load.vector
    return vector


KEY = ProblemKey("load", rank=50, read=read_loads, array=True)
