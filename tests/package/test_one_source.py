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
from kresling.simulate.problem_keys.analysis import Analysis
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
     ("tolerance", "max_iterations", "max_bisections", "extrapolation", "shift", "adaptive",
      "adaptive_tolerance")),
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


def test_the_specimens_edge_families_are_the_cores_enum():
    from kresling.model import EDGE_FAMILIES, kresling_specimen
    from kresling import Design
    codes = {name: int(value) for name, value in _core.model.EdgeFamily.__members__.items()}
    assert sorted(codes.values()) == list(range(len(EDGE_FAMILIES)))
    assert EDGE_FAMILIES == tuple(sorted(codes, key=codes.get))
    # The names a built specimen reports are the core's codes read through that table.
    specimen = kresling_specimen(Design(6, 0.8, 20), [1])
    core = _core.model.build_kresling_specimen(Design(6, 0.8, 20)._core, [1], [1],
                                               SpecimenParameters().to_core(), [])
    assert [codes[f] for f in specimen.hinge_family] == list(core.hinge_family)
    assert [codes[f] for f in specimen.bar_family] == list(core.bar_family)


def test_the_fold_assignment_tables_derive_from_one():
    from kresling.model.crease_kinds import FAMILY_OF_FOLD, FAMILY_OF_LETTER, FOLD_FAMILIES
    from kresling.model.crease_laws import CreaseLaws, HingeLaw
    from kresling.model.pattern_model import FAMILY_OF_ASSIGNMENT
    from kresling.model.pattern_model import FOLD_FAMILIES as pattern_fold_families
    from kresling.simulate.fold_plan import _FOLD_FAMILIES
    from kresling.simulate.outputs import _ASSIGNMENT
    from kresling.simulate.problem_keys.actuation import ACTUATION_FAMILIES
    from kresling.view.pattern_file import ASSIGNMENT_FAMILIES
    assert FOLD_FAMILIES == tuple(FAMILY_OF_FOLD.values()) == pattern_fold_families
    assert FAMILY_OF_ASSIGNMENT is FAMILY_OF_FOLD
    assert ASSIGNMENT_FAMILIES is FAMILY_OF_LETTER
    assert {k: FAMILY_OF_LETTER[k] for k in FAMILY_OF_FOLD} == dict(FAMILY_OF_FOLD)
    assert ACTUATION_FAMILIES == FOLD_FAMILIES + ("join", "fold")
    assert _FOLD_FAMILIES == FOLD_FAMILIES + ("join",)
    assert all(_ASSIGNMENT[family] == letter for letter, family in FAMILY_OF_FOLD.items())
    # The crease laws know the fold families and no other.
    with pytest.raises(ValueError, match="polygon_edge"):
        CreaseLaws(families={"polygon_edge": HingeLaw()})


def test_the_shared_literals_come_from_the_core():
    # shift, kf and initial_load_factor are declared in the core's structs; Python reads
    # them (or, where it must repeat one, is held to it here).
    from kresling.cli._specimen import add_specimen_arguments
    import argparse
    from kresling.simulate import load_problem
    parser = argparse.ArgumentParser()
    add_specimen_arguments(parser)
    assert parser.get_default("kf") == _core.model.SpecimenParameters().kf == \
        SpecimenParameters().kf
    mgdcm = _core.solvers.MgdcmOptions()
    read = load_problem({"pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                                     "panels": [[0, 1, 2]]},
                         "material": {"calibration": "manual", "bar_modulus": 1e3,
                                      "bar_area": 1.0},
                         "load": [{"node": 2, "force": [0.0, 0.0, 1.0]}],
                         "analysis": {"method": "mgdcm"}})
    assert read.analysis.initial_load_factor == mgdcm.initial_load_factor
    assert Analysis(method="mgdcm").initial_load_factor == mgdcm.initial_load_factor
    for function, options in ((solve_displacement_control,
                               _core.solvers.DisplacementControlOptions),
                              (solve_fold, _core.solvers.FoldOptions),
                              (solve_force_control, _core.solvers.ForceControlOptions),
                              (solve_mgdcm, _core.solvers.MgdcmOptions)):
        assert inspect.signature(function).parameters["shift"].default == options().shift


# The [analysis] table of docs/simulate.md against the defaults and bounds the code has.
def _analysis_rows():
    from pathlib import Path
    text = (Path(__file__).resolve().parents[2] / "docs" / "simulate.md").read_text()
    table = text[text.index("## `[analysis]`"):]
    table = table[:table.index("\n\n", table.index("| key |"))]
    rows = {}
    for line in table.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 4 and cells[0].startswith("`"):
            rows[cells[0].strip("`")] = cells
    return rows


def test_the_analysis_tables_defaults_and_bounds_are_the_codes():
    rows = _analysis_rows()
    analysis = Analysis(method="displacement_control")
    mgdcm = _core.solvers.MgdcmOptions()
    assert rows["initial_load_factor"][2] == f"`{mgdcm.initial_load_factor:g}`"
    assert rows["max_increments"][2] == f"`{mgdcm.max_increments}`" == \
        f"`{analysis.max_increments}`"
    assert rows["max_iterations"][2] == f"`{analysis.max_iterations}`"
    assert rows["max_iterations"][1] == f"integer in [1, {_core.solvers.MAX_ITERATIONS}]"
    assert rows["steps"][1] == rows["max_increments"][1] == \
        f"integer in [1, {_core.solvers.MAX_STEPS}]"
    assert rows["increments"][2] == f"`\"{analysis.increments}\"`"
    assert rows["predictor"][2] == f"`\"{analysis.predictor}\"`"
    from kresling.simulate.methods import method_names
    from kresling.simulate.methods.path_settings import INCREMENTS, PREDICTORS
    METHODS = method_names()
    for key, choices in (("increments", INCREMENTS), ("predictor", PREDICTORS),
                         ("method", METHODS)):
        named = [c.strip('"') for c in rows[key][1].replace(" or ", ", ").split(", ")]
        assert [c.strip('`"') for c in named] == list(choices), key


def test_the_damping_tangents_default_is_one_in_the_core_the_library_and_the_file():
    from pathlib import Path

    from kresling.simulate.problem_keys.dynamics import DAMPING_TANGENTS, Dynamics
    from kresling.solvers import solve_dynamics
    from kresling.solvers.dynamics import DAMPING_TANGENTS as LIBRARY_TANGENTS

    assert _core.solvers.TimeIntegrationOptions().damping_current_tangent is False
    default = inspect.signature(solve_dynamics).parameters["damping_tangent"].default
    assert default == Dynamics("newmark", 1.0, 1.0).damping_tangent == "initial"
    assert DAMPING_TANGENTS == LIBRARY_TANGENTS
    text = (Path(__file__).resolve().parents[2] / "docs" / "simulate.md").read_text()
    row = next(line for line in text.splitlines() if line.startswith("| `damping_tangent` |"))
    cells = [c.strip() for c in row.strip("|").split("|")]
    assert cells[1] == " or ".join(f'`"{t}"`' for t in DAMPING_TANGENTS)
    assert cells[2] == f'`"{default}"`'
