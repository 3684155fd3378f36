"""The [output] table and --every: every k-th increment kept (the last always), the view's
curve named or chosen by the method, the warning before large outputs."""

from __future__ import annotations

import csv
import json
import logging
import re

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling.io import read_fold
from kresling.simulate import load_problem, simulate
from test_simulate_problem import STRIP_OBJ, VALID

# The strip driven by a displacement of its far corner instead of a force.
DRIVEN = VALID.replace("force = [0.0, 0.0, 0.01]", "displacement = [0.0, 0.0, 2.0]").replace(
    'method = "force_control"', 'method = "displacement_control"').replace("steps = 5",
                                                                           "steps = 7")


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "strip.obj").write_text(STRIP_OBJ)
    return tmp_path


def problem(folder, text):
    (folder / "problem.toml").write_text(text)
    return folder / "problem.toml"


def figure(page):
    text = page.read_text(encoding="utf-8")
    return json.loads(re.search('id="kresling-figure">(.*?)</script>', text, re.S).group(1))


def assert_shown(shown, exact):
    """The page's curve holds 10 significant digits of its largest value."""
    exact = np.asarray(exact, dtype=float)
    assert np.abs(np.asarray(shown, dtype=float) - exact).max() <= 1e-9 * np.abs(exact).max()


def read_csv(path):
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    return rows[0], np.array(rows[1:], dtype=float)


def test_every_keeps_every_kth_increment_and_the_last(folder):
    sim = simulate(problem(folder, DRIVEN + "\n[output]\nevery = 3\n"), progress=False)
    files = sim.write(folder / "out")
    header, history = read_csv(files["history"])
    assert history[:, 0].tolist() == [3, 6, 7]   # increments 3, 6 and the last, 7
    _, displacements = read_csv(files["displacements"])
    np.testing.assert_array_equal(displacements, sim.path.displacement[[2, 5, 6]])
    assert len(read_fold(files["fold"], planarity_tolerance=None).frames) == 3
    info = figure(files["view"])["frames"]
    assert info["names"] == ["3", "6", "7"]
    assert json.loads(files["summary"].read_text())["increments"] == 7


def test_the_cli_every_overrides_the_problem(folder):
    problem(folder, DRIVEN + "\n[output]\nevery = 3\n")
    result = run_kresling("simulate", "problem.toml", "--out", "out", "--every", "2",
                          "--quiet", cwd=folder)
    assert result.returncode == 0, result.stderr
    _, history = read_csv(folder / "out" / "history.csv")
    assert history[:, 0].tolist() == [2, 4, 6, 7]
    bad = run_kresling("simulate", "problem.toml", "--out", "out", "--every", "0", cwd=folder)
    assert bad.returncode == 2 and "--every = 0 is invalid" in bad.stderr


def test_the_default_curve_is_the_reaction_against_the_driven_displacement(folder):
    sim = simulate(problem(folder, DRIVEN), progress=False)
    spec = figure(sim.write(folder / "out")["view"])
    curve = spec["data"][-2]
    assert_shown(curve["x"], sim.path.displacement[:, 3 * 2 + 2])
    assert_shown(curve["y"], sim.path.constraint_force[:, 0])
    assert spec["layout"]["xaxis"]["title"]["text"] == "uz of node 2 [mm]"
    assert spec["layout"]["yaxis"]["title"]["text"] == "reaction_2_z [N]"


def test_force_control_plots_the_load_factor_against_the_monitored_displacement(folder):
    text = VALID.replace("steps = 5", "steps = 5\nstop = { node = 5, axis = \"z\", beyond = 50.0 }")
    sim = simulate(problem(folder, text), progress=False)
    spec = figure(sim.write(folder / "out")["view"])
    curve = spec["data"][-2]
    assert_shown(curve["x"], sim.path.displacement[:, 3 * 5 + 2])
    assert_shown(curve["y"], sim.path.load_factor)
    assert spec["layout"]["xaxis"]["title"]["text"] == "uz of node 5 [mm]"


def test_a_named_curve(folder):
    text = DRIVEN + '\n[output]\ncurve = { x = "u_2_z", y = "energy_total" }\n'
    sim = simulate(problem(folder, text), progress=False)
    spec = figure(sim.write(folder / "out")["view"])
    curve = spec["data"][-2]
    assert_shown(curve["y"], sim.path.energy)
    assert spec["layout"]["yaxis"]["title"]["text"] == "energy_total [N*mm]"


@pytest.mark.parametrize("table, message", [
    ("every = 0", "key 'every' = 0 is invalid: must be an integer >= 1"),
    ("every = 1.5", "key 'every' = 1.5 is invalid"),
    ('curve = { x = "u_2_z" }', "key 'curve' = {'x': 'u_2_z'} is invalid: must be a table"),
    ('curve = { x = "u_99_z", y = "step" }', "names node 99, out of range"),
    ('curve = { x = "u_2_w", y = "step" }', "x = 'u_2_w' is invalid: must be step"),
    ('curve = { x = "u_2_z", y = "reaction_1_z" }', "reaction_1_z' is invalid: a reaction is "
                                                    "a column of a driven DOF"),
    ("colour = 1", "key 'colour' is unknown"),
])
def test_bad_output_keys_name_the_key(folder, table, message):
    with pytest.raises(ValueError, match=re.escape(message)) as error:
        load_problem(problem(folder, DRIVEN + f"\n[output]\n{table}\n"))
    assert "problem.toml" in str(error.value) and "[output]" in str(error.value)


def test_large_outputs_are_announced_with_their_size(folder, caplog, monkeypatch):
    import kresling.simulate.outputs as outputs

    sim = simulate(problem(folder, DRIVEN), progress=False)
    # 7 increments x 8 nodes x 3 x 2 files x 20 characters = 6,720 bytes: over a bound of
    # 5,000, not over one of 10,000.
    monkeypatch.setattr(outputs, "LARGE_OUTPUT", 10_000)
    with caplog.at_level(logging.WARNING, logger="kresling.simulate.outputs"):
        sim.write(folder / "quiet", view=False)
    assert caplog.records == []
    monkeypatch.setattr(outputs, "LARGE_OUTPUT", 5_000)
    with caplog.at_level(logging.WARNING, logger="kresling.simulate.outputs"):
        sim.write(folder / "loud", view=False)
    message = caplog.records[-1].getMessage()
    assert "writing about 0.00672 MB of outputs (7 increments of 8 nodes)" in message
    assert "[output] every = k" in message and "--every k" in message


def test_a_drive_of_several_dofs_plots_the_force_that_does_its_work(folder):
    # Both far corners lifted (2 mm and 1 mm): the curve's y is the force whose work over
    # the lead DOF's displacement is the drive's work, so the area under the curve is the
    # energy stored (the trapezoid rule over 40 increments: within 0.5 %).
    text = DRIVEN.replace("node = 2\ndisplacement = [0.0, 0.0, 2.0]",
                          "node = 2\ndisplacement = [0.0, 0.0, 2.0]\n[[load]]\nnode = 5\n"
                          "displacement = [0.0, 0.0, 1.0]").replace("steps = 7", "steps = 40")
    sim = simulate(problem(folder, text), progress=False)
    spec = figure(sim.write(folder / "out")["view"])
    x, y = (np.asarray(spec["data"][-2][k]) for k in "xy")
    r = np.asarray(sim.path.constraint_force)
    assert_shown(y, r[:, 0] + 0.5 * r[:, 1])
    work = -np.trapezoid(np.concatenate([[0.0], y]), np.concatenate([[0.0], x]))
    assert work == pytest.approx(sim.path.energy[-1], rel=5e-3)
    assert spec["layout"]["yaxis"]["title"]["text"] == "drive's reaction over 2 driven DOFs [N]"
