"""``method = "dynamic"`` in a problem file: [dynamics], each [[load]]'s time, the run
against the library, its files, the example's snap in time, and bad input."""

import copy
import csv
import json
import re
from pathlib import Path

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling.analyses.modes import vibration_modes
from kresling.assembly import assemble
from kresling.simulate import build_problem_model, load_problem, simulate
from kresling.simulate.problem_keys.mass import problem_masses
from kresling.solvers import solve_dynamics, solve_force_control

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "kresling_snap_in_time"
# A triangle of bars, node 0 held, node 1 on a roller along x, node 2 in the plane.
PROBLEM = {
    "pattern": {"vertices": [[0, 0, 0], [10, 0, 0], [0, 10, 0]], "panels": [[0, 1, 2]]},
    "material": {"calibration": "manual", "bar_modulus": 500.0, "bar_area": 1.0},
    "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"}, {"node": 2, "fix": "z"}],
    "mass": [{"nodes": [1, 2], "mass": 1e-4}],
    "load": [{"node": 2, "force": [0.0, 5.0, 0.0], "time": "ramp", "ramp_time": 0.01},
             {"node": 1, "force": [0.5, 0.0, 0.0],
              "time": {"harmonic": [1.0, 40.0]}}],
    "dynamics": {"scheme": "newmark", "time_step": 1e-3, "duration": 0.2,
                 "damping": {"alpha": 20.0, "beta": 1e-4}, "gravity": [0.0, -9810.0, 0.0]},
    "analysis": {"method": "dynamic", "tolerance": 1e-10},
}


def test_a_dynamic_run_is_the_library_s_integration(tmp_path):
    run = simulate(PROBLEM)
    assert run.completed and run.path.num_steps == 200
    pm = build_problem_model(PROBLEM)
    masses = problem_masses(load_problem(PROBLEM), pm)
    f2, f1 = np.zeros(9), np.zeros(9)
    f2[7], f1[3] = 5.0, 0.5
    h = solve_dynamics(pm.model, masses, 1e-3, 0.2, gravity=(0, -9810.0, 0),
                       loads=[(f2, [[0, 0], [0.01, 1]]), (f1, {"harmonic": (1.0, 40.0)})],
                       mass_damping=20.0, stiffness_damping=1e-4, tolerance=1e-10)
    np.testing.assert_array_equal(run.path.displacement, h.path.displacement)
    np.testing.assert_array_equal(run.history.velocity, h.velocity)
    written = run.write(tmp_path)
    rows = list(csv.DictReader(written["history"].open()))
    assert list(rows[0])[:6] == ["step", "time", "energy_kinetic", "energy_strain",
                                 "energy_damping", "work_external"]
    np.testing.assert_allclose([float(r["time"]) for r in rows], h.time, rtol=1e-15)
    np.testing.assert_allclose([float(r["work_external"]) for r in rows], h.work, rtol=1e-15)
    velocities = np.loadtxt(written["velocities"], delimiter=",", skiprows=1)
    np.testing.assert_allclose(velocities, h.velocity, rtol=1e-15)
    summary = json.loads(written["summary"].read_text())
    assert summary["scheme"] == "newmark" and summary["final_time"] == pytest.approx(0.2)
    assert summary["total_mass_t"] == pytest.approx(2e-4)


def test_the_view_plays_in_scaled_real_time(tmp_path):
    run = simulate(PROBLEM)
    page = run.write(tmp_path)["view"].read_text()
    figure = json.loads(re.search(r'id="kresling-figure">(.*?)</script>', page).group(1))
    frames = figure["frames"]
    # The 0.2 s motion in 5 s: 25 wall seconds per second, each frame at its own time.
    assert frames["scale"] == pytest.approx(25.0)
    assert frames["times"] == pytest.approx(list(run.history.time[frames["rows"]]))
    assert "scaled by 25" in page
    fold = json.loads((tmp_path / "path.fold").read_text())
    assert fold["file_frames"][0]["frame_title"] == "t = 0.001 s"


def test_a_damped_run_settles_on_the_static_equilibrium():
    problem = copy.deepcopy(PROBLEM)
    problem["load"] = [{"node": 2, "force": [0.0, 5.0, 0.0]}]       # a step, by default
    problem["dynamics"].update(duration=2.0, damping={"alpha": 20.0})
    problem["dynamics"].pop("gravity")
    run = simulate(problem)
    force = np.zeros(9)
    force[7] = 5.0
    static = solve_force_control(run.model, force, 5, tolerance=1e-12)
    # Released from rest with damping, it comes to rest where force control puts it: to
    # 1e-7 mm, Newton's 1e-10 mm and the damped tail's e^(-10 t) = 2e-9 of the motion.
    np.testing.assert_allclose(run.path.displacement[-1], static.displacement[-1], atol=1e-7)
    residual = assemble(run.model, run.path.displacement[-1], stiffness=False).force - force
    assert np.abs(residual[~run.model.fixed.ravel()]).max() < 1e-6   # N, on a 5 N load


@pytest.fixture(scope="module")
def snap():
    return simulate(EXAMPLE / "problem.toml", progress=False)


def test_the_example_snaps_and_rests_in_the_symmetric_contracted_state(snap):
    """What examples/kresling_snap_in_time/problem.toml's header says."""
    assert snap.completed and snap.path.num_steps == 1500
    h = snap.history
    top = snap.path.displacement[:, 3 * 10 + 2:3 * 20:3].mean(axis=1)
    lowest = int(np.argmin(top))
    assert top[lowest] == pytest.approx(-44.6, abs=0.05) and h.time[lowest] < 0.02
    assert top[-1] == pytest.approx(-38.64, abs=0.01)
    # At rest: a static equilibrium of the unloaded cell (the force residual below what a
    # 1e-6 mm Newton correction leaves on its ~100 N/mm stiffness), stable along the axis
    # and unstable to tilting: the lowest pair of modes about it has omega^2 < 0 (-6.1 Hz
    # as the modes report it), the next a real frequency.
    u = snap.path.displacement[-1]
    residual = assemble(snap.model, u, stiffness=False).force[~snap.model.fixed.ravel()]
    assert np.abs(residual).max() < 1e-4 and h.kinetic[-1] < 1e-9
    modes = vibration_modes(snap.model, snap.masses, k=3, u=u)
    assert modes.frequencies_hz[:2] == pytest.approx([-6.09, -6.09], abs=0.01)
    assert modes.frequencies_hz[2] > 10.0
    # The energy balance: work = stored + dissipated + HHT's own loss, that loss positive
    # and a small part of the work.
    loss = h.work[-1] - h.strain[-1] - h.dissipated[-1] - h.kinetic[-1]
    assert 0 < loss < 0.05 * h.work[-1]


def test_the_explicit_scheme_refuses_a_step_above_its_stable_one_and_reports_it():
    problem = copy.deepcopy(PROBLEM)
    problem["dynamics"] = {"scheme": "explicit", "time_step": 0.01, "duration": 0.05}
    with pytest.raises(ValueError, match=r"\[dynamics\]: time_step = 0.01 s is above the "
                                         r"explicit scheme's stable step"):
        simulate(problem)
    problem["dynamics"].update(time_step=1e-4, duration=0.01, record_every=10)
    run = simulate(problem)
    assert run.completed and run.path.num_steps == 10
    summary = run.summary()
    assert 1e-4 < summary["stable_time_step"] < 1e-2 and summary["time_step"] == 1e-4


@pytest.mark.parametrize("change, match", [
    (lambda p: p["dynamics"].update(scheme="rk4"), r"\[dynamics\] key 'scheme' = 'rk4'"),
    (lambda p: p["dynamics"].pop("time_step"), r"\[dynamics\] key 'time_step' is missing"),
    (lambda p: p["dynamics"].update(duration=-1.0), r"key 'duration' = -1.0 is invalid"),
    (lambda p: p["dynamics"].update(hht_alpha=-0.1), "applies only with scheme = 'hht'"),
    (lambda p: p["dynamics"].update(scheme="hht", hht_alpha=-0.5), r"in \[-1/3, 0\]"),
    (lambda p: p["dynamics"].update(record_every=5), "applies only with scheme = 'explicit'"),
    (lambda p: p["dynamics"].update(damping={"gamma": 1.0}), r"key 'damping'"),
    (lambda p: p["dynamics"].update(damping={"alpha": -1.0}), "alpha = -1.0 is invalid"),
    (lambda p: p["dynamics"].update(gravity=[0, 0]), r"key 'gravity'"),
    (lambda p: p["dynamics"].update(extra=1), r"key 'extra' is unknown"),
    (lambda p: p.pop("dynamics"), r"needs a \[dynamics\] table"),
    (lambda p: p["analysis"].update(method="force_control", steps=3),
     r"\[dynamics\] applies only with \[analysis\] method = 'dynamic'"),
    (lambda p: p["load"][0].pop("ramp_time"), r"key 'ramp_time' is missing"),
    (lambda p: p["load"][0].update(time="step"), "applies only with time = \"ramp\""),
    (lambda p: (p["load"][0].pop("ramp_time"), p["load"][0].update(time="sine")),
     r"key 'time' = 'sine' is invalid"),
    (lambda p: (p["load"][0].pop("ramp_time"), p["load"][0].update(time=[[0.1, 1], [0.0, 0]])),
     "they must increase"),
    (lambda p: (p["load"][0].pop("ramp_time"), p["load"][0].update(time=[[0.1, 1, 2]])),
     r"each row is \[t, factor\]"),
    (lambda p: p["load"][1].update(time={"harmonic": [1.0, 0.0]}), "frequency must be > 0"),
    (lambda p: p["load"][1].update(time={"sine": [1.0, 2.0]}), r"harmonic = \[amplitude"),
    (lambda p: p["load"].append({"node": 2, "displacement": [0, 1.0, 0]}), "force loads only"),
    (lambda p: p.pop("mass"), "needs masses"),
])
def test_bad_dynamic_problems(change, match):
    problem = copy.deepcopy(PROBLEM)
    change(problem)
    with pytest.raises(ValueError, match=match):
        load_problem(problem)


def test_a_load_s_time_outside_a_dynamic_run_is_refused():
    problem = copy.deepcopy(PROBLEM)
    problem.pop("dynamics")
    problem["analysis"] = {"method": "force_control", "steps": 3}
    with pytest.raises(ValueError, match=r"load\[0\] key 'time' applies only with"):
        load_problem(problem)


def test_the_command_line_runs_the_example_and_names_a_bad_key(tmp_path):
    result = run_kresling("simulate", str(EXAMPLE / "problem.toml"), "--out",
                          str(tmp_path / "out"), "--quiet", "--no-view", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "stable_time_step" in result.stdout and "velocities.csv" in result.stdout
    bad = tmp_path / "bad.toml"
    bad.write_text((EXAMPLE / "problem.toml").read_text()
                   .replace('scheme = "hht"', 'scheme = "leapfrog"')
                   .replace("../kresling_tower", str(EXAMPLE.parent / "kresling_tower")))
    result = run_kresling("simulate", str(bad), "--out", str(tmp_path / "bad"), cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert re.search(r"bad.toml:\d+: \[dynamics\] key 'scheme' = 'leapfrog'", result.stderr)
