"""Load capacity of every configuration: stiffness against length, and the largest tip loads.

For each of the ``2**m`` configurations, the arm is pretensioned (every tendon at
``pretension`` N), its 3 x 3 tip compliance is taken from the tangent, and the tip load is
raised along each of four directions (:data:`~kresling.arm.analyses.CAPACITY_DIRECTIONS`:
towards the base, towards tendon 1, away from it, across) until a tendon that was taut goes
slack or the arm loses equilibrium (a module snaps).

The table keeps the arm's length beside its stiffness on purpose: the all-extended arm is
not the stiffest configuration, it is the longest, and a tip load acts on a longer lever.
The moment a sideways load exerts at the base (load times tip height) is listed too.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling._validation import as_integer
from kresling.arm.analyses import (CAPACITY_DIRECTIONS, DEFAULT_PRETENSION, ArmSolver,
                                   CapacityResult, load_capacity)
from kresling.arm.structure import all_configurations, build_arm

__all__ = ["CapacityRow", "load_capacity_table", "capacity_rows"]


@dataclass(frozen=True)
class CapacityRow:
    """One configuration of the load-capacity table.

    Attributes
    ----------
    configuration : str
    tip_height : float
        Length of the pretensioned arm, base to tip [mm].
    compliance : ndarray (3, 3)
        Tip compliance [mm/N].
    capacity : dict
        Direction name -> :class:`~kresling.arm.analyses.CapacityResult`.
    """

    configuration: str
    tip_height: float
    compliance: np.ndarray
    capacity: dict

    @property
    def sideways_stiffness(self) -> float:
        """1 / C_xx [N/mm]."""
        return 1.0 / float(self.compliance[0, 0])


def load_capacity_table(modules: int = 3, *, pretension: float = DEFAULT_PRETENSION,
                        max_load: float = 30.0, directions: dict | None = None,
                        **arm_options) -> list:
    """:class:`CapacityRow` of every configuration of ``modules`` modules, "00..0" first.

    ``arm_options`` go to :func:`~kresling.arm.structure.build_arm` (``n``, ``lam``, ``Lc``,
    ``R``, ``design``, ``parameters``). About 0.7 s per configuration of three modules.
    Raises :class:`~kresling.arm.analyses.EquilibriumNotReached` where a configuration's
    pretension is not reached.
    """
    modules = as_integer("modules", modules, minimum=1)
    directions = CAPACITY_DIRECTIONS if directions is None else directions
    rows = []
    for configuration in all_configurations(modules):
        arm = build_arm(configuration, **arm_options)
        solver = ArmSolver(arm)
        start = solver.pretension(pretension)
        capacity = {name: load_capacity(arm, d, pretension=pretension, max_load=max_load,
                                        solver=solver, pretensioned=start)
                    for name, d in directions.items()}
        rows.append(CapacityRow(configuration, float(start.tip_position[2]),
                                solver.tip_compliance(start), capacity))
    return rows


def _limit(c: CapacityResult) -> str:
    if c.limit == "slack":
        return f"tendon {c.tendon + 1} slack"
    if c.limit == "snap":
        return "snap" + (f" (module {c.module})" if c.module >= 0 else "")
    return "none"


def capacity_rows(table: list) -> list:
    """The table as flat dicts (for CSV, JSON and printing): configuration, tip height,
    compliance diagonal, sideways stiffness, then per direction the load, its limit and the
    moment about the base it exerts (load times tip height for sideways loads)."""
    out = []
    for row in table:
        entry = {"configuration": row.configuration, "tip_height_mm": row.tip_height,
                 "C_xx_mm_per_N": float(row.compliance[0, 0]),
                 "C_yy_mm_per_N": float(row.compliance[1, 1]),
                 "C_zz_mm_per_N": float(row.compliance[2, 2]),
                 "sideways_stiffness_N_per_mm": row.sideways_stiffness}
        for name, c in row.capacity.items():
            entry[f"load_{name}_N"] = c.load
            entry[f"limit_{name}"] = _limit(c)
            if name.endswith(("x", "y")):
                entry[f"base_moment_{name}_Nmm"] = c.load * row.tip_height
        out.append(entry)
    return out
