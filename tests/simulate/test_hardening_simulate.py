"""Reproducers of what a new user and a fuzz of ``kresling simulate`` hit (each must stay
fixed): a bad problem or pattern file is one line naming the file and the key (exit 2); a
path that stops is the summary and exit 1; the limits the docs state are the solvers'."""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling import _core
from kresling.simulate import load_problem, simulate
from kresling.simulate.problem_table import QUANTITY_RANGE
from kresling.simulate.problem_file import MAX_NESTING

DOCS = Path(__file__).resolve().parents[2] / "docs"

# The worked example of docs/simulate.md: one crease folded by lifting a corner.
CREASE = """\
[pattern]
vertices = [[0.0, 0.0, 0.0], [20.0, 0.0, 0.0], [20.0, 20.0, 0.0], [0.0, 20.0, 0.0]]
panels = [[0, 1, 2], [0, 2, 3]]

[material]
calibration = "manual"
bar_modulus = 1e4
bar_area = 1.0
fold_stiffness = 0.01

[[support]]
nodes = [0, 1, 2]
fix = "xyz"

[[load]]
node = 3
displacement = [0.0, 0.0, 5.0]

[analysis]
method = "displacement_control"
steps = 10
"""


def problem_file(tmp_path, text=CREASE, name="problem.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


def one_line_error(result, *fragments):
    """A refused problem: exit 2 and one line on stderr holding every fragment."""
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    for fragment in fragments:
        assert fragment in lines[0], lines[0]
    return lines[0]


# 2. A path that stops before its first increment: exit 1 and the summary, view or not.
@pytest.mark.parametrize("view", [True, False])
def test_a_path_with_no_increment_exits_1_with_its_summary(tmp_path, view):
    # A Newton tolerance below rounding: no increment converges, however it is halved.
    path = problem_file(tmp_path, CREASE.replace(
        "steps = 10", "steps = 1\nmax_iterations = 2\ntolerance = 1e-300"))
    result = run_kresling("simulate", str(path), "--out", "out", "--quiet", "--json",
                          *([] if view else ["--no-view"]), cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    summary = json.loads(result.stdout)
    assert summary["increments"] == 0 and summary["completed"] is False
    assert summary["attempted_increments"] >= 1
    assert "stopped early" in result.stderr and "Traceback" not in result.stderr
    written = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert written["increments"] == 0
    assert not (tmp_path / "out" / "view.html").exists()


# 4. summary.json counts the attempts too, not only the accepted increments.
def test_the_summary_counts_every_attempt():
    # Force control of the crease in one increment with at most 5 iterations: the full load
    # does not converge, so the increment is halved and retried.
    text = CREASE.replace("displacement = [0.0, 0.0, 5.0]", "force = [0.0, 0.0, 0.002]").replace(
        '"displacement_control"', '"force_control"').replace("steps = 10",
                                                             "steps = 1\nmax_iterations = 5")
    simulation = simulate(load_problem_text(text))
    summary, path = simulation.summary(), simulation.path
    assert summary["completed"]
    assert summary["increments"] == path.num_steps
    assert summary["newton_iterations"] == int(path.iterations.sum())
    rejected = summary["attempted_increments"] - summary["increments"]
    assert rejected > 0
    # Each rejected attempt ran all 5 iterations without converging.
    assert summary["attempted_newton_iterations"] == summary["newton_iterations"] + 5 * rejected
    smooth = simulate(load_problem_text(CREASE)).summary()
    # Every increment accepted at once: the attempts are the increments.
    assert smooth["attempted_increments"] == smooth["increments"] == 10
    assert smooth["attempted_newton_iterations"] == smooth["newton_iterations"]


def load_problem_text(text):
    import tomllib

    return load_problem(tomllib.loads(text))


# 5. The limits the docs' tables state are the ones the core checks.
def _documented_range(key):
    text = (DOCS / "simulate.md").read_text()
    row = re.search(rf"^\| `{key}` \| integer in \[1, ([0-9e,]+)\] \|", text, re.MULTILINE)
    assert row, f"docs/simulate.md has no range for {key}"
    return int(float(row.group(1).replace(",", "")))


@pytest.mark.parametrize("key, limit", [("steps", "MAX_STEPS"),
                                        ("max_increments", "MAX_STEPS"),
                                        ("max_iterations", "MAX_ITERATIONS")])
def test_documented_limits_are_the_cores(key, limit):
    largest = getattr(_core.solvers, limit)
    assert _documented_range(key) == largest
    method = "mgdcm" if key == "max_increments" else "displacement_control"
    base = {"pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "panels": [[0, 1, 2]]},
            "material": {"calibration": "manual", "bar_modulus": 1.0, "bar_area": 1.0},
            "support": [{"node": 0, "fix": "xyz"}],
            "load": [{"node": 1, "force" if method == "mgdcm" else "displacement":
                      [0.0, 0.0, 1.0]}],
            "analysis": {"method": method, **({} if method == "mgdcm" else {"steps": 1})}}
    base["analysis"][key] = largest
    assert getattr(load_problem(base).analysis, key) == largest
    base["analysis"][key] = largest + 1
    with pytest.raises(ValueError, match=rf"key '{key}' = {largest + 1} is invalid: must be an "
                                         rf"integer in \[1, {largest}\]"):
        load_problem(base)


# 6. The planarity message offers a value a problem file can write.
def test_planarity_message_offers_a_tolerance_that_accepts_the_panel(tmp_path):
    warped = CREASE.replace("[0.0, 20.0, 0.0]]", "[0.0, 20.0, 0.0], [10.0, 30.0, 0.7]]").replace(
        "panels = [[0, 1, 2], [0, 2, 3]]", "panels = [[0, 1, 2], [0, 2, 4, 3]]")
    result = run_kresling("simulate", str(problem_file(tmp_path, warped)), cwd=tmp_path)
    line = one_line_error(result, "face 1 is not planar", "planarity_tolerance = ")
    assert "none" not in line
    suggested = re.search(r"planarity_tolerance = ([0-9.e-]+)", line).group(1)
    accepted = warped.replace("panels =", f"planarity_tolerance = {suggested}\npanels =")
    assert load_problem_text(accepted).pattern.num_faces == 2


# 8. Weak messages: a missing file, a negative stiffness.
def test_a_missing_problem_file_is_named(tmp_path):
    one_line_error(run_kresling("simulate", "nowhere.toml", cwd=tmp_path),
                   "nowhere.toml: no such problem file")


@pytest.mark.parametrize("key, value, message", [
    ("fold_stiffness", "-0.01", "problem.toml:9: [material] key 'fold_stiffness' = -0.01 is "
                                "invalid: must be >= 0"),
    ("fold_stiffness", "[0.01, -2.0]", "problem.toml:9: [material] key 'fold_stiffness' has an "
                                       "entry -2.0 that is invalid: must be >= 0"),
    ("bar_area", "0.0", "problem.toml:8: [material] key 'bar_area' = 0.0 is invalid: must be > 0")])
def test_a_negative_stiffness_names_its_line(tmp_path, key, value, message):
    text = re.sub(rf"^{key} = .*$", f"{key} = {value}", CREASE, flags=re.MULTILINE)
    one_line_error(run_kresling("simulate", str(problem_file(tmp_path, text)), cwd=tmp_path),
                   message)


# 12 and 17. Numbers near the ends of the floating-point range: one line naming the key.
@pytest.mark.parametrize("key, value", [
    ("fold_stiffness", "1e300"), ("bar_modulus", "1.7e308"), ("bar_area", "5e-324"),
    ("displacement", "[0.0, 0.0, 1e300]"), ("bar_modulus", "1e-31")])
def test_huge_and_tiny_quantities_are_out_of_range(tmp_path, key, value):
    text = re.sub(rf"^{key} = .*$", f"{key} = {value}", CREASE, flags=re.MULTILINE)
    low, high = QUANTITY_RANGE
    one_line_error(run_kresling("simulate", str(problem_file(tmp_path, text)), cwd=tmp_path),
                   f"key '{key}' = ", "is out of range",
                   f"magnitude must be in [{low:g}, {high:g}]")


@pytest.mark.parametrize("family", ["valley", "unassigned"])
def test_a_huge_family_stiffness_is_out_of_range(family):
    problem = load_problem_text(CREASE)  # valid as given
    assert problem.laws.families == {}
    with pytest.raises(ValueError, match=rf"\[laws.{family}\] key 'stiffness' = 1e\+300 is "
                                         "out of range"):
        load_problem_text(CREASE + f"\n[laws.{family}]\nstiffness = 1e300\n")


def test_the_quantities_range_still_runs_at_its_ends():
    # A crease 1e3 times stiffer in every element: the same fold, 1e3 times the reaction.
    stiff = CREASE.replace("bar_modulus = 1e4", "bar_modulus = 1e7").replace(
        "fold_stiffness = 0.01", "fold_stiffness = 10.0")
    soft, hard = simulate(load_problem_text(CREASE)), simulate(load_problem_text(stiff))
    assert hard.completed and soft.completed
    ratio = hard.path.constraint_force[-1, 0] / soft.path.constraint_force[-1, 0]
    assert ratio == pytest.approx(1e3, rel=1e-6)  # the bars barely stretch in either


@pytest.mark.parametrize("coordinate", ["1e150", "1e308", "-3e40"])
def test_coordinates_near_overflow_are_named_in_one_line(tmp_path, coordinate):
    text = CREASE.replace("[20.0, 20.0, 0.0]", f"[{coordinate}, 20.0, 0.0]")
    result = run_kresling("simulate", str(problem_file(tmp_path, text)), cwd=tmp_path)
    one_line_error(result, "vertex 2 has a coordinate of", "out of range: at most 1e+30 mm")
    assert "Warning" not in result.stderr


# 13. Nesting deeper than any problem needs: refused before the parser recurses.
@pytest.mark.parametrize("depth", [MAX_NESTING + 1, 450, 20_000])
@pytest.mark.parametrize("open_, close", [("[", "]"), ("{a = ", "}")])
def test_deeply_nested_toml_is_refused(tmp_path, depth, open_, close):
    text = CREASE + "\n[extra]\nx = " + open_ * depth + "1" + close * depth + "\n"
    if open_ == "[":
        text = text.replace("1" + close, close, 1)
    path = problem_file(tmp_path, text)
    with pytest.raises(ValueError, match=rf"problem.toml:\d+: not valid TOML here: arrays or "
                                         rf"inline tables nested {depth} levels deep"):
        load_problem(path)


def test_brackets_inside_strings_and_comments_are_not_nesting(tmp_path):
    text = CREASE.replace('fix = "xyz"', 'fix = "xyz"  # [[[[' + "[" * 100) + (
        '\n[extra]\nnote = "' + "[" * 100 + '"\n')
    with pytest.raises(ValueError, match=r"key 'extra' is unknown"):
        load_problem(problem_file(tmp_path, text))


# 16. Files that are not files: refused before they are read.
def test_a_fifo_problem_file_is_refused(tmp_path):
    fifo = tmp_path / "problem.toml"
    os.mkfifo(fifo)
    one_line_error(run_kresling("simulate", str(fifo), cwd=tmp_path, timeout=30),
                   "problem.toml: is a FIFO, not a regular file")


def test_a_device_as_problem_or_pattern_is_refused(tmp_path):
    one_line_error(run_kresling("simulate", "/dev/zero", "--out", "out", cwd=tmp_path, timeout=30),
                   "/dev/zero: is a device or socket, not a regular file")
    text = CREASE.replace(CREASE[:CREASE.index("[material]")],
                          '[pattern]\nfile = "/dev/zero"\n\n')
    result = run_kresling("simulate", str(problem_file(tmp_path, text)), cwd=tmp_path, timeout=30)
    one_line_error(result, "problem.toml:2: [pattern] key 'file'")


@pytest.mark.parametrize("name", ["problem.toml", "sheet.obj", "sheet.fold"])
def test_a_huge_sparse_file_is_refused_by_its_size(tmp_path, name):
    huge = tmp_path / name
    with huge.open("wb") as handle:  # 5 GiB of holes: no disk, but a read would fill memory
        handle.truncate(5 * 2**30)
    if name == "problem.toml":
        problem = huge
    else:
        problem = problem_file(tmp_path, CREASE.replace(
            CREASE[:CREASE.index("[material]")], f'[pattern]\nfile = "{name}"\n\n'))
    result = run_kresling("simulate", str(problem), cwd=tmp_path, timeout=30)
    one_line_error(result, f"{name}: is 5 GiB, larger than the 256 MiB an input file may have")


# 18. Garbled text names the file; a wrong-type `panels` names the key.
@pytest.mark.parametrize("garbage", [b"\xff\xfe[pattern]", b"[pattern]\nx = \"\xc3(\"\n",
                                     b"[pattern\n", b"a = 1\x00\n"])
def test_garbled_toml_names_the_file(tmp_path, garbage):
    path = tmp_path / "garbled.toml"
    path.write_bytes(garbage)
    with pytest.raises(ValueError, match=r"^.*garbled.toml(:\d+:\d+)?: not valid TOML"):
        load_problem(path)


@pytest.mark.parametrize("panels", ["5", '"abc"', "[0, 1, 2]", "[[0, 1, 2.5]]", "[]",
                                    "[[0, 1, true]]", "[[0, 1, 9]]"])
def test_wrong_panels_name_the_key(tmp_path, panels):
    text = CREASE.replace("panels = [[0, 1, 2], [0, 2, 3]]", f"panels = {panels}")
    one_line_error(run_kresling("simulate", str(problem_file(tmp_path, text)), cwd=tmp_path),
                   "problem.toml:3: [pattern] key 'panels'")


def test_a_pattern_array_of_wrong_shape_names_vertices():
    bad = CREASE.replace("[0.0, 20.0, 0.0]]", "[0.0, 20.0]]").replace("[0.0, 0.0, 0.0],", "[0.0],")
    with pytest.raises(ValueError, match=r"\[pattern\] key 'vertices'"):
        load_problem_text(bad)
    assert np.isfinite(load_problem_text(CREASE).pattern.vertices).all()


# 7. `kresling manipulator`: the arc's angle is labelled as eqn 26's phi, and where the bend
# points is printed beside it, checked against where the tip goes.
def test_the_manipulator_prints_where_a_module_bends(tmp_path):
    table = run_kresling("manipulator", "--config", "101", "--k", "10", cwd=tmp_path)
    assert table.returncode == 0, table.stderr
    assert "phi (eqn 26) [rad]" in table.stdout and "bends towards [deg]" in table.stdout
    row = next(line.split() for line in table.stdout.splitlines()  # the arcs' table
               if line.startswith("module2") and len(line.split()) == 7)
    phi_deg, towards = float(row[5]), float(row[6])
    assert phi_deg == pytest.approx(90.0) and towards == pytest.approx(0.0)
    data = json.loads(run_kresling("manipulator", "--config", "101", "--k", "10", "--json",
                                   cwd=tmp_path).stdout)
    tip = np.asarray(data["markers"][-1])
    assert np.degrees(np.arctan2(tip[1], tip[0])) == pytest.approx(towards, abs=1e-6)
    assert tip[0] > 1.0  # the tip moved to +x


# 14. Large polygons under N5B8: the centre is walked to, not searched among every crossing
# of two diagonals (a 64-gon ran over 60 s, a 300-gon ran out of memory).
def _lowest_crossing(corners):
    """The centre rule's exact minimiser by brute force (numpy): every crossing of two
    diagonal lines of a planar polygon in z = 0, the one of least objective."""
    m = len(corners)
    pairs = [(i, j) for j in range(m) for i in range(j - 1) if not (i == 0 and j == m - 1)]
    p, q = corners[[i for i, _ in pairs], :2], corners[[j for _, j in pairs], :2]
    d = q - p
    a, b = np.triu_indices(len(pairs), 1)
    det = d[a, 0] * d[b, 1] - d[a, 1] * d[b, 0]
    keep = np.abs(det) > 1e-12
    a, b, det = a[keep], b[keep], det[keep]
    w = p[b] - p[a]
    s = (w[:, 0] * d[b, 1] - w[:, 1] * d[b, 0]) / det
    x = p[a] + s[:, None] * d[a]                                    # (K, 2) crossings
    r = np.abs((x[:, None, 0] - p[None, :, 0]) * d[None, :, 1]
               - (x[:, None, 1] - p[None, :, 1]) * d[None, :, 0])   # twice the areas
    values = (r / (d ** 2).sum(axis=1)[None, :]).sum(axis=1)
    return values.min()


@pytest.mark.parametrize("seed", range(4))
def test_the_centre_of_a_large_polygon_is_the_lowest_crossing(seed):
    rng = np.random.default_rng(seed)
    m = 26  # above the 24 corners up to which every crossing is tried
    angles = 2 * np.pi * (np.arange(m) + 0.8 * rng.random(m)) / m
    radii = 20 * (0.5 + 0.5 * rng.random(m))
    corners = np.column_stack([radii * np.cos(angles), radii * np.sin(angles), np.zeros(m)])
    centre = _core.model.polygon_optimal_centre(list(corners))
    value = _core.model.polygon_centre_objective(list(corners), centre)
    # The objective sums 299 terms of order 1, each exact to rounding.
    assert value == pytest.approx(_lowest_crossing(corners), rel=1e-11)


@pytest.mark.parametrize("corners", [64, 300])
def test_a_large_polygon_builds_under_n5b8(corners):
    from kresling.simulate import build_problem_model

    angles = 2 * np.pi * np.arange(corners) / corners
    vertices = np.column_stack([50 * np.cos(angles), 50 * np.sin(angles), 0 * angles])
    model = build_problem_model({
        "pattern": {"vertices": vertices.tolist(), "panels": [list(range(corners))]},
        "material": {"calibration": "auto", "E": 1e3, "nu": 0.3, "thickness": 0.25},
        "support": [{"node": 0, "fix": "xyz"}], "load": [{"node": 1, "force": [0, 0, 1.0]}],
        "analysis": {"method": "mgdcm"}}).model
    # A regular polygon's centre is its middle, by symmetry.
    assert np.abs(model.nodes[corners]).max() < 1e-9 * 50
    assert model.num_nodes == corners + 1


# A solver's refusal names the problem's table and key (it named the solver's argument:
# "problem: forces: no force acts on a free DOF").
@pytest.mark.parametrize("load", ["node = 0\nforce = [0.0, 0.0, 1.0]",
                                  "node = 3\nforce = [0.0, 0.0, 0.0]"])
def test_a_load_on_no_free_dof_names_the_load_key(tmp_path, load):
    text = CREASE.replace("node = 3\ndisplacement = [0.0, 0.0, 5.0]", load).replace(
        'method = "displacement_control"', 'method = "force_control"')
    one_line_error(run_kresling("simulate", str(problem_file(tmp_path, text)), cwd=tmp_path),
                   "problem.toml: [[load]] key 'force': no force acts on a free DOF")
