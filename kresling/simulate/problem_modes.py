"""The state a problem's vibration modes are about (``[analysis] method = "modes"``): the
rest state (``about = "rest"``, the default) or a loaded equilibrium (an ``[analysis.about]``
table), read as :mod:`kresling.simulate.problem` reads every table.

``[analysis.about]``: ``load_factor`` (default 1) times the ``[[load]]`` forces, reached by
force control in ``steps`` equal increments (default 10); the modes are those of the tangent
there, its stress stiffness included.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["LoadedState", "read_about"]


@dataclass(frozen=True)
class LoadedState:
    """The equilibrium under ``load_factor`` times the [[load]] forces, by force control in
    ``steps`` increments."""

    load_factor: float = 1.0
    steps: int = 10

    def describe(self) -> dict:
        """As summary.json records it."""
        return {"load_factor": self.load_factor, "steps": self.steps}


def read_about(t, sub_table, number, count):
    """``about`` of ``[analysis]`` ``t``: "rest", or a LoadedState from ``[analysis.about]``
    (``sub_table(value)`` makes its table reader)."""
    value = t.get("about", lambda t_, k, v, a: v, "rest")
    if value == "rest":
        return value
    if not isinstance(value, dict):
        t.fail("about", f"= {value!r} is invalid: must be \"rest\" or an [analysis.about] table "
                        "(load_factor, steps: the equilibrium under the [[load]] forces)")
    about = sub_table(value)
    state = LoadedState(about.get("load_factor", number, 1.0), about.get("steps", count, 10))
    about.finish()
    return state
