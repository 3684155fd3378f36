"""``[[spring]]``: zero-length springs tying nodes to fixed points (elastic supports), the
model's ``springs`` family."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import node_list, number, raw, vector3

__all__ = ["KEY", "Spring"]


@dataclass(frozen=True)
class Spring:
    """A zero-length spring tying ``node`` to ``anchor`` [mm] with ``stiffness`` [N/mm] per
    axis (x, y, z)."""

    node: int
    stiffness: tuple
    anchor: tuple


def read_springs(entries, context) -> dict:
    """The ``[[spring]]`` entries (each ``node`` or ``nodes``, ``stiffness`` [kx, ky, kz]
    N/mm >= 0 or one number for all three, ``anchor`` [x, y, z] mm, default: the node's own
    position, given as None here)."""
    out = []
    for t in entries:
        nodes = node_list(t, context.num_nodes)
        value = t.get("stiffness", raw, required=True,
                      allowed="[kx, ky, kz] N/mm, or one number for every axis")
        k = vector3(t, "stiffness", value) if isinstance(value, list) else \
            (number(t, "stiffness", value),) * 3
        if min(k) < 0:
            t.fail("stiffness", f"= {value!r} is invalid: must be >= 0 [N/mm]")
        anchor = t.get("anchor", vector3)
        t.finish()
        out.extend(Spring(node, tuple(k), anchor) for node in nodes)
    return {"springs": tuple(out)}


def spring_family(problem, pattern_model) -> dict:
    """The springs family's columns (an anchor not given is the node's own position)."""
    if not problem.springs:
        return {}
    nodes = pattern_model.model.nodes
    springs = problem.springs
    return {"springs": {
        "nodes": np.array([s.node for s in springs], dtype=np.int64),
        "stiffness": np.array([s.stiffness for s in springs], dtype=float),
        "anchor": np.array([nodes[s.node] if s.anchor is None else s.anchor
                            for s in springs], dtype=float)}}


KEY = ProblemKey("spring", rank=85, read=read_springs, array=True, families=spring_family)
