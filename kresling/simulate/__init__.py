"""Simulate any crease pattern from a problem file.

A problem (a TOML file, or a dict of the same shape) names a pattern (FOLD or OBJ), how
to build its bar-and-hinge model (panel split, material calibration, laws per hinge
family), its supports and loads, and the analysis (displacement control, force control or
MGDCM, with a stopping rule). :func:`simulate` runs it; :meth:`Simulation.write` writes
the history, the displacements, the path as FOLD frames and an interactive view. From the
command line: ``kresling simulate PROBLEM.toml --out DIR``. docs/simulate.md lists every
key.
"""

from kresling._lazy import lazy_names
from kresling.simulate.element_histories import ElementHistories, element_histories
from kresling.simulate.problem import Analysis, Load, MonitorStop, Problem, Support, load_problem
from kresling.simulate.problem_model import build_problem_model
from kresling.simulate.run import simulate
from kresling.simulate.simulation import PathState, Simulation

# Imported when first used: a path needs no vibration modes (nor the analyses they bring).
__getattr__, __dir__ = lazy_names(__name__, {"modes_at": "state_modes"})

__all__ = ["simulate", "load_problem", "build_problem_model", "Simulation", "PathState",
           "Problem", "Analysis", "Load", "Support", "MonitorStop", "ElementHistories",
           "element_histories", "modes_at"]
