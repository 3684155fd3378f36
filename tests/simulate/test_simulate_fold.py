"""Problem files that fold: [[actuation]] with method = "fold" through kresling simulate
(the solver's own checks are in tests/solvers/test_fold.py)."""

from __future__ import annotations

import dataclasses
import tomllib
from pathlib import Path

import numpy as np
import pytest

from kresling.io import write_fold
from kresling.io.miura import miura_sheet
from kresling.simulate import load_problem, simulate
from small_models import CREASED_SQUARE

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

STIFF = {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
         "fold_stiffness": 1.0, "bend_stiffness": 1.0}


def test_the_fold_example_behaves_as_its_file_says():
    sim = simulate(EXAMPLES / "fold_vertex" / "problem.toml", progress=False)
    # The path runs to its end, but the crease ends near 47 deg of its 90: not completed.
    assert sim.path.completed and not sim.completed and sim.path.num_steps == 40
    report = sim.summary()["fold"]
    assert report["creases_driven"] == 1 and report["short_of_target"] == 1
    assert 44.0 < report["worst"]["fold_angle_deg"] < 50.0
    columns = sim.history_columns()
    assert list(columns)[:4] == ["step", "load_factor", "stage", "fold_fraction"]
    assert (columns["stage"] == 1).all()
    np.testing.assert_allclose(columns["fold_fraction"], np.arange(1, 41) / 40, atol=1e-14)
    assert columns["energy_bars"][-1] < 1e-5 * columns["energy_folds"][-1]


def _miura_file(tmp_path, angle=40.0):
    """A flat 2 x 2 Miura sheet whose edges_foldAngle are its rigidly folded state's."""
    flat = miura_sheet(2, 2, fold_angle=0.0)
    folded = miura_sheet(2, 2, fold_angle=angle)
    pattern = dataclasses.replace(flat, edges_assignment=folded.edges_assignment,
                                  edges_fold_angle=folded.edges_fold_angle)
    path = write_fold(tmp_path / "miura.fold", pattern)
    return path, pattern, folded


def _miura_problem(path, pattern, actuation, steps=20, **analysis):
    held = list(pattern.faces[0][:3])
    return {"pattern": {"file": str(path)}, "material": STIFF,
            "laws": {"fold_limits_deg": [5.0, 355.0]},
            "support": [{"nodes": held, "fix": "xyz"}],
            "actuation": actuation, "analysis": {"method": "fold", "steps": steps, **analysis}}


def test_a_miura_sheet_folds_to_its_files_fold_angles(tmp_path):
    path, pattern, folded = _miura_file(tmp_path)
    sim = simulate(_miura_problem(path, pattern, [{"family": "fold", "fold_angle_deg": "file"}],
                                  predictor="quadratic"), progress=False)
    assert sim.completed, sim.path.message
    report = sim.summary()["fold"]
    assert report["short_of_target"] == 0 and report["left_branch"] == 0
    x = (sim.model.nodes + sim.path.displacement[-1].reshape(-1, 3))[:pattern.num_vertices]
    d = np.linalg.norm(x[:, None] - x[None], axis=2)
    d_ref = np.linalg.norm(folded.vertices[:, None] - folded.vertices[None], axis=2)
    np.testing.assert_allclose(d, d_ref, atol=1e-4)


def test_stages_fold_one_after_another(tmp_path):
    path, pattern, _ = _miura_file(tmp_path)
    actuation = [{"family": "valley", "fold_angle_deg": 20.0, "stage": 1},
                 {"family": "mountain", "fold_angle_deg": -20.0, "stage": 2}]
    sim = simulate(_miura_problem(path, pattern, actuation, steps=5), progress=False)
    columns = sim.history_columns()
    assert columns["stage"].tolist() == [1] * 5 + [2] * 5
    np.testing.assert_allclose(columns["fold_fraction"], np.tile(np.arange(1, 6) / 5, 2),
                               atol=1e-14)
    assert sim.path.load_factor[-1] == pytest.approx(2.0)
    assert sim.summary()["fold"]["creases_driven"] == sum(
        f in ("valley", "mountain") for f in sim.pattern_model.hinge_family)


def test_a_crease_named_by_its_vertices_is_the_only_one_driven(tmp_path):
    path, pattern, _ = _miura_file(tmp_path)
    sim0 = simulate(_miura_problem(path, pattern, [{"family": "fold", "fold_angle_deg": "file"}],
                                   steps=2), progress=False)
    hinge = sim0.fold.hinges[0]
    u, v = sorted(sim0.model.hinges[hinge][:2].tolist())
    sim = simulate(_miura_problem(path, pattern, [{"edges": [[v, u]], "fold_angle_deg": 30.0}],
                                  steps=4), progress=False)
    assert sim.fold.hinges.tolist() == [hinge]
    assert sim.fold.target_deg.tolist() == [30.0]


@pytest.mark.parametrize("change, message", [
    ({"actuation": []}, "[[actuation]] is missing"),
    ({"actuation": [{"edges": [[0, 1]], "family": "valley", "fold_angle_deg": 10.0}]},
     "exactly one of 'edges'"),
    ({"actuation": [{"family": "valley"}]}, "'fold_angle_deg' is missing"),
    ({"actuation": [{"family": "valley", "fold_angle_deg": 200.0}]}, "in [-180, 180]"),
    ({"actuation": [{"family": "valley", "fold_angle_deg": "flat"}]}, "or \"file\""),
    ({"actuation": [{"family": "sideways", "fold_angle_deg": 10.0}]}, "must be one of"),
    ({"actuation": [{"edges": [[0, 99]], "fold_angle_deg": 10.0}]}, "out of range"),
    ({"actuation": [{"edges": [[0]], "fold_angle_deg": 10.0}]}, "a pair [u, v]"),
    ({"actuation": [{"family": "valley", "fold_angle_deg": 10.0, "stage": 2}]},
     "without a gap"),
    ({"load": [{"node": 4, "displacement": [0.0, 0.0, 1.0]}]}, "force loads only"),
])
def test_bad_actuation_is_refused_naming_the_key(tmp_path, change, message):
    path, pattern, _ = _miura_file(tmp_path)
    data = _miura_problem(path, pattern, [{"family": "valley", "fold_angle_deg": 10.0}])
    data.update(change)
    if not data["actuation"]:
        del data["actuation"]
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]")):
        load_problem(data)


def test_actuation_needs_the_fold_method(tmp_path):
    path, pattern, _ = _miura_file(tmp_path)
    data = _miura_problem(path, pattern, [{"family": "valley", "fold_angle_deg": 10.0}])
    data["analysis"] = {"method": "force_control", "steps": 2}
    data["load"] = [{"node": 4, "force": [0.0, 0.0, 1.0]}]
    with pytest.raises(ValueError, match="only with .* method = 'fold'"):
        load_problem(data)


def test_an_edge_that_is_no_crease_is_named(tmp_path):
    path, pattern, _ = _miura_file(tmp_path)
    boundary = next(e for e, a in zip(pattern.edges.tolist(), pattern.edges_assignment)
                    if a == "B")
    data = _miura_problem(path, pattern, [{"edges": [boundary], "fold_angle_deg": 10.0}])
    with pytest.raises(ValueError, match="is not a crease"):
        simulate(data, progress=False)


def test_the_folds_view_plots_the_energy_against_the_fold_percent(tmp_path):
    from kresling.simulate.curve import path_curve

    sim = simulate(EXAMPLES / "fold_vertex" / "problem.toml", progress=False)
    columns = sim.history_columns()
    x, y, x_label, y_label = path_curve(sim, columns)
    assert x_label == "fold [%]" and y_label.startswith("energy_total")
    np.testing.assert_allclose(x, 100 * np.arange(1, 41) / 40, atol=1e-12)
    np.testing.assert_array_equal(y, columns["energy_total"])
    written = sim.write(tmp_path)
    assert "fold [%]" in written["view"].read_text(encoding="utf-8")


def _vertex_problem(steps, **analysis):
    problem = tomllib.loads((EXAMPLES / "fold_vertex" / "problem.toml").read_text())
    problem["pattern"]["file"] = str(EXAMPLES / "single_vertex" / "single_vertex.fold")
    problem["analysis"].update(steps=steps, **analysis)
    return problem


def test_a_fold_in_adaptive_increments_reads_its_samples_off_the_path():
    # The fold example's vertex in 200 samples: the adaptive increments take 65 (measured),
    # the samples between them read off their Hermite curves (0 iterations), and agree with
    # the fixed increments' converged samples to 1e-8 mm (measured 6.8e-10) and their stored
    # energy to 1e-8 of its largest value (measured 1.8e-10).
    fixed = simulate(_vertex_problem(200), progress=False)
    adaptive = simulate(_vertex_problem(200, increments="adaptive"), progress=False)
    assert adaptive.path.completed, adaptive.path.message
    f, a = fixed.path, adaptive.path
    np.testing.assert_array_equal(a.load_factor, f.load_factor)
    assert a.attempted_increments < f.attempted_increments / 2
    assert (a.iterations == 0).sum() > 100
    assert np.abs(a.displacement - f.displacement).max() <= 1e-8
    assert np.abs(a.energy - f.energy).max() <= 1e-8 * f.energy.max()
    assert adaptive.summary()["stepping"].startswith("adaptive increments of the creases'")
    assert list(adaptive.history_columns())[:4] == ["step", "load_factor", "stage", "fold_fraction"]


def test_adaptive_fold_increments_refuse_a_predictor(tmp_path):
    problem = tmp_path / "p.toml"
    text = (EXAMPLES / "fold_vertex" / "problem.toml").read_text().replace(
        "../single_vertex/single_vertex.fold",
        (EXAMPLES / "single_vertex" / "single_vertex.fold").as_posix())
    problem.write_text(text + 'increments = "adaptive"\npredictor = "cubic"\n')
    with pytest.raises(ValueError, match="predictor"):
        load_problem(problem)


def test_the_fold_report_reads_angles_on_the_circle():
    """A crease folded past flat reads as the other sign (-164 deg for 196 deg): it is
    16 deg from a target of 180 deg and not folded the other way; one short of a small
    target on the far side of flat is the other way."""
    problem = dict(CREASED_SQUARE, actuation=[{"edges": [[0, 2]], "fold_angle_deg": 180.0}],
                   analysis={"method": "fold", "steps": 2})
    sim = simulate(problem, progress=False)
    nodes = sim.model.nodes

    def turned(degrees):
        """The free corner turned about the crease 0 -> 2 by ``degrees`` from flat."""
        axis = (nodes[2] - nodes[0]) / np.linalg.norm(nodes[2] - nodes[0])
        r = nodes[3] - nodes[0]
        a = np.radians(degrees)
        rotated = (r * np.cos(a) + np.cross(axis, r) * np.sin(a)
                   + axis * np.dot(axis, r) * (1 - np.cos(a)))
        u = np.zeros_like(nodes)
        u[3] = nodes[0] + rotated - nodes[3]
        return u.ravel()

    def report_at(degrees, target):
        plan = dataclasses.replace(sim.fold, target_deg=np.array([target]))
        path = dataclasses.replace(sim.path, displacement=turned(degrees)[None, :])
        return dataclasses.replace(sim, path=path, fold=plan).fold_report()

    # Which way the corner turns for a valley: the reached fold angle's sign says.
    sign = np.sign(report_at(30.0, 30.0)["worst"]["fold_angle_deg"])
    past = report_at(sign * 196.0, 180.0)
    assert past["worst"]["fold_angle_deg"] == pytest.approx(-164.0, abs=1e-6)
    assert past["largest_shortfall_deg"] == pytest.approx(16.0, abs=1e-6)
    assert past["left_branch"] == 0
    other = report_at(-sign * 10.0, 30.0)
    assert other["largest_shortfall_deg"] == pytest.approx(40.0, abs=1e-6)
    assert other["left_branch"] == 1
