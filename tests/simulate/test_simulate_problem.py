"""Problem files: bad input gets a ValueError naming the file, the key and what is allowed
(the CLI: one line on stderr, exit 2); a path that stops early says why (exit 1)."""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling.simulate import load_problem, simulate

# A 2 x 1 strip of squares, folded about its middle crease by a force at a far corner.
VALID = """\
[pattern]
file = "strip.obj"
split = "N5B8"

[material]
calibration = "auto"
E = 1000.0
nu = 0.3
thickness = 0.25

[[support]]
nodes = [0, 3]
fix = "xyz"
[[support]]
node = 1
fix = "z"

[[load]]
node = 2
force = [0.0, 0.0, 0.01]

[analysis]
method = "force_control"
steps = 5
"""

STRIP_OBJ = """\
v 0 0 0
v 10 0 0
v 20 0 0
v 0 10 0
v 10 10 0
v 20 10 0
f 1 2 5 4
f 2 3 6 5
"""


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "strip.obj").write_text(STRIP_OBJ)
    (tmp_path / "problem.toml").write_text(VALID)
    return tmp_path


def write(folder, text, name="bad.toml"):
    path = folder / name
    path.write_text(text)
    return path


def test_valid_problem_runs(folder):
    sim = simulate(folder / "problem.toml", progress=False)
    assert sim.completed and sim.path.num_steps == 5
    assert sim.model.num_nodes == 8  # 6 vertices and 2 centre nodes
    # The load lifts the free corner: its z grows with the load factor.
    z = sim.path.displacement[:, 3 * 2 + 2]
    assert np.all(np.diff(z) > 0)


@pytest.mark.parametrize("edit, match", [
    (("thickness = 0.25", "thickness = 0.25\ncolour = 'red'"),
     r"bad.toml:\d+: \[material\] key 'colour' is unknown: allowed keys are"),
    (("thickness = 0.25\n", ""), r"\[material\] key 'thickness' is missing"),
    (('split = "N5B8"', 'split = "N6B9"'),
     r"\[pattern\] key 'split' = 'N6B9' is invalid: must be one of \['N4B5', 'N5B8'\]"),
    (('calibration = "auto"', 'calibration = "magic"'),
     r"key 'calibration' = 'magic' is invalid: must be one of \['auto', 'manual'\]"),
    (("node = 2\nforce", "node = 8\nforce"), r"\[load\] key 'node' = 8 is out of range: nodes "
                                             r"are numbered 0 to 7"),
    (('method = "force_control"', 'method = "arc_length"'),
     r"key 'method' = 'arc_length' is invalid: must be one of"),
    (("steps = 5", "steps = 0"), r"key 'steps' = 0 is invalid"),
    (("steps = 5", "steps = 2.5"), r"key 'steps' = 2.5 is invalid: must be an integer"),
    (('fix = "z"', 'fix = "w"'), r"\[support\] key 'fix' = 'w' is invalid"),
    (("[analysis]", "[analysis]\nmethod2 = 1"), r"\[analysis\] key 'method2' is unknown"),
    (("E = 1000.0", "E = -1000.0"), r"key 'E' = -1000.0 is invalid: must be > 0"),
    (("nu = 0.3", "nu = 0.7"), r"key 'nu' = 0.7 is invalid: must be in \(-1, 0.5\]"),
    (('file = "strip.obj"', 'file = "missing.obj"'), r"key 'file' = 'missing.obj': no such file"),
    (("[analysis]", "[laws]\nfold = 'rubber'\n[analysis]"),
     r"\[laws\] key 'fold' = 'rubber' is invalid: must be one of"),
    (("[analysis]", "[laws]\nfold_limits_deg = [300.0, 20.0]\n[analysis]"),
     r"key 'fold_limits_deg' = \[300.0, 20.0\] is invalid"),
    (("force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 1.0]"),
     r"key 'method' = 'force_control' needs every \[\[load\]\] to be a force"),
])
def test_bad_keys_are_named(folder, edit, match):
    old, new = edit
    assert old in VALID
    with pytest.raises(ValueError, match=match):
        load_problem(write(folder, VALID.replace(old, new, 1)))


def test_toml_syntax_error_names_line_and_column(folder):
    with pytest.raises(ValueError, match=r"bad.toml: not valid TOML: .*line 3, column"):
        load_problem(write(folder, VALID.replace('split = "N5B8"', "split = N5B8")))


def test_missing_table(folder):
    text = VALID.replace("[analysis]\nmethod = \"force_control\"\nsteps = 5\n", "")
    with pytest.raises(ValueError, match=r"key 'analysis' is missing"):
        load_problem(write(folder, text))


def test_supported_and_driven_dof(folder):
    text = VALID.replace('method = "force_control"', 'method = "displacement_control"').replace(
        "force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 1.0]").replace(
        'node = 1\nfix = "z"', 'node = 2\nfix = "z"')
    with pytest.raises(ValueError, match=r"load\[0\] drives node 2 along z, which a "
                                         r"\[\[support\]\] fixes"):
        load_problem(write(folder, text))


def test_under_constrained_model(folder):
    text = VALID.replace('[[support]]\nnode = 1\nfix = "z"\n', "")
    with pytest.raises(ValueError, match=r"bad.toml: .*rigid-body"):
        simulate(write(folder, text), progress=False)


def test_dict_problem_names_its_keys(folder):
    problem = {"pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "panels": [[0, 1, 2]]},
               "material": {"calibration": "manual", "bar_modulus": 1.0, "bar_area": 1.0},
               "analysis": {"method": "force_control", "steps": 2},
               "load": [{"node": 2, "force": [0, 1, 0]}]}
    bad = copy.deepcopy(problem)
    bad["load"][0]["force"] = [0, 1]
    with pytest.raises(ValueError, match=r"problem: \[load\] key 'force' = \[0, 1\] is invalid"):
        load_problem(bad)
    bad = copy.deepcopy(problem)
    bad["extra"] = {}
    with pytest.raises(ValueError, match=r"key 'extra' is unknown"):
        load_problem(bad)


def test_cli_bad_problem_is_one_line_and_exit_2(folder):
    write(folder, VALID.replace('split = "N5B8"', 'split = "N6B9"'))
    result = run_kresling("simulate", "bad.toml", "--out", "out", cwd=folder)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "key 'split' = 'N6B9'" in lines[0]
    assert "Traceback" not in result.stderr


def test_cli_path_that_stops_early_exits_1_and_keeps_its_increments(folder):
    # Force control cannot pass the strip's stiffening: far too large a load in one step.
    text = VALID.replace("force = [0.0, 0.0, 0.01]", "force = [0.0, 0.0, 1e6]").replace(
        "steps = 5", "steps = 1\nmax_iterations = 3")
    write(folder, text)
    result = run_kresling("simulate", "bad.toml", "--out", "out", "--no-view", "--json",
                          cwd=folder)
    assert result.returncode == 1, result.stderr
    summary = json.loads(result.stdout)
    assert summary["completed"] is False and summary["message"]
    assert "stopped early" in result.stderr
    assert (folder / "out" / "history.csv").is_file()


def test_python_stopping_rule(folder):
    sim = simulate(folder / "problem.toml", progress=False,
                   stop=lambda state: state.displacement[2, 2] > 0.0 and state.step >= 3)
    assert sim.completed and sim.path.num_steps == 3


def test_monitor_stop_under_displacement_control(folder):
    text = VALID.replace('method = "force_control"', 'method = "displacement_control"').replace(
        "force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 4.0]").replace(
        "steps = 5", "steps = 8\nstop = { node = 2, axis = \"z\", beyond = 1.2 }")
    sim = simulate(write(folder, text), progress=False)
    z = sim.path.displacement[:, 3 * 2 + 2]
    # 0.5 mm per increment: the first increment past 1.2 mm is the third.
    assert sim.completed and sim.path.num_steps == 3 and z[-1] > 1.2 >= z[-2]


def test_progress_bar_does_not_count_as_a_stopping_rule():
    # An MGDCM run without a stop completes when its increments run out, bar or no bar.
    from pathlib import Path
    problem = Path(__file__).resolve().parents[1] / "data" / "merlin2_examples" / "kresling_folding" / \
        "problem.toml"
    shown = simulate(problem, progress=True)
    hidden = simulate(problem, progress=False)
    assert shown.completed and hidden.completed
    np.testing.assert_array_equal(shown.path.displacement, hidden.path.displacement)


def test_adaptive_increments_keep_the_samples(folder):
    # The strip folded by a prescribed 4 mm at its far corner in 40 samples: adaptive
    # increments give the same 40 samples (load factors k/40, to rounding) as fixed steps, to the
    # adaptive samples' accuracy, in fewer Newton iterations. Measured: the reaction within
    # 2e-10 of its largest value, displacements within 1.9e-7 mm, 68 iterations against 367.
    # Bounds: 1e-6 of the reaction and 1e-5 mm (the samples' stated 1e-8-1e-9 of the drive's
    # force, plus what the Newton tolerance, 1e-6 mm, leaves in each path).
    fixed_text = VALID.replace('method = "force_control"', 'method = "displacement_control"') \
        .replace("force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 4.0]") \
        .replace("steps = 5", "steps = 40")
    fixed = simulate(write(folder, fixed_text), progress=False)
    adaptive = simulate(write(folder, fixed_text.replace("steps = 40",
                                                          'steps = 40\nincrements = "adaptive"')),
                        progress=False)
    assert fixed.completed and adaptive.completed
    np.testing.assert_allclose(adaptive.path.load_factor, np.arange(1, 41) / 40, rtol=1e-15)
    np.testing.assert_allclose(fixed.path.load_factor, adaptive.path.load_factor, rtol=1e-15)
    reaction = lambda sim: np.asarray(sim.path.constraint_force)[:, 0]
    scale = np.abs(reaction(fixed)).max()
    assert np.abs(reaction(adaptive) - reaction(fixed)).max() <= 1e-6 * scale
    assert np.abs(adaptive.path.displacement - fixed.path.displacement).max() <= 1e-5
    assert adaptive.path.iterations.sum() < fixed.path.iterations.sum()


def test_extrapolated_predictors_keep_the_equilibria(folder):
    # The strip folded 4 mm in 40 fixed increments, each Newton solve started from the last
    # equilibrium or from a linear, quadratic or cubic extrapolation of the path: the same
    # samples and equilibria to what the Newton tolerance (1e-6 mm) leaves, in fewer
    # iterations. Measured: displacements within 4.0e-8 mm, reactions within 2.4e-9 of their
    # largest value (the bound: the 1e-8 the samples of adaptive increments promise); 367
    # iterations from the last equilibrium, 85 with the cubic.
    text = VALID.replace('method = "force_control"', 'method = "displacement_control"') \
        .replace("force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 4.0]") \
        .replace("steps = 5", "steps = 40")
    runs = {p: simulate(write(folder, text.replace("steps = 40",
                                                   f'steps = 40\npredictor = "{p}"')),
                        progress=False)
            for p in ("previous", "linear", "quadratic", "cubic")}
    previous = runs["previous"]
    scale = np.abs(np.asarray(previous.path.constraint_force)).max()
    stepping = {name: run.summary()["stepping"] for name, run in runs.items()}
    assert stepping["previous"] == "equal increments, each started from the previous equilibrium"
    assert stepping["cubic"] == "equal increments, each started from a cubic extrapolation"
    for name, run in runs.items():
        assert run.completed and run.problem.analysis.predictor == name
        np.testing.assert_allclose(run.path.load_factor, np.arange(1, 41) / 40, rtol=1e-15)
        assert np.abs(run.path.displacement - previous.path.displacement).max() <= 1e-6
        difference = np.asarray(run.path.constraint_force) - previous.path.constraint_force
        assert np.abs(difference).max() <= 1e-8 * scale
    assert runs["cubic"].path.iterations.sum() < 0.5 * previous.path.iterations.sum()


def test_summary_says_how_the_path_was_stepped(folder):
    displacement = VALID.replace('method = "force_control"', 'method = "displacement_control"') \
        .replace("force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 1.0]")
    cases = {VALID: "equal load increments",
             displacement: "equal increments, each started from the previous equilibrium",
             displacement.replace("steps = 5", 'steps = 5\nincrements = "adaptive"'):
                 "adaptive increments, the equal samples read off the path between them"}
    for text, stepping in cases.items():
        assert simulate(write(folder, text), progress=False).summary()["stepping"] == stepping


def test_predictor_is_for_fixed_increments_of_displacement_control(folder):
    base = VALID.replace('method = "force_control"', 'method = "displacement_control"') \
        .replace("force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 4.0]")
    text = base.replace("steps = 5", 'steps = 5\nincrements = "adaptive"\npredictor = "cubic"')
    with pytest.raises(ValueError, match=r"\[analysis\] key 'predictor' applies to fixed "
                                         r"increments only"):
        load_problem(write(folder, text))
    text = base.replace("steps = 5", 'steps = 5\npredictor = "spline"')
    with pytest.raises(ValueError, match=r"predictor.*'spline'.*previous.*linear.*quadratic"
                                         r".*cubic"):
        load_problem(write(folder, text))
    with pytest.raises(ValueError, match=r"predictor"):  # force control has no predictor
        load_problem(write(folder, VALID.replace("steps = 5", 'steps = 5\npredictor = "cubic"')))


def test_adaptive_increments_are_for_displacement_control(folder):
    text = VALID.replace("steps = 5", 'steps = 5\nincrements = "adaptive"')
    with pytest.raises(ValueError, match=r"increments"):
        load_problem(write(folder, text))
    text = VALID.replace('method = "force_control"', 'method = "displacement_control"') \
        .replace("force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 4.0]") \
        .replace("steps = 5", 'steps = 5\nincrements = "smart"')
    with pytest.raises(ValueError, match=r"increments.*'smart'.*fixed.*adaptive"):
        load_problem(write(folder, text))
