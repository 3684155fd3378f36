"""Bars and hinges from panels by MERLIN2's rules, and the N5B8 centre nodes."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import minimize

from kresling import _core
from kresling.model import ManualProperties, build_panel_elements, build_pattern_model
from kresling.io import pattern_from_arrays

SQUARE = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]], float)


def test_n4b5_quad_bends_on_its_shorter_diagonal():
    kite = np.array([[0, 0, 0], [3, -1, 0], [5, 0, 0], [3, 1, 0]], float)  # 1-3 shorter
    e = build_panel_elements(kite, [[0, 1, 2, 3]], split="N4B5")
    assert e.bends.tolist() == [[1, 3, 0, 2]]
    # On a tie (a rectangle) the diagonal from the first corner.
    e = build_panel_elements(SQUARE, [[0, 1, 2, 3]], split="N4B5")
    assert e.bends.tolist() == [[0, 2, 1, 3]]
    assert e.triangles.tolist() == [[0, 1, 2], [0, 2, 3]]
    assert len(e.bars) == 5 and len(e.folds) == 0  # diagonal + 4 sides


def test_n4b5_polygon_is_cut_into_triangles():
    angles = np.linspace(0, 2 * np.pi, 8, endpoint=False)
    octagon = np.column_stack([np.cos(angles) * 3, np.sin(angles) * 2, np.zeros(8)])
    e = build_panel_elements(octagon, [list(range(8))], split="N4B5")
    assert len(e.bends) == 5 and len(e.triangles) == 6  # m - 3 cuts, m - 2 triangles
    area = sum(0.5 * np.linalg.norm(np.cross(octagon[b] - octagon[a], octagon[c] - octagon[a]))
               for a, b, c in e.triangles)
    x, y = octagon[:, 0], octagon[:, 1]
    assert area == pytest.approx(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))),
                                 rel=1e-12)


def test_n5b8_planar_quad_centre_is_where_the_diagonals_cross():
    quad = np.array([[0, 0, 0], [4, 0, 0], [5, 3, 0], [1, 2, 0]], float)
    e = build_panel_elements(quad, [[0, 1, 2, 3]], split="N5B8")
    # Diagonals 0-2 and 1-3: solve s (p2 - p0) = p1 + r (p3 - p1).
    A = np.column_stack([quad[2] - quad[0], quad[1] - quad[3]])[:2]
    s, _ = np.linalg.solve(A, (quad[1] - quad[0])[:2])
    np.testing.assert_allclose(e.nodes[4], quad[0] + s * (quad[2] - quad[0]), atol=1e-12)
    assert e.bends.tolist() == [[4, k, (k - 1) % 4, (k + 1) % 4] for k in range(4)]
    assert len(e.bars) == 8 and e.panel_centre.tolist() == [4]


def test_n5b8_warped_quad_centre_lies_on_its_shorter_diagonal():
    warped = np.array([[0, 0, 0], [4, 0, 1], [4, 2, 0], [0, 3, 1]], float)  # 0-2 shorter
    c = build_panel_elements(warped, [[0, 1, 2, 3]], split="N5B8").nodes[4]
    on_line = np.cross(c - warped[0], warped[2] - warped[0])
    assert np.linalg.norm(on_line) < 1e-12
    # ... at the point closest to the other diagonal's line.
    d = warped[3] - warped[1]
    t = np.dot(c - warped[1], d) / np.dot(d, d)
    gap = c - (warped[1] + t * d)
    assert abs(np.dot(gap, warped[2] - warped[0])) < 1e-12


@pytest.mark.parametrize("seed", range(5))
def test_polygon_centre_is_the_objective_minimum(seed):
    rng = np.random.default_rng(seed)
    m = int(rng.integers(5, 9))
    angles = np.sort(rng.uniform(0, 2 * np.pi, m))
    radii = rng.uniform(2, 4, m)
    corners = np.column_stack([radii * np.cos(angles), radii * np.sin(angles),
                               rng.normal(0, 0.3 if seed % 2 else 0.0, m)])
    centre = _core.model.polygon_optimal_centre(list(corners))
    best = _core.model.polygon_centre_objective(list(corners), centre)

    def objective(x):
        return _core.model.polygon_centre_objective(list(corners), np.asarray(x))

    # An independent minimiser from many starts never finds a lower value (the objective is
    # convex; 1e-9 relative allows for where Nelder-Mead stops near a kink).
    for start in rng.normal(0, 1.5, (8, 3)):
        found = minimize(objective, start, method="Nelder-Mead",
                         options={"xatol": 1e-12, "fatol": 1e-14, "maxiter": 20000})
        assert best <= found.fun * (1 + 1e-9)


def test_folds_between_panels_and_the_boundary():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], float)
    e = build_panel_elements(vertices, [[0, 1, 4, 3], [1, 2, 5, 4]], split="N5B8")
    assert e.folds[:, :2].tolist() == [[1, 4]]
    assert len(e.boundary) == 6 and len(e.bends) == 8
    assert len(e.bars) == len(e.bends) + len(e.folds) + len(e.boundary)


@pytest.mark.parametrize("panels, match", [
    ([[0, 1]], "panel 0: has 2 vertices"),
    ([[0, 1, 2, 2]], "panel 0: vertex 2 appears twice"),
    ([[0, 1, 2], [0, 2, 9]], "panel 1: vertex 9 is out of range"),
])
def test_bad_panels_are_named(panels, match):
    with pytest.raises(ValueError, match=match):
        build_panel_elements(SQUARE, panels, split="N4B5")


def test_unknown_split():
    with pytest.raises(ValueError, match="split = 'N3B3' is invalid"):
        build_panel_elements(SQUARE, [[0, 1, 2, 3]], split="N3B3")


def test_assignments_set_families_and_a_cut_separates_its_faces():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0], [2, 1, 0]], float)
    faces = [[0, 1, 2], [0, 2, 3], [1, 4, 5], [1, 5, 2]]
    edges = [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2], [1, 4], [4, 5], [5, 2], [1, 5]]
    assignment = ["B", "C", "B", "B", "M", "B", "B", "B", "V"]
    pattern = pattern_from_arrays(vertices, faces, edges=edges, edges_assignment=assignment)
    pm = build_pattern_model(pattern, split="N4B5",
                             material=ManualProperties(bar_modulus=1e3, bar_area=1.0,
                                                       fold_stiffness=0.1))
    # The cut 1-2 runs from boundary to boundary (FOLD 1.2: faces separated along it): the
    # right-hand faces get copies of its ends, 6 (of 1) and 7 (of 2), and no hinge joins
    # the two halves.
    assert pm.model.num_nodes == 8
    np.testing.assert_array_equal(pm.model.nodes[6:], vertices[[1, 2]])
    families = dict(zip(map(tuple, np.sort(pm.model.hinges[:, :2], axis=1).tolist()),
                        pm.hinge_family))
    assert families == {(0, 2): "mountain", (5, 6): "valley"}
    bars = dict(zip(map(tuple, np.sort(pm.model.bars, axis=1).tolist()), pm.bar_family))
    assert bars[(1, 2)] == bars[(6, 7)] == "cut"          # each side of the cut
    assert sorted(set(pm.bar_family)) == ["boundary", "cut", "fold"]


def test_boundary_assignment_on_an_inner_edge_is_refused():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    pattern = pattern_from_arrays(vertices, [[0, 1, 2], [0, 2, 3]],
                                  edges=[[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]],
                                  edges_assignment=["B", "B", "B", "B", "B"])
    with pytest.raises(ValueError, match=r"edge 4 \(0, 2\) is assigned 'B'"):
        build_pattern_model(pattern, split="N4B5",
                            material=ManualProperties(1e3, 1.0, fold_stiffness=0.1))


def test_manual_properties_need_the_stiffness_of_each_kind_present():
    with pytest.raises(ValueError, match="bend_stiffness is missing"):
        build_pattern_model((SQUARE, [[0, 1, 2, 3]]), split="N4B5",
                            material=ManualProperties(1e3, 1.0))
    with pytest.raises(ValueError, match=r"bar_area has shape \(3,\)"):
        build_pattern_model((SQUARE, [[0, 1, 2, 3]]), split="N4B5",
                            material=ManualProperties(1e3, [1.0, 1.0, 1.0], bend_stiffness=1))


def test_mean_centre_rule():
    kite = np.array([[0, 0, 0], [3, -1, 0], [5, 0, 0], [3, 1, 0]], float)
    mean = build_panel_elements(kite, [[0, 1, 2, 3]], split="N5B8", centre="mean")
    merlin2 = build_panel_elements(kite, [[0, 1, 2, 3]], split="N5B8")
    np.testing.assert_allclose(mean.nodes[4], kite.mean(axis=0), rtol=0, atol=1e-15)
    np.testing.assert_allclose(merlin2.nodes[4], [3, 0, 0], atol=1e-15)  # diagonals cross
    with pytest.raises(ValueError, match="centre = 'middle' is invalid"):
        build_panel_elements(kite, [[0, 1, 2, 3]], split="N5B8", centre="middle")
