"""Each default is declared once, in the C++ core's options structs, and every Python
signature, dataclass and problem-file default that repeats it is held to it here: change a
default in C++ and these fail until the Python side follows."""

from __future__ import annotations

import inspect
import math

import numpy as np
import pytest

from kresling import _core
from kresling.model import SpecimenParameters
from kresling.simulate.problem import Analysis
from kresling.solvers import (solve_displacement_control, solve_fold, solve_force_control,
                              solve_mgdcm)

# Python function -> the core's options struct and the parameters it shares with it.
SOLVERS = [
    (solve_displacement_control, _core.solvers.DisplacementControlOptions,
     ("tolerance", "max_iterations", "reject_iterations", "max_bisections", "shift",
      "extrapolation", "merlin2_steps", "adaptive", "adaptive_tolerance")),
    (solve_force_control, _core.solvers.ForceControlOptions,
     ("tolerance", "max_iterations", "max_bisections", "shift")),
    (solve_mgdcm, _core.solvers.MgdcmOptions,
     ("initial_load_factor", "max_increments", "max_load_factor", "max_step_factor",
      "tolerance", "max_iterations", "shift")),
    (solve_fold, _core.solvers.FoldOptions,
     ("tolerance", "max_iterations", "max_bisections", "extrapolation", "shift")),
]


@pytest.mark.parametrize("function, options, names", SOLVERS,
                         ids=[f.__name__ for f, _, _ in SOLVERS])
def test_solver_defaults_are_the_cores(function, options, names):
    core = options()
    parameters = inspect.signature(function).parameters
    for name in names:
        assert parameters[name].default == getattr(core, name), name


def test_the_problem_files_defaults_are_the_cores():
    dc, mgdcm = _core.solvers.DisplacementControlOptions(), _core.solvers.MgdcmOptions()
    analysis = Analysis(method="displacement_control")
    assert analysis.tolerance == dc.tolerance
    assert analysis.max_iterations == dc.max_iterations
    assert analysis.initial_load_factor == mgdcm.initial_load_factor
    assert analysis.max_increments == mgdcm.max_increments
    assert analysis.max_load_factor == mgdcm.max_load_factor == math.inf


def test_the_specimens_parameters_are_the_cores():
    core, python = _core.model.SpecimenParameters(), SpecimenParameters()
    for name in ("kf", "valley_factor", "polygon_edge_factor", "spoke_factor",
                 "mountain_factor", "modulus_factor", "material_area", "mountain_area",
                 "duplicate_shared_edges"):
        assert getattr(python, name) == getattr(core, name), name
    np.testing.assert_array_equal(python.fold_limits, (core.theta1, core.theta2))
    assert _core.elements.BarLawKind(core.bar_law).name == python.bar_law


def test_a_changed_default_would_be_caught(monkeypatch):
    # Negative control: a Python default that drifts from the core's is reported.
    def drifted(model, prescribed, steps, *, shift=1e-7):
        pass
    core = _core.solvers.DisplacementControlOptions()
    assert inspect.signature(drifted).parameters["shift"].default != core.shift
