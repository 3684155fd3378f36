"""``method = "modes"`` in a problem file: masses from [material] and [[mass]], modes.csv and
the shapes as path.fold frames."""

import copy
import csv
import json

import numpy as np
import pytest

from kresling.analyses.modes import vibration_modes
from kresling.io import read_pattern
from kresling.model.masses import lumped_masses
from kresling.simulate import load_problem, simulate

GRID = [[x, y, 0.0] for y in (0.0, 10.0, 20.0) for x in (0.0, 10.0, 20.0)]
PROBLEM = {
    "pattern": {"vertices": GRID, "panels": [[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6],
                                             [4, 5, 8, 7]]},
    "material": {"calibration": "manual", "bar_modulus": 3e3, "bar_area": 1.0,
                 "fold_stiffness": 0.05, "bend_stiffness": 0.5, "thickness": 0.3,
                 "density": 1.38e-9},
    "support": [{"nodes": [0, 3, 6], "fix": "xyz"}],
    "mass": [{"nodes": [2, 8], "mass": 1e-6}],
    "analysis": {"method": "modes", "modes": 5},
}


def test_modes_run_matches_the_library(tmp_path):
    run = simulate(PROBLEM)
    extra = np.zeros(13)
    extra[[2, 8]] = 1e-6
    masses = lumped_masses(run.pattern_model, 0.3, 1.38e-9, extra=extra)
    np.testing.assert_array_equal(run.masses, masses)
    # The sheet's 400 mm^2 at 0.3 mm and 1.38e-9 t/mm^3, plus the two explicit masses.
    assert run.masses.sum() == pytest.approx(400 * 0.3 * 1.38e-9 + 2e-6, rel=1e-12)
    expected = vibration_modes(run.model, masses, k=5)
    written = run.write(tmp_path)
    with open(written["modes"]) as handle:
        rows = list(csv.DictReader(handle))
    assert [int(r["mode"]) for r in rows] == [1, 2, 3, 4, 5]
    # Mode 1 is the rigid rotation about the held line x = 0 (round-off frequency).
    assert [int(r["rigid"]) for r in rows] == [1, 0, 0, 0, 0]
    np.testing.assert_allclose([float(r["frequency_hz"]) for r in rows][1:],
                               expected.frequencies_hz[1:], rtol=1e-12)
    np.testing.assert_allclose([float(r["effective_mass_z"]) for r in rows],
                               expected.effective_mass_fraction[:, 2], rtol=1e-9, atol=1e-15)
    pattern = read_pattern(written["fold"])
    assert len(pattern.frames) == 5
    # Each frame is the rest state plus the mode's shape, largest node motion 2 mm (0.1 of 20).
    motion = np.asarray(pattern.frames[0]) - np.asarray(run.model.nodes)
    assert np.linalg.norm(motion, axis=1).max() == pytest.approx(2.0, rel=1e-9)
    summary = json.loads(written["summary"].read_text())
    assert summary["method"] == "modes" and summary["modes"] == 5


@pytest.mark.parametrize("change, match", [
    (lambda p: p["material"].pop("thickness"), r"\[material\] key 'density' needs"),
    (lambda p: (p["material"].pop("density"), p["material"].pop("thickness"),
                p.pop("mass")), "needs masses"),
    (lambda p: p.update(load=[{"node": 4, "force": [0, 0, 1.0]}]), "would have no effect"),
    (lambda p: p["analysis"].update(about="loaded"), r"\[analysis\] key 'about'"),
    (lambda p: p["mass"][0].update(mass=-1.0), r"\[mass\] key 'mass' = -1.0"),
    (lambda p: p["mass"][0].update(nodes=[13]), "out of range"),
])
def test_bad_modes_problems(change, match):
    problem = copy.deepcopy(PROBLEM)
    change(problem)
    with pytest.raises(ValueError, match=match):
        load_problem(problem)


def test_massless_free_node_is_named():
    problem = copy.deepcopy(PROBLEM)
    problem["material"].pop("density")
    problem["material"].pop("thickness")
    with pytest.raises(ValueError, match=r"zero at free node\(s\) \[1, 4, 5"):
        simulate(problem)


LOADED = dict(copy.deepcopy(PROBLEM),
              support=[{"nodes": [0, 3, 6], "fix": "xyz"}, {"node": 1, "fix": "z"}],
              load=[{"nodes": [2, 8], "force": [0.0, 0.0, -0.05]}],
              analysis={"method": "modes", "modes": 4,
                        "about": {"load_factor": 0.5, "steps": 4}})


def test_modes_about_a_loaded_state_are_the_library_s(tmp_path):
    """[analysis.about]: force control to the loaded equilibrium, then the modes of the
    tangent there (its stress stiffness included), bit for bit as from Python."""
    from kresling.simulate import build_problem_model
    from kresling.simulate.problem_keys.mass import problem_masses
    from kresling.solvers import solve_force_control

    run = simulate(LOADED)
    pm = build_problem_model(LOADED)
    forces = np.zeros(pm.model.num_dofs)
    forces[[3 * 2 + 2, 3 * 8 + 2]] = -0.05
    path = solve_force_control(pm.model, 0.5 * forces, 4,
                               tolerance=load_problem(LOADED).analysis.tolerance)
    expected = vibration_modes(pm.model, problem_masses(load_problem(LOADED), pm), k=4,
                               u=path.displacement[-1])
    np.testing.assert_array_equal(run.modes.frequencies_hz, expected.frequencies_hz)
    np.testing.assert_array_equal(run.state, path.displacement[-1])
    at_rest = simulate(dict(copy.deepcopy(LOADED), load=[],
                            analysis={"method": "modes", "modes": 4}))
    # The load moves the frequencies (a prestressed, displaced sheet), not by rounding.
    assert np.abs(run.modes.frequencies_hz / at_rest.modes.frequencies_hz - 1).max() > 1e-3
    written = run.write(tmp_path)
    assert json.loads(written["summary"].read_text())["about"] == {"load_factor": 0.5,
                                                                    "steps": 4}
    fold = json.loads(written["fold"].read_text())
    np.testing.assert_allclose(np.asarray(fold["vertices_coords"]),
                               pm.model.nodes + path.displacement[-1].reshape(-1, 3),
                               atol=1e-12)


@pytest.mark.parametrize("change, match", [
    (lambda p: p.pop("load"), r"loaded state: it needs \[\[load\]\] forces"),
    (lambda p: p["load"].append({"node": 4, "displacement": [0, 0, 1.0]}), "forces only"),
    (lambda p: p["analysis"]["about"].update(steps=0), r"\[analysis.about\] key 'steps'"),
    (lambda p: p["analysis"]["about"].update(extra=1), r"key 'extra' is unknown"),
    (lambda p: p["analysis"].update(about=3), r"must be \"rest\" or an \[analysis.about\]"),
])
def test_bad_loaded_states(change, match):
    problem = copy.deepcopy(LOADED)
    change(problem)
    with pytest.raises(ValueError, match=match):
        load_problem(problem)
