"""STL files through kresling.io: one fan triangle per face corner beyond two, unit normals
that agree with the triangles' corner order, and the binary layout's size and contents."""

import json
import math

import numpy as np
import pytest

import kresling
from kresling.fabrication import write_pattern
from kresling.io import fan_triangles, read_fold, write_stl


def _polygon(sides, radius=5.0, centre=(0.0, 0.0, 0.0)):
    return [[centre[0] + radius * math.cos(2 * math.pi * k / sides),
             centre[1] + radius * math.sin(2 * math.pi * k / sides), centre[2]]
            for k in range(sides)]


@pytest.fixture
def mesh():
    """A triangle, a square, a hexagon and an octagon; the octagon tilted about x."""
    vertices = _polygon(3) + _polygon(4, centre=(20, 0, 0)) + _polygon(6, centre=(40, 0, 0))
    octagon = np.array(_polygon(8, centre=(0, 0, 0)))
    tilt = np.array([[1, 0, 0], [0, math.cos(0.7), -math.sin(0.7)],
                     [0, math.sin(0.7), math.cos(0.7)]])
    vertices += (octagon @ tilt.T + [60, 0, 5]).tolist()
    sizes = [3, 4, 6, 8]
    starts = np.cumsum([0] + sizes[:-1])
    faces = [list(range(s, s + k)) for s, k in zip(starts, sizes)]
    faces[1] = faces[1][::-1]                    # one clockwise face: its normals point down
    return np.array(vertices), faces


def _parse_ascii(text):
    lines = [line.split() for line in text.splitlines()]
    assert lines[0][0] == "solid" and lines[-1][0] == "endsolid"
    normals = [list(map(float, line[2:])) for line in lines if line[0] == "facet"]
    corners = [list(map(float, line[1:])) for line in lines if line[0] == "vertex"]
    assert sum(line[0] == "endfacet" for line in lines) == len(normals)
    assert sum(line == ["outer", "loop"] for line in lines) == len(normals)
    return np.array(normals), np.array(corners).reshape(-1, 3, 3)


def _check_normals(normals, corners):
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-6)
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    cross /= np.linalg.norm(cross, axis=1)[:, None]
    np.testing.assert_allclose(normals, cross, atol=1e-6)    # right-hand rule on the corners


def test_ascii_has_one_facet_per_fan_triangle(tmp_path, mesh):
    vertices, faces = mesh
    path = write_stl(tmp_path / "mesh.stl", vertices, faces)
    text = path.read_text()
    assert text.startswith("solid kresling\n") and text.endswith("endsolid kresling\n")
    normals, corners = _parse_ascii(text)
    assert len(normals) == sum(len(face) - 2 for face in faces) == 1 + 2 + 4 + 6
    _check_normals(normals, corners)
    # The fan: every triangle of a face starts at its first corner, in face order.
    triangles = fan_triangles(faces)
    np.testing.assert_array_equal(corners, vertices[triangles])
    assert triangles[1:3].tolist() == [[6, 5, 4], [6, 4, 3]]
    np.testing.assert_allclose(normals[1:3], [[0, 0, -1]] * 2, atol=1e-12)
    np.testing.assert_allclose(normals[-1], [0, -math.sin(0.7), math.cos(0.7)], atol=1e-12)


def test_binary_layout(tmp_path, mesh):
    vertices, faces = mesh
    path = write_stl(tmp_path / "mesh.stl", vertices, faces, binary=True, name="cell n=10")
    data = path.read_bytes()
    count = sum(len(face) - 2 for face in faces)
    assert len(data) == 84 + 50 * count
    assert not data.startswith(b"solid")              # would confuse readers with ASCII STL
    assert b"cell n=10" in data[:80]
    assert int(np.frombuffer(data[80:84], "<u4")[0]) == count
    records = np.frombuffer(data[84:], dtype=[("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)),
                                              ("attribute", "<u2")])
    _check_normals(records["normal"].astype(float), records["corners"].astype(float))
    np.testing.assert_allclose(records["corners"], vertices[fan_triangles(faces)], atol=1e-5)
    assert np.all(records["attribute"] == 0)


def test_a_fabrication_pattern_and_its_folded_frame(tmp_path):
    fold = write_pattern(tmp_path / "cell.fold", kresling.Design(10, 0.9, 15.0, 30.0))
    pattern = read_fold(fold)
    flat = write_stl(tmp_path / "flat.stl", pattern.vertices, pattern.faces)
    folded = write_stl(tmp_path / "folded.stl", pattern.frames[1], pattern.faces, binary=True)
    count = sum(len(face) - 2 for face in pattern.faces)
    normals, _ = _parse_ascii(flat.read_text())
    assert len(normals) == count
    np.testing.assert_allclose(normals, [[0, 0, 1]] * count, atol=1e-12)   # counter-clockwise
    assert folded.stat().st_size == 84 + 50 * count
    assert json.loads(fold.read_text())["frame_unit"] == "mm"


def test_name_two_d_input_and_a_sliver_in_a_non_convex_fan(tmp_path):
    # A notched hexagon whose fan from corner 0 has a zero-area triangle (0, 3, 4): it takes
    # the face's normal.
    shape = [[0, 0], [4, 0], [4, 2], [2, 2], [1, 1], [0, 2]]
    text = write_stl(tmp_path / "l.stl", shape, [list(range(6))],
                     name="an L\nshape").read_text()
    assert text.splitlines()[0] == "solid an_L_shape"
    normals, corners = _parse_ascii(text)
    assert len(normals) == 4
    sliver = corners[2] - corners[2, 0]
    assert np.linalg.norm(np.cross(sliver[1], sliver[2])) == 0
    np.testing.assert_allclose(normals, [[0, 0, 1]] * 4, atol=1e-12)


def test_bad_input_names_the_face(tmp_path):
    with pytest.raises(ValueError, match=r"faces\[1\]: face 1 has 2 vertices"):
        write_stl(tmp_path / "x.stl", _polygon(4), [[0, 1, 2], [0, 1]])
    with pytest.raises(ValueError, match=r"faces\[0\]: face 0 has vertex 4 out of range"):
        write_stl(tmp_path / "x.stl", _polygon(4), [[0, 1, 4]])
    with pytest.raises(ValueError, match=r"faces\[1\]: face 1 is degenerate: its corners are "
                                         r"collinear"):
        write_stl(tmp_path / "x.stl", [[0, 0], [1, 0], [0, 1], [2, 0]],
                  [[0, 1, 2], [0, 1, 3]], binary=True)
    with pytest.raises(ValueError, match=r"vertices\[1\]: vertex 1 has a non-finite"):
        write_stl(tmp_path / "x.stl", [[0, 0], [np.inf, 0], [0, 1]], [[0, 1, 2]])
    assert not (tmp_path / "x.stl").exists()
