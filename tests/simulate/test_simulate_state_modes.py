"""Vibration modes about a fold's end state: those of the model the state is an equilibrium
of (the crease at its reached rest angle), which is the sheet built stress-free in its folded
shape."""

import numpy as np
import pytest

from small_models import CREASED_SQUARE
from kresling.analyses.modes import vibration_modes
from kresling.simulate import build_problem_model, load_problem, modes_at, simulate
from kresling.simulate.problem_keys.mass import problem_masses

# The crease folded to 90 deg.
SHEET = {
    **CREASED_SQUARE,
    "actuation": [{"edges": [[0, 2]], "fold_angle_deg": 90.0}],
    "analysis": {"method": "fold", "steps": 10, "tolerance": 1e-12}}


@pytest.fixture(scope="module")
def folded():
    return simulate(SHEET, progress=False)


def test_the_folded_states_modes_are_those_of_the_sheet_built_folded(folded):
    assert folded.completed
    end = folded.model.nodes + folded.path.displacement[-1].reshape(-1, 3)
    rebuilt = {**SHEET, "pattern": {**SHEET["pattern"], "vertices": end.tolist()}}
    rebuilt.pop("actuation")
    rebuilt["analysis"] = {"method": "modes", "modes": 3}
    problem = load_problem(rebuilt)
    pm = build_problem_model(problem)
    expected = vibration_modes(pm.model, problem_masses(problem, pm), k=3)
    modes = modes_at(folded, k=3)
    # The fold ends within 1e-12 mm of the stress-free folded shape: the frequencies agree
    # to the tangent's rounding.
    np.testing.assert_allclose(modes.frequencies_hz, expected.frequencies_hz, rtol=1e-8)


def test_the_as_built_rest_angles_would_give_other_modes(folded):
    # The flat rest angle leaves the crease pushing back at 90 deg: its moment adds M d2theta
    # to the tangent, which moves the crease mode by 1.7e-4 here (the mode turns the panel
    # about the crease, where theta is nearly linear): 1e4 times the agreement above.
    masses = problem_masses(folded.problem, folded.pattern_model)
    as_built = vibration_modes(folded.model, masses, k=3, u=folded.path.displacement[-1])
    right = modes_at(folded, k=3)
    assert np.max(np.abs(as_built.frequencies_hz / right.frequencies_hz - 1)) > 1e-5
    # Halfway, the rest angle is 45 deg: the model there differs from the end's.
    assert not np.allclose(folded.model_at(4).hinge_rest_angle,
                           folded.model_at(-1).hinge_rest_angle)


def test_bad_steps_and_missing_masses_are_refused(folded):
    with pytest.raises(ValueError, match=r"step = 10 is out of range: the path has 10 steps"):
        modes_at(folded, step=10)
    run = simulate({**SHEET, "mass": []}, progress=False)
    with pytest.raises(ValueError, match="the modes need masses"):
        modes_at(run)
