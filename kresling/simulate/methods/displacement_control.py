"""``method = "displacement_control"``: prescribed displacements ([[load]] displacement)
followed in equal or adaptive increments, MERLIN2's step control under merlin2_compat."""

from __future__ import annotations

import numpy as np

from kresling.simulate.methods.method import PathMethod
from kresling.simulate.methods.path_settings import (ADAPTIVE_TOLERANCE, PREDICTORS,
                                                     check_load_kind, read_increments)
from kresling.solvers import solve_displacement_control

__all__ = ["METHOD"]


class DisplacementControl(PathMethod):
    name = "displacement_control"
    drives_displacements = True

    def read_settings(self, t) -> dict:
        return {**self.read_steps(t), **read_increments(t, "previous")}

    def check(self, problem, t):
        check_load_kind(problem, t, "displacement")
        supported = {(s.node, a) for s in problem.supports for a in s.axes}
        for i, load in enumerate(problem.loads):
            for node in load.nodes:
                for axis, value in zip("xyz", load.vector):
                    if value != 0 and (node, axis) in supported:
                        raise ValueError(f"{problem.source}: load[{i}] drives node {node} along "
                                         f"{axis}, which a [[support]] fixes: a DOF is either "
                                         "supported or driven")

    def stepping(self, problem) -> str:
        analysis = problem.analysis
        if analysis.increments == "adaptive":
            return "adaptive increments, the equal samples read off the path between them"
        if analysis.predictor != "previous":
            return f"equal increments, each started from a {analysis.predictor} extrapolation"
        if problem.merlin2_compat:
            return "equal increments with MERLIN2's step control"
        return "equal increments, each started from the previous equilibrium"

    def solve(self, problem, pattern_model, vector, common, plan):
        analysis = problem.analysis
        adaptive = analysis.increments == "adaptive"
        order = PREDICTORS.index(analysis.predictor)  # its extrapolation's order
        return solve_displacement_control(
            pattern_model.model, vector, analysis.steps, adaptive=adaptive,
            adaptive_tolerance=ADAPTIVE_TOLERANCE, extrapolation=order,
            merlin2_steps=problem.merlin2_compat and not adaptive and order == 0,
            **common)

    def recorded_dofs(self, vector, model):
        return np.flatnonzero(vector)

    def driven_dofs(self, path, vector):
        return path.constraint_dofs

    def history_columns(self, simulation) -> dict:
        path = simulation.path
        return {f"reaction_{dof // 3}_{'xyz'[dof % 3]}": path.constraint_force[:, k]
                for k, dof in enumerate(path.constraint_dofs)}

    def curve(self, simulation, columns) -> tuple:
        """The drive's reaction against the driven displacement of its largest component
        (several driven DOFs: their reactions weighted by their share of the motion, the
        force that does the drive's work over that displacement)."""
        path = simulation.path
        dofs = np.asarray(path.constraint_dofs, dtype=np.int64)
        motion = np.zeros(3 * simulation.model.num_nodes)
        for load in simulation.problem.loads:
            for node in load.nodes:
                motion[3 * node:3 * node + 3] += load.vector
        share = motion[dofs]
        lead = int(np.argmax(np.abs(share)))
        node, axis = divmod(int(dofs[lead]), 3)
        x = np.asarray(path.displacement)[:, dofs[lead]]
        reactions = np.asarray(path.constraint_force, dtype=float).reshape(len(x), len(dofs))
        label = f"u{'xyz'[axis]} of node {node} [mm]"
        if len(dofs) == 1:
            return x, reactions[:, 0], label, f"reaction_{node}_{'xyz'[axis]} [N]"
        y = reactions @ (share / share[lead])  # work-conjugate to x: sum r_k du_k = y dx
        return x, y, label, f"drive's reaction over {len(dofs)} driven DOFs [N]"


METHOD = DisplacementControl()
