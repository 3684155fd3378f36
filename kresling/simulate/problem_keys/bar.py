"""``[[bar]]``: bars between any two nodes, with their own modulus, area and law (members
given one by one: a linkage's braced links, a brace across a panel; see
:class:`kresling.model.Members`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.laws import BAR_LAWS
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import node_rows, quantity, string

__all__ = ["KEY", "MemberBars"]


@dataclass(frozen=True)
class MemberBars:
    """One ``[[bar]]`` entry: ``nodes`` (B, 2), ``modulus`` [N/mm^2], ``area`` [mm^2] and
    ``law`` (one of :data:`kresling.laws.BAR_LAWS`) shared by its bars."""

    nodes: np.ndarray
    modulus: float
    area: float
    law: str


def read_bars(entries, context) -> dict:
    """The ``[[bar]]`` entries."""
    out = []
    for t in entries:
        nodes = node_rows(t, "nodes", 2, context.num_nodes, "a bar: [i, j]")
        modulus = t.get("modulus", quantity, required=True, allowed="the modulus [N/mm^2]")
        area = t.get("area", quantity, required=True, allowed="the cross-section [mm^2]")
        law = t.get("law", string, "linear", choices=tuple(BAR_LAWS))
        t.finish()
        out.append(MemberBars(nodes, modulus, area, law))
    return {"member_bars": tuple(out)}


KEY = ProblemKey("bar", rank=30, read=read_bars, array=True)
