"""What a simulation writes, read back: history, displacements, FOLD frames, view."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from kresling.io import read_fold
from kresling.simulate import simulate
from test_simulate_problem import STRIP_OBJ, VALID


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    folder = tmp_path_factory.mktemp("strip")
    (folder / "strip.obj").write_text(STRIP_OBJ)
    (folder / "problem.toml").write_text(VALID)
    sim = simulate(folder / "problem.toml", progress=False)
    return sim, sim.write(folder / "out"), folder / "out"


def rows(path):
    with open(path, newline="") as handle:
        table = list(csv.reader(handle))
    return table[0], np.array(table[1:], dtype=float)


def test_displacements_csv_has_every_node(written):
    sim, files, _ = written
    header, values = rows(files["displacements"])
    assert header[:4] == ["x0", "y0", "z0", "x1"] and len(header) == 3 * sim.model.num_nodes
    np.testing.assert_array_equal(values, sim.path.displacement)


def test_history_columns(written):
    sim, files, _ = written
    header, values = rows(files["history"])
    assert header[:2] == ["step", "load_factor"]
    np.testing.assert_array_equal(values[:, 1], sim.path.load_factor)
    # The energy split adds up to the solver's stored energy at every increment.
    total = values[:, header.index("energy_bars")] + values[:, header.index("energy_folds")] + \
        values[:, header.index("energy_bends")]
    np.testing.assert_allclose(total, sim.path.energy, rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(values[:, header.index("energy_bars")], sim.path.energy_bars,
                               rtol=1e-12, atol=1e-18)


def test_path_fold_frames_are_the_deformed_nodes(written):
    sim, files, _ = written
    pattern = read_fold(files["fold"], planarity_tolerance=None)
    np.testing.assert_allclose(pattern.vertices, sim.model.nodes, atol=1e-12)
    assert len(pattern.frames) == sim.path.num_steps
    last = sim.model.nodes + sim.path.displacement[-1].reshape(-1, 3)
    np.testing.assert_allclose(pattern.frames[-1], last, atol=1e-12)
    # The middle crease is a fold, the panels' inner edges joins (bend hinges), the rim B.
    letters = dict(zip(map(tuple, np.sort(pattern.edges, axis=1).tolist()),
                       pattern.edges_assignment))
    assert letters[(1, 4)] == "U" and letters[(0, 1)] == "B" and letters[(0, 6)] == "J"


def test_view_and_summary(written):
    sim, files, _ = written
    html = files["view"].read_text()
    assert "#frame=" in html or "frame=" in html
    assert '<script src="http' not in html
    assert files["summary"].read_text().count('"completed": true') == 1


def test_element_histories(written):
    sim, _, _ = written
    h = sim.element_histories()
    steps, bars, hinges = sim.path.num_steps, len(sim.model.bars), len(sim.model.hinges)
    assert h.bar_strain.shape == (steps, bars) and h.hinge_angle.shape == (steps, hinges)
    # The fold between the squares opens as the corner lifts.
    fold = sim.pattern_model.family_mask("unassigned")
    change = h.angle_change(sim.model.hinge_rest_angle)[:, fold]
    assert np.all(np.abs(change[-1]) > np.abs(change[0]))
