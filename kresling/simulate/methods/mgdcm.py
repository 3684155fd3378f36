"""``method = "mgdcm"``: the [[load]] forces' path by the modified generalized displacement
control method, past limit points, to a largest load factor or a monitored displacement."""

from __future__ import annotations

import numpy as np

from kresling import _core
from kresling.simulate.methods.method import PathMethod
from kresling.simulate.methods.path_settings import check_load_kind
from kresling.simulate.problem_table import count, number, positive
from kresling.solvers import solve_mgdcm

__all__ = ["METHOD"]

#: MGDCM's defaults, as the core declares them.
_MGDCM = _core.solvers.MgdcmOptions()


class Mgdcm(PathMethod):
    name = "mgdcm"
    checks_own_monitor = True

    def read_settings(self, t) -> dict:
        initial = t.get("initial_load_factor", number, _MGDCM.initial_load_factor)
        if initial == 0:
            t.fail("initial_load_factor", "= 0 is invalid: must be non-zero (its sign sets "
                                          "the loading direction)")
        return {"initial_load_factor": initial,
                "max_increments": t.get("max_increments", count, _MGDCM.max_increments),
                "max_load_factor": t.get("max_load_factor", positive, _MGDCM.max_load_factor)}

    def check(self, problem, t):
        check_load_kind(problem, t, "force")

    def stepping(self, problem) -> str:
        return "MGDCM (generalized displacement control)"

    def solve(self, problem, pattern_model, vector, common, plan):
        analysis = problem.analysis
        monitor = analysis.stop
        return solve_mgdcm(pattern_model.model, vector,
                           initial_load_factor=analysis.initial_load_factor,
                           max_increments=analysis.max_increments,
                           max_load_factor=analysis.max_load_factor,
                           monitor_dof=None if monitor is None else monitor.dof,
                           max_displacement=np.inf if monitor is None else monitor.beyond,
                           **common)

    def progress_total(self, analysis) -> int:
        return analysis.max_increments

    def progress_done(self, analysis, count, load_factor, u) -> float:
        """Increments of the largest number, or the monitored displacement's share of
        its bound, whichever is further."""
        done = count
        if analysis.stop is not None:
            done = max(done, abs(u[analysis.stop.dof]) / analysis.stop.beyond
                       * analysis.max_increments)
        return done


METHOD = Mgdcm()
