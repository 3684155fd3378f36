"""``method = "force_control"``: the [[load]] forces applied in equal increments of the
load factor."""

from __future__ import annotations

import math

from kresling.simulate.methods.method import PathMethod
from kresling.simulate.methods.path_settings import check_load_kind
from kresling.simulate.problem_table import positive
from kresling.solvers import solve_force_control

__all__ = ["METHOD"]


class ForceControl(PathMethod):
    name = "force_control"
    bounded = True

    def read_settings(self, t) -> dict:
        return {**self.read_steps(t),
                "max_load_factor": t.get("max_load_factor", positive, math.inf)}

    def check(self, problem, t):
        check_load_kind(problem, t, "force")

    def stepping(self, problem) -> str:
        return "equal load increments"

    def solve(self, problem, pattern_model, vector, common, plan):
        return solve_force_control(pattern_model.model, vector, problem.analysis.steps,
                                   **common)


METHOD = ForceControl()
