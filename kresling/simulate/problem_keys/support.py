"""``[[support]]``: nodes held along some axes (u = 0 there). A method that drives the
sheet from inside (a fold) needs none: without them the free sheet's rigid-body motions
alone are held."""

from __future__ import annotations

from dataclasses import dataclass

from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import AXES, node_list, string
from kresling.simulate.rigid_hold import rigid_body_hold

__all__ = ["KEY", "Support", "held_in_words"]


@dataclass(frozen=True)
class Support:
    """Supported axes of a node (u = 0 there)."""

    node: int
    axes: str


def read_supports(entries, context) -> dict:
    supports = []
    for t in entries:
        fix = t.get("fix", string, required=True, allowed="any of the letters x, y, z")
        if not fix or set(fix) - set(AXES) or len(set(fix)) != len(fix):
            t.fail("fix", f"= {fix!r} is invalid: must be some of the letters x, y, z, each once")
        for node in node_list(t, context.num_nodes):
            supports.append(Support(node, "".join(sorted(fix))))
        t.finish()
    held = ()
    if not supports and getattr(context.method, "holds_free_sheet", False):
        # Driven from inside: hold the free sheet's rigid-body motions only.
        held = tuple(Support(node, axes) for node, axes in
                     rigid_body_hold(context.pattern.vertices, context.pattern.faces))
        supports = list(held)
    return {"supports": tuple(supports), "held": held}


def held_in_words(held) -> str:
    """``node 12 (x, y, z), node 40 (y, z), node 41 (z)``."""
    return ", ".join(f"node {s.node} ({', '.join(s.axes)})" for s in held)


KEY = ProblemKey("support", rank=40, read=read_supports, array=True)
