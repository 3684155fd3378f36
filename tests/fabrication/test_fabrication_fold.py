"""The FOLD file of a cell, read back as JSON: every face folds isometrically onto the 3D
node positions of both stable states; fold angles and assignments agree with the folding;
the general writer rejects inconsistent input."""

import itertools
import json
import math

import numpy as np
import pytest

import kresling
from kresling.fabrication import fold_angles, fold_document, write_pattern

TOL = 1e-9  # mm; the FOLD file keeps full double precision (JSON repr of floats)


def _read(path):
    return json.loads(path.read_text())


def _corner_angles(points):
    out = []
    for k in range(len(points)):
        u = points[k - 1] - points[k]
        v = points[(k + 1) % len(points)] - points[k]
        out.append(math.acos(np.clip(np.dot(u, v) / np.linalg.norm(u) / np.linalg.norm(v), -1, 1)))
    return np.array(out)


@pytest.fixture(scope="module", params=[(10, 0.9, 15.0, 1), (10, 0.9, 15.0, -1), (4, 0.7, 30.0, 1),
                                        (6, 0.8, 60.0, -1)], ids=str)
def fold_file(request, tmp_path_factory):
    n, lam, Lc, chirality = request.param
    design = kresling.Design(n, lam, Lc, 30.0, chirality)
    path = tmp_path_factory.mktemp("fold") / "cell.fold"
    write_pattern(path, design, "laminate")
    return design, _read(path)


def test_structure(fold_file):
    design, doc = fold_file
    assert doc["file_spec"] == 1.1 and doc["frame_unit"] == "mm"
    assert doc["frame_classes"] == ["creasePattern"]
    v, e = len(doc["vertices_coords"]), len(doc["edges_vertices"])
    assert v == 4 * design.n + 4
    assert len(doc["edges_assignment"]) == len(doc["edges_foldAngle"]) == e
    assert set(doc["edges_assignment"]) <= {"M", "V", "B"}
    assert doc["edges_assignment"].count("V") == design.n
    assert [f["frame_title"] for f in doc["file_frames"]] == ["contracted", "extended"]
    for frame in doc["file_frames"]:
        assert frame["frame_parent"] == 0 and frame["frame_inherit"] is True
        assert np.shape(frame["vertices_coords"]) == (v, 3)
    # Every face side is an edge.
    edges = {frozenset(pair) for pair in doc["edges_vertices"]}
    for face in doc["faces_vertices"]:
        assert all(frozenset(pair) in edges for pair in zip(face, face[1:] + face[:1]))


def test_every_face_folds_isometrically_onto_both_states(fold_file):
    design, doc = fold_file
    flat = np.array(doc["vertices_coords"])
    for frame in doc["file_frames"]:
        folded = np.array(frame["vertices_coords"])
        for face in doc["faces_vertices"]:
            for a, b in itertools.combinations(face, 2):
                assert np.linalg.norm(folded[a] - folded[b]) == pytest.approx(
                    np.linalg.norm(flat[a] - flat[b]), abs=TOL)
            np.testing.assert_allclose(_corner_angles(folded[face]), _corner_angles(flat[face]),
                                       atol=1e-10)
            # Planar: every corner lies in the plane of the first three.
            normal = np.cross(folded[face[1]] - folded[face[0]], folded[face[2]] - folded[face[0]])
            normal /= np.linalg.norm(normal)
            assert np.all(np.abs((folded[face] - folded[face[0]]) @ normal) < TOL)


def test_strip_vertices_land_on_the_state_node_positions(fold_file):
    design, doc = fold_file
    n = design.n
    for frame in doc["file_frames"]:
        state = frame["frame_title"]
        bottom, top = design.vertices(state)
        folded = np.array(frame["vertices_coords"])
        strip_bottom, strip_top = folded[:n + 1], folded[n + 1:2 * n + 2]
        nearest = lambda nodes, x: np.linalg.norm(nodes - x, axis=1).min()  # noqa: E731
        assert max(nearest(bottom, x) for x in strip_bottom) < TOL
        assert max(nearest(top, x) for x in strip_top) < TOL
        assert np.linalg.norm(strip_bottom[-1] - strip_bottom[0]) < TOL   # closed strip
        assert np.linalg.norm(strip_top[-1] - strip_top[0]) < TOL


def test_fold_angles_match_assignments_and_geometry(fold_file):
    design, doc = fold_file
    assignments = np.array(doc["edges_assignment"])
    key = np.array(doc["edges_foldAngle"])
    extended = doc["file_frames"][1]
    np.testing.assert_array_equal(key, extended["edges_foldAngle"])
    for frame in doc["file_frames"]:
        angles = np.array(frame["edges_foldAngle"])
        recomputed = np.degrees(fold_angles(doc["faces_vertices"], doc["edges_vertices"],
                                            frame["vertices_coords"]))
        np.testing.assert_allclose(angles, recomputed, atol=1e-9)
        assert np.all(angles[assignments == "V"] > 0) and np.all(angles[assignments == "M"] < 0)
        assert np.all(angles[assignments == "B"] == 0)


def test_paper_marks_mountains_as_cut(tmp_path):
    path = write_pattern(tmp_path / "paper.fold", kresling.Design(8, 0.8, 15.0), "paper")
    doc = _read(path)
    kinds = doc["kresling:edges_crease"]
    assert [a for a, k in zip(doc["edges_assignment"], kinds) if k == "mountain"] == ["C"] * 7
    assert all(a == "V" for a, k in zip(doc["edges_assignment"], kinds) if k == "valley")


def test_fold_document_is_general_and_checks_its_input():
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    edges = [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]]
    faces = [[0, 1, 2], [0, 2, 3]]
    folded = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0.5, 0.5, math.sqrt(0.5)]]
    angles = np.degrees(fold_angles(faces, edges, folded))
    assert angles[4] == pytest.approx(90.0, abs=1e-9)          # folded up: a valley
    doc = fold_document(square, edges, "BBBBV", faces, edges_fold_angle=angles,
                        frames=[{"title": "folded", "vertices_coords": folded}])
    assert doc["file_frames"][0]["frame_classes"] == ["foldedForm"]
    json.dumps(doc, allow_nan=False)
    with pytest.raises(ValueError, match="edges_assignment has"):
        fold_document(square, edges, "BBBBX", faces)
    with pytest.raises(ValueError, match="must have one per edge"):
        fold_document(square, edges, "BBBB", faces)
    with pytest.raises(ValueError, match=r"faces_vertices\[1\] refers to vertex 7"):
        fold_document(square, edges, "BBBBV", [[0, 1, 2], [0, 2, 7]])
    with pytest.raises(ValueError, match="must be \\(4, 3\\)"):
        fold_document(square, edges, "BBBBV", faces, frames=[{"vertices_coords": square}])


def test_flat_folded_traditional_kresling_keeps_the_assignment_signs(tmp_path):
    """Lc = 0 folds the contracted cell flat: fold angles of +-180 degrees, signed by kind."""
    doc = _read(write_pattern(tmp_path / "flat.fold", kresling.Design(6, 0.8, 0.0), "laminate"))
    contracted = np.array(doc["file_frames"][0]["edges_foldAngle"])
    assignments = np.array(doc["edges_assignment"])
    np.testing.assert_allclose(contracted[assignments == "V"], 180.0, atol=1e-6)
    np.testing.assert_allclose(contracted[assignments == "M"], -180.0, atol=1e-6)
