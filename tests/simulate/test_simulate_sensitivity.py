"""``[sensitivity]``: sensitivities.csv against central differences of the same problem run
again with the parameter moved."""

import copy
import csv

import numpy as np
import pytest

from kresling.simulate import load_problem, simulate

# One crease between two triangles, three corners held, the fourth pushed up 5 mm: the
# reaction there is the crease's and the bars' resistance.
SHEET = {
    "pattern": {"vertices": [[0.0, 0.0, 0.0], [20.0, 0.0, 0.0], [20.0, 20.0, 0.0],
                             [0.0, 20.0, 0.0]], "panels": [[0, 1, 2], [0, 2, 3]]},
    "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                 "fold_stiffness": 0.05},
    "support": [{"nodes": [0, 1, 2], "fix": "xyz"}],
    "load": [{"node": 3, "displacement": [0.0, 0.0, 5.0]}],
    # Newton to 1e-12 mm, so that the differences below carry only their own error.
    "analysis": {"method": "displacement_control", "steps": 5, "tolerance": 1e-12},
    "sensitivity": {"parameters": ["fold_stiffness", "bar_modulus", "bars.area",
                                   "vertices"]}}


# A triangle whose corner is pulled 0.5 mm along its plane: the bars stretch and carry it.
TRIANGLE = {
    "pattern": {"vertices": [[0.0, 0.0, 0.0], [20.0, 0.0, 0.0], [0.0, 20.0, 0.0]],
                "panels": [[0, 1, 2]]},
    "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0},
    "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"}, {"node": 2, "fix": "z"}],
    "load": [{"node": 2, "displacement": [0.0, 0.5, 0.0]}],
    "analysis": {"method": "displacement_control", "steps": 5, "tolerance": 1e-12},
    "sensitivity": {"parameters": ["bar_modulus", "bars.area"]}}


def _read(path):
    with open(path) as handle:
        rows = list(csv.DictReader(handle))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def _written(problem, directory):
    files = simulate(problem, progress=False).write(directory, view=False)
    return _read(files["sensitivities"])


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    return _written(SHEET, tmp_path_factory.mktemp("sheet"))


@pytest.fixture(scope="module")
def stretched(tmp_path_factory):
    return _written(TRIANGLE, tmp_path_factory.mktemp("triangle"))


def _reaction(problem):
    return simulate(problem, progress=False).path.constraint_force[:, 0]


def _central(problem, change, value, step):
    plus, minus = copy.deepcopy(problem), copy.deepcopy(problem)
    change(plus, value + step)
    change(minus, value - step)
    return (_reaction(plus) - _reaction(minus)) / (2 * step)


@pytest.mark.parametrize("sheet, name, change, value", [
    (True, "fold_stiffness", lambda p, v: p["material"].update(fold_stiffness=v), 0.05),
    (True, "vertices[3].x", lambda p, v: p["pattern"]["vertices"][3].__setitem__(0, v), 0.0),
    (True, "vertices[2].z", lambda p, v: p["pattern"]["vertices"][2].__setitem__(2, v), 0.0),
    (False, "bar_modulus", lambda p, v: p["material"].update(bar_modulus=v), 1e3),
    (False, "bars.area", lambda p, v: p["material"].update(bar_area=v), 1.0)])
def test_each_column_is_the_central_difference_of_runs_with_the_parameter_moved(
        written, stretched, sheet, name, change, value):
    problem, files, column = ((SHEET, written, "reaction_3_z") if sheet else
                              (TRIANGLE, stretched, "reaction_2_y"))
    exact = files[f"d({column})/d({name})"]
    step = 1e-4 * max(abs(value), 1.0)
    # A central difference errs by ~h^2 f''' and by the runs' rounding (1e-12 mm Newton
    # tolerance, forces of ~1e-2 N) over 2h: 1e-6 of the largest entry bounds both here.
    np.testing.assert_allclose(exact, _central(problem, change, value, step),
                               atol=1e-6 * np.abs(exact).max())
    assert np.abs(exact).max() > 0


def test_energy_total_has_its_derivative_and_the_rows_follow_the_history(written):
    assert list(written["step"]) == [1, 2, 3, 4, 5]
    assert "d(energy_total)/d(fold_stiffness)" in written
    # The stored energy is the crease's 1/2 k theta^2 and the bars': by k it grows.
    assert np.all(written["d(energy_total)/d(fold_stiffness)"] > 0)


@pytest.mark.parametrize("parameters, match", [
    ([], "must be a non-empty list"),
    (["E"], r"has 'E': not a number of this problem's \[material\]"),
    (["bars.modulus", "bars.modulus"], "names a parameter twice"),
    (["bars"], r"has 'bars': not a number"),
    (["bars.modulus[x]"], "has 'bars.modulus\\[x\\]'")])
def test_bad_parameters_are_refused_naming_the_key(parameters, match):
    with pytest.raises(ValueError, match=r"\[sensitivity\] key 'parameters'.*" + match):
        load_problem({**SHEET, "sensitivity": {"parameters": parameters}})


def test_a_parameter_the_model_has_not_and_a_method_without_a_path_are_refused(tmp_path):
    # Before the run, as the model is built.
    with pytest.raises(ValueError, match="'springs.anchor' is not a parameter of this model"):
        simulate({**SHEET, "sensitivity": {"parameters": ["springs.anchor"]}}, progress=False)
    with pytest.raises(ValueError, match=r"\[sensitivity\] differentiates a path"):
        load_problem({**SHEET, "load": [], "mass": [{"node": 3, "mass": 1e-6}],
                      "analysis": {"method": "modes"}})
