"""``[[mass]]`` and the sheet's mass: the problem file's masses: ``[material] density`` (with the sheet's thickness) and the
``[[mass]]`` entries, and the node masses they give (see docs/dynamics.md).

``density`` [t/mm^3] spreads each triangle's mass ``density * thickness * area`` equally over
its corners (:func:`kresling.model.masses.lumped_masses`); the thickness is the sheet
calibration's (``calibration = "auto"``) or ``[material] thickness`` beside a manual
calibration. Each ``[[mass]]`` adds ``mass`` [t] to every node it names.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.model.masses import lumped_masses
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import node_list, number, quantity

__all__ = ["KEY", "NodeMass", "SheetMass", "read_sheet_mass", "problem_masses"]


@dataclass(frozen=True)
class NodeMass:
    """An explicit mass [t] on one node."""

    node: int
    mass: float


@dataclass(frozen=True)
class SheetMass:
    """The sheet's density [t/mm^3] and thickness [mm] (either may be None: no sheet mass)."""

    density: float | None = None
    thickness: float | None = None


def read_sheet_mass(t, material) -> SheetMass:
    """``density`` (and, beside a manual calibration, ``thickness``) of ``[material]``."""
    density = t.get("density", quantity, None)
    thickness = getattr(material, "thickness", None)
    if thickness is None:       # a manual calibration names no thickness of its own
        thickness = t.get("thickness", quantity, None)
    if density is not None and thickness is None:
        t.fail("density", "needs the sheet's thickness [mm]: add 'thickness' to [material]")
    if thickness is not None and density is None and t.has("thickness") \
            and not hasattr(material, "thickness"):
        t.fail("thickness", "is used for the sheet's mass only: give 'density' [t/mm^3] too")
    return SheetMass(density, thickness)


def read_masses(entries, context) -> dict:
    """The ``[[mass]]`` entries (``node`` or ``nodes``, ``mass`` [t] >= 0 per node)."""
    out = []
    for t in entries:
        nodes = node_list(t, context.num_nodes)
        mass = t.get("mass", number, required=True, allowed="a mass per node [t] (>= 0)")
        if mass < 0:
            t.fail("mass", f"= {mass!r} is invalid: must be >= 0 [t]")
        t.finish()
        out.extend(NodeMass(node, mass) for node in nodes)
    return {"masses": tuple(out)}


def problem_masses(problem, pattern_model) -> np.ndarray:
    """Node masses [t], shape (N,): the sheet's (if it has a density) plus ``[[mass]]``."""
    count = pattern_model.model.num_nodes
    extra = np.zeros(count)
    for entry in problem.masses:
        extra[entry.node] += entry.mass
    sheet = problem.sheet_mass
    if sheet.density is None:
        return extra
    return lumped_masses(pattern_model, sheet.thickness, sheet.density, extra=extra)


KEY = ProblemKey("mass", rank=90, read=read_masses, array=True)
