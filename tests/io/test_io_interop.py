"""Crease patterns as other tools write them: FOLD's units, frames and assignments as its
specification (1.2) says, faces derived from edges, coincident vertices, folded-flat key
frames, and Origami Simulator's F and U by a switch."""

import json
import math

import numpy as np
import pytest

from kresling.laws import SPRING_LAWS
from kresling.io import pattern_from_arrays, read_fold, read_pattern, separate_cuts, write_fold
from kresling.model import ManualProperties, SheetMaterial, build_pattern_model

MANUAL = ManualProperties(bar_modulus=1e3, bar_area=1.0, fold_stiffness=0.1, bend_stiffness=2.0)
SQUARE = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]


def _write(tmp_path, document, name="sheet.fold"):
    path = tmp_path / name
    path.write_text(json.dumps(document))
    return path


def _grid(n=3, size=10.0):
    """An n x n grid of square panels: vertices row by row, faces counter-clockwise."""
    points = [[i * size, j * size] for j in range(n + 1) for i in range(n + 1)]
    faces = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1,
              (j + 1) * (n + 1) + i] for j in range(n) for i in range(n)]
    return points, faces


# -- units -----------------------------------------------------------------------------------

@pytest.mark.parametrize("unit, factor", [("mm", 1.0), ("cm", 10.0), ("m", 1000.0),
                                          ("in", 25.4), ("pt", 25.4 / 72), ("unit", 1.0)])
def test_frame_unit_is_converted_to_mm(tmp_path, unit, factor):
    path = _write(tmp_path, {"vertices_coords": SQUARE, "faces_vertices": [[0, 1, 2, 3]],
                             "frame_unit": unit})
    np.testing.assert_allclose(read_fold(path).vertices[:, :2], np.array(SQUARE) * factor,
                               rtol=1e-15)


def test_a_unit_given_replaces_the_files_and_a_scale_sizes_a_unitless_one(tmp_path):
    path = _write(tmp_path, {"vertices_coords": SQUARE, "faces_vertices": [[0, 1, 2, 3]],
                             "frame_unit": "in"})
    assert read_pattern(path, unit="cm").vertices.max() == 100.0
    assert read_pattern(path, unit="unit", scale=2.5).vertices.max() == 25.0
    with pytest.raises(ValueError, match="scale = 2 is invalid with unit = 'cm'"):
        read_pattern(path, unit="cm", scale=2)
    bad = _write(tmp_path, {"vertices_coords": SQUARE, "faces_vertices": [[0, 1, 2, 3]],
                            "frame_unit": "furlong"}, "bad.fold")
    with pytest.raises(ValueError, match=r"bad\.fold: key 'frame_unit' = 'furlong' is a unit"):
        read_fold(bad)


def test_written_files_say_mm_and_read_back_the_same(tmp_path):
    pattern = pattern_from_arrays(SQUARE, [[0, 1, 2], [0, 2, 3]])
    path = write_fold(tmp_path / "p.fold", pattern, metadata={"frame_unit": "in"})
    assert json.loads(path.read_text())["vertices_coords"][1] == pytest.approx([10 / 25.4, 0])
    np.testing.assert_allclose(read_fold(path).vertices, pattern.vertices, rtol=1e-15,
                               atol=1e-15)


# -- faces from edges, frames ----------------------------------------------------------------

def test_faces_are_derived_from_a_flat_edge_graph(tmp_path):
    points, faces = _grid(3)
    pattern = pattern_from_arrays(points, faces)
    path = _write(tmp_path, {"vertices_coords": points, "edges_vertices": pattern.edges.tolist(),
                             "edges_assignment": list(pattern.edges_assignment)})
    derived = read_fold(path)
    assert derived.num_faces == 9
    # The same faces, counter-clockwise, each possibly starting at another corner.
    def canonical(face):
        k = face.index(min(face))
        return tuple(face[k:] + face[:k])
    assert sorted(canonical(list(f)) for f in derived.faces) == \
        sorted(canonical(f) for f in faces)
    folded = dict(json.loads(path.read_text()), vertices_coords=[p + [p[0] * p[1] / 50.0]
                                                                 for p in points])
    with pytest.raises(ValueError, match="faces_vertices' is missing and the frame is not flat"):
        read_fold(_write(tmp_path, folded, "folded.fold"))


def test_only_the_frame_in_use_is_checked_and_any_frame_can_be_chosen(tmp_path):
    folded = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [5, 5, math.sqrt(50)]]
    document = {"vertices_coords": folded, "faces_vertices": [[0, 1, 2], [0, 2, 3]],
                "edges_vertices": [[0, 2]], "edges_assignment": ["V"], "file_frames": [
                    # Another model altogether (its own vertices and faces): not checked.
                    {"vertices_coords": [[0, 0], [1, 0]], "faces_vertices": [[0, 1, 7]]},
                    # The flat crease pattern of the key frame's mesh.
                    {"frame_inherit": True, "frame_parent": 0, "vertices_coords": SQUARE}]}
    path = _write(tmp_path, document)
    key = read_fold(path)
    assert len(key.frames) == 1 and not np.any(key.frames[0][:, 2])
    flat = read_fold(path, frame=2)
    assert not np.any(flat.vertices[:, 2]) and flat.edges_assignment[0] == "V"
    np.testing.assert_array_equal(flat.frames[0], np.array(folded, float))
    with pytest.raises(ValueError, match=r"face 0 has vertex 7 out of range"):
        read_fold(path, frame=1)
    with pytest.raises(ValueError, match=r"frame = 3 is invalid: the file has frames 0 to 2"):
        read_fold(path, frame=3)


def test_a_folded_flat_key_frame_is_named_up_front_and_its_crease_pattern_frame_runs(tmp_path):
    flat_on_itself = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [10, 0, 1e-12]]
    document = {"vertices_coords": flat_on_itself, "faces_vertices": [[0, 1, 2], [0, 2, 3]],
                "edges_vertices": [[0, 2]], "edges_assignment": ["V"],
                "file_frames": [{"frame_inherit": True, "frame_parent": 0,
                                 "vertices_coords": SQUARE}]}
    path = _write(tmp_path, document)
    # Vertex 3 sits 1e-12 mm on the far side of the other panel: the exact angle is 360 deg
    # less 1.4e-13 rad (MERLIN2's side threshold of 1e-8 would call it 0).
    with pytest.raises(ValueError, match=r"1 hinge is folded flat at rest .*hinge 0 \(axis "
                                         r"0-2, valley\) at 360 deg.*\[pattern\] frame = K"):
        build_pattern_model(read_fold(path, planarity_tolerance=None), material=MANUAL)
    model = build_pattern_model(read_fold(path, frame=1), material=MANUAL).model
    assert model.hinge_rest_angle[0] == pytest.approx(math.pi)


# -- coincident vertices ---------------------------------------------------------------------

def test_a_vertex_written_twice_is_merged_and_a_cut_marked_c_kept(tmp_path, caplog):
    points = SQUARE + [[20.0, 0.0], [20.0, 10.0], [10.0, 0.0]]     # 6 repeats vertex 1
    document = {"vertices_coords": points, "faces_vertices": [[0, 1, 2, 3], [6, 4, 5, 2]]}
    merged = read_fold(_write(tmp_path, document))
    # The same sheet written with one vertex there (an independent reading).
    joined = read_fold(_write(tmp_path, {"vertices_coords": points[:6],
                                         "faces_vertices": [[0, 1, 2, 3], [1, 4, 5, 2]]},
                              name="joined.fold"))
    assert merged == joined
    assert "sheet.fold: 1 coincident vertex merged" in caplog.text
    assert "6 into 1 (0 mm apart)" in caplog.text
    # Marked as the two sides of a cut, the same file keeps both.
    document["edges_vertices"] = [[1, 2], [6, 2]]
    document["edges_assignment"] = ["C", "C"]
    assert read_fold(_write(tmp_path, document)).num_vertices == 7


# -- assignments -----------------------------------------------------------------------------

def _two_triangles(letter):
    return pattern_from_arrays(SQUARE, [[0, 1, 2], [0, 2, 3]], edges=[[0, 2]],
                               edges_assignment=[letter])


def test_a_join_is_a_bend_of_the_panel_not_a_fold():
    manual = build_pattern_model(_two_triangles("J"), material=MANUAL)
    assert manual.hinge_family == ("bend",) and manual.model.hinge_stiffness[0] == 2.0
    sheet = SheetMaterial(youngs_modulus=3e3, poisson_ratio=0.3, thickness=0.2)
    calibrated = build_pattern_model(_two_triangles("J"), material=sheet)
    # The bend formula with the join as the panel's diagonal (docs/model.md):
    # D (L / t)^(1/3) / L, D = E t^3 / (12 (1 - nu^2)).
    D, L = 3e3 * 0.2 ** 3 / (12 * (1 - 0.09)), math.hypot(10, 10)
    assert calibrated.model.hinge_stiffness[0] == pytest.approx(D * (L / 0.2) ** (1 / 3) / L,
                                                                rel=1e-14)
    assert calibrated.model.hinge_law[0] == SPRING_LAWS["super_linear_bend"]
    with pytest.raises(ValueError, match=r"bend_stiffness is missing: the pattern's 1 join"):
        build_pattern_model(_two_triangles("J"),
                            material=ManualProperties(bar_modulus=1e3, bar_area=1.0))


@pytest.mark.parametrize("letter, fold, origami_simulator", [
    ("M", ("mountain",), ("mountain",)), ("V", ("valley",), ("valley",)),
    ("F", ("flat",), ("bend",)), ("U", ("unassigned",), ()), ("J", ("bend",), ("bend",)),
    ("C", (), ())])
def test_the_two_conventions(letter, fold, origami_simulator):
    for convention, families in (("fold", fold), ("origami_simulator", origami_simulator)):
        pm = build_pattern_model(_two_triangles(letter), material=MANUAL,
                                 assignments=convention)
        assert pm.hinge_family == families, convention
        # The diagonal keeps its bar; a cut from corner to corner parts the two triangles
        # (6 nodes, each with its own copy of the diagonal).
        assert len(pm.model.bars) == (6 if letter == "C" else 5)
    with pytest.raises(ValueError, match="assignments = 'rabbit' is invalid"):
        build_pattern_model(_two_triangles("M"), material=MANUAL, assignments="rabbit")


def test_a_cut_separates_its_faces_and_a_slit_keeps_its_ends_joined():
    points, faces = _grid(3)
    pattern = pattern_from_arrays(points, faces)
    edges = [tuple(e) for e in pattern.edges.tolist()]

    def with_cuts(*cuts):
        letters = ["C" if tuple(sorted(e)) in cuts else a
                   for e, a in zip(edges, pattern.edges_assignment)]
        return pattern_from_arrays(points, faces, edges=pattern.edges, edges_assignment=letters)

    # A slit between the inner vertices 5 and 6: both ends stay joined round them, so no
    # vertex is copied; the slit's bar stays, its hinge goes.
    slit = with_cuts((5, 6))
    assert separate_cuts(slit) is slit
    pm = build_pattern_model(slit, split="N4B5", material=MANUAL)
    full = build_pattern_model(pattern, split="N4B5", material=MANUAL)
    assert len(pm.model.bars) == len(full.model.bars)
    assert len(pm.model.hinges) == len(full.model.hinges) - 1
    # Cut round face 1 (1-5, 5-6, 6-2; its fourth side 1-2 is the boundary): it comes off
    # as a piece of its own. Each of 1, 2, 5, 6 gets one copy, for the faces after the first
    # group round it; the cut edges become one C edge per side.
    cut = separate_cuts(with_cuts((1, 5), (5, 6), (2, 6)))
    assert cut.num_vertices == 16 + 4
    np.testing.assert_array_equal(cut.vertices[16:], pattern.vertices[[1, 2, 5, 6]])
    assert cut.faces[1] == (16, 2, 6, 18)
    others = {v for k, face in enumerate(cut.faces) if k != 1 for v in face}
    assert not others & set(cut.faces[1])
    assert cut.edges_assignment.count("C") == 6
    assert separate_cuts(cut) is cut                       # nothing left to separate


def test_faces_derived_from_edges_that_touch_themselves_are_refused_naming_the_file(tmp_path):
    # A triangle hanging inside the square from its corner 0: the region between them has
    # an outline through vertex 0 twice, which no panel can be.
    points = SQUARE + [[5.0, 2.0], [2.0, 5.0]]
    edges = [[0, 1], [1, 2], [2, 3], [3, 0], [0, 4], [4, 5], [5, 0]]
    with pytest.raises(ValueError, match=r"sheet\.fold: key 'edges_vertices' encloses a region "
                                         r"whose outline touches itself at vertex 0"):
        read_fold(_write(tmp_path, {"vertices_coords": points, "edges_vertices": edges}))
