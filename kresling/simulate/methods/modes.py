"""``method = "modes"``: vibration modes about the rest state, or about the loaded
equilibrium an ``[analysis.about]`` table names (``load_factor``, default 1, times the
``[[load]]`` forces, reached by force control in ``steps`` equal increments, default 10;
the modes are those of the tangent there, its stress stiffness included)."""

from __future__ import annotations

from dataclasses import dataclass

from kresling.simulate.methods.method import Method
from kresling.simulate.problem_table import count, number, raw

__all__ = ["METHOD", "LoadedState"]


@dataclass(frozen=True)
class LoadedState:
    """The equilibrium under ``load_factor`` times the [[load]] forces, by force control in
    ``steps`` increments."""

    load_factor: float = 1.0
    steps: int = 10

    def describe(self) -> dict:
        """As summary.json records it."""
        return {"load_factor": self.load_factor, "steps": self.steps}


class Modes(Method):
    name = "modes"
    monitors = False

    def read_settings(self, t) -> dict:
        return {"modes": t.get("modes", count, 10), "about": _read_about(t)}

    def check(self, problem, t):
        kinds = {load.kind for load in problem.loads}
        if problem.analysis.about == "rest" and problem.loads:
            t.fail("about", "= 'rest': the modes are about the rest state, so a [[load]] "
                            "would have no effect; remove it, or give an [analysis.about] "
                            "table (the modes about the loaded state)")
        if problem.analysis.about != "rest" and kinds != {"force"}:
            t.fail("about", "is a loaded state: it needs [[load]] forces (and forces "
                            f"only; given: {sorted(kinds) or 'none'})")
        if problem.sheet_mass.density is None and not problem.masses:
            t.fail("method", "= 'modes' needs masses: [material] density [t/mm^3] (with "
                             "the sheet's thickness) or [[mass]] entries")

    def stepping(self, problem) -> str:
        return "none: the modes about one state"

    def run(self, problem, pattern_model, *, stop=None, start=None):
        # Here: every problem loads the methods, a path needs no modes (nor the analyses).
        from kresling.simulate.modes_output import run_modes

        return run_modes(problem, pattern_model,
                         state=None if start is None else start.displacement)


def _read_about(t):
    """``about``: "rest", or a LoadedState from ``[analysis.about]``."""
    value = t.get("about", raw, "rest")
    if value == "rest":
        return value
    if not isinstance(value, dict):
        t.fail("about", f"= {value!r} is invalid: must be \"rest\" or an [analysis.about] table "
                        "(load_factor, steps: the equilibrium under the [[load]] forces)")
    about = t.table("about")
    state = LoadedState(about.get("load_factor", number, 1.0), about.get("steps", count, 10))
    about.finish()
    return state


METHOD = Modes()
