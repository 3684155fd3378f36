"""``method = "dynamic"``: the motion in time under the [[load]] forces (each with its
time function) and gravity, integrated over ``[dynamics] duration``."""

from __future__ import annotations

import logging

import numpy as np

from kresling.simulate.curve import moving_dof
from kresling.simulate.methods.method import Method
from kresling.simulate.simulation import PathState

__all__ = ["METHOD"]

logger = logging.getLogger("kresling.simulate.run")


class Dynamic(Method):
    name = "dynamic"
    in_time = True

    def check(self, problem, t):
        if problem.dynamics is None:
            t.fail("method", "= 'dynamic' needs a [dynamics] table (scheme, time_step, "
                             "duration)")
        if {load.kind for load in problem.loads} - {"force"}:
            t.fail("method", "= 'dynamic' takes force loads only (each with its time); a "
                             "prescribed displacement is not one")
        if problem.sheet_mass.density is None and not problem.masses:
            t.fail("method", "= 'dynamic' needs masses: [material] density [t/mm^3] (with "
                             "the sheet's thickness) or [[mass]] entries")
        if problem.contact is not None and problem.dynamics.scheme == "explicit":
            raise ValueError(f"{problem.source}: [dynamics] scheme = 'explicit' cannot keep "
                             "[contact]'s barriers (each step must not cross them): use "
                             "'newmark' or 'hht'")

    def stepping(self, problem) -> str:
        return {"newmark": "time steps of Newmark's average acceleration scheme",
                "hht": f"time steps of HHT-alpha (alpha = {problem.dynamics.hht_alpha:g})",
                "explicit": "explicit central-difference time steps"}[problem.dynamics.scheme]

    def run(self, problem, pattern_model, *, stop=None, start=None):
        """The motion, ended early by the problem's monitor or by ``stop`` (which sees
        the time as the load factor)."""
        # Here: every problem loads the methods, a path needs no time integration.
        from kresling.simulate.dynamics_output import run_dynamics

        monitor, count = problem.analysis.stop, [0]

        def rule(time, u):
            count[0] += 1
            if monitor is not None and abs(u[monitor.dof]) > monitor.beyond:
                return True
            return stop is not None and bool(
                stop(PathState(count[0], float(time), np.asarray(u).reshape(-1, 3))))

        run = run_dynamics(problem, pattern_model,
                           stop=rule if monitor is not None or stop else None, start=start)
        if not run.path.completed:
            logger.warning("%s: the motion stopped after %d steps: %s", problem.source,
                           run.path.num_steps, run.path.message)
        return run

    def curve(self, simulation, columns) -> tuple:
        """The monitored (or busiest) DOF's displacement against time."""
        u, label = moving_dof(simulation, simulation.problem.analysis.stop)
        return np.asarray(simulation.path.load_factor, dtype=float), u, "time [s]", label


METHOD = Dynamic()
