"""Coincident vertices of a flat pattern file: a vertex written twice is merged (with a
warning naming the file and the vertices), a cut drawn as two boundaries or marked C stays
a cut, and a coincidence that no sheet has is refused naming the file and the vertices."""

import json

import numpy as np
import pytest

from kresling.io import read_fold, read_obj

# A 2 x 1 strip of unit squares, then a copy of its middle bottom vertex 1 (vertex 6).
STRIP = [[0.0, 0.0], [10.0, 0.0], [20.0, 0.0], [0.0, 10.0], [10.0, 10.0], [20.0, 10.0]]
LEFT, RIGHT = [0, 1, 4, 3], [1, 2, 5, 4]


def _fold(tmp_path, **document):
    path = tmp_path / "sheet.fold"
    path.write_text(json.dumps(document))
    return path


def _edges(pattern):
    """Every edge as {sorted pair: (assignment, fold angle or None)}."""
    return {tuple(sorted(e)): (a, None if np.isnan(x) else x) for e, a, x in
            zip(pattern.edges.tolist(), pattern.edges_assignment, pattern.edges_fold_angle)}


def test_a_copy_is_merged_into_the_sheet_written_once_keeping_the_files_crease(tmp_path,
                                                                              caplog):
    once = read_fold(_fold(tmp_path, vertices_coords=STRIP, faces_vertices=[LEFT, RIGHT],
                           edges_vertices=[[1, 4]], edges_assignment=["V"],
                           edges_foldAngle=[30]))
    # The right square uses the copy: its side 6-4 lies on the valley 1-4 of the left one.
    twice = read_fold(_fold(tmp_path, vertices_coords=STRIP + [STRIP[1]],
                            faces_vertices=[LEFT, [6, 2, 5, 4]], edges_vertices=[[1, 4]],
                            edges_assignment=["V"], edges_foldAngle=[30]))
    assert twice.num_vertices == 6 and twice.faces == once.faces
    assert _edges(twice) == _edges(once)
    assert _edges(twice)[(1, 4)] == ("V", 30.0)
    assert "sheet.fold: 1 coincident vertex merged" in caplog.text and "6 into 1" in caplog.text


def test_the_vertices_after_a_merged_copy_are_numbered_one_lower(tmp_path):
    # The copy (vertex 2) comes before the right square's other corners.
    points = STRIP[:2] + [STRIP[1]] + STRIP[2:]
    pattern = read_fold(_fold(tmp_path, vertices_coords=points,
                              faces_vertices=[[0, 1, 5, 4], [2, 3, 6, 5]]))
    np.testing.assert_array_equal(pattern.vertices[:, :2], STRIP)
    assert pattern.faces == (tuple(LEFT), tuple(RIGHT))


def test_frames_lose_the_copys_row_too(tmp_path):
    moved = [[x, y, 1.0] for x, y in STRIP + [STRIP[1]]]
    pattern = read_fold(_fold(tmp_path, vertices_coords=STRIP + [STRIP[1]],
                              faces_vertices=[LEFT, [6, 2, 5, 4]],
                              file_frames=[{"vertices_coords": moved}]))
    assert len(pattern.frames) == 1
    np.testing.assert_array_equal(pattern.frames[0], np.array(moved[:6]))


@pytest.mark.parametrize("letter", ["B", "C"])
def test_a_slit_the_file_draws_as_two_boundaries_stays_a_slit(tmp_path, letter):
    # Vertices 1 and 6 at one point, the file assigning both sides of the seam B (FOLD 1.1's
    # way of drawing a slit) or C: the faces stay apart.
    pattern = read_fold(_fold(tmp_path, vertices_coords=STRIP + [STRIP[1]],
                              faces_vertices=[LEFT, [6, 2, 5, 4]],
                              edges_vertices=[[1, 4], [6, 4]],
                              edges_assignment=[letter, letter]))
    assert pattern.num_vertices == 7
    assert pattern.faces[1] == (6, 2, 5, 4)


def test_faces_meeting_at_a_point_only_are_refused_naming_the_file_and_vertices(tmp_path):
    # Two squares touching corner to corner: merging would join them at one point.
    points = [[0, 0], [10, 0], [10, 10], [0, 10], [10, 10], [20, 10], [20, 20], [10, 20]]
    with pytest.raises(ValueError, match=r"sheet\.fold: vertices 2 and 4 coincide \(0 mm "
                                         r"apart\) and their faces share no edge there"):
        read_fold(_fold(tmp_path, vertices_coords=points,
                        faces_vertices=[[0, 1, 2, 3], [4, 5, 6, 7]]))


def test_a_merge_that_would_put_three_faces_on_an_edge_is_refused(tmp_path):
    # Two triangles on the square's diagonal 0-2 already; a third (overlapping the first,
    # turning the same way) uses a copy of 2.
    points = [[0, 0], [10, 0], [10, 10], [0, 10], [10, 10], [10, -5]]
    with pytest.raises(ValueError, match=r"sheet\.fold: merging coincident vertices would put "
                                         r"faces 0, 1, 2 on one edge 0-2"):
        read_fold(_fold(tmp_path, vertices_coords=points,
                        faces_vertices=[[0, 1, 2], [0, 2, 3], [0, 5, 4]]))


def test_conflicting_creases_laid_on_one_edge_are_refused(tmp_path):
    with pytest.raises(ValueError, match=r"sheet\.fold: merging coincident vertices would make "
                                         r"edges .* one, but the file assigns them M and V"):
        read_fold(_fold(tmp_path, vertices_coords=STRIP + [STRIP[1]],
                        faces_vertices=[LEFT, [6, 2, 5, 4]], edges_vertices=[[1, 4], [6, 4]],
                        edges_assignment=["M", "V"]))


def test_an_obj_copy_is_merged_and_named_from_1(tmp_path, caplog):
    text = "".join(f"v {x} {y} 0\n" for x, y in STRIP + [STRIP[1]])
    path = tmp_path / "sheet.obj"
    path.write_text(text + "f 1 2 5 4\nf 7 3 6 5\n")
    pattern = read_obj(path)
    assert pattern.num_vertices == 6 and pattern.faces == (tuple(LEFT), tuple(RIGHT))
    assert "sheet.obj: 1 coincident vertex merged" in caplog.text and "7 into 2" in caplog.text


def test_a_folded_pattern_is_not_merged(tmp_path):
    # Folded flat in half: corners of the two halves lie on each other (no copy).
    points = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0], [10, 0, 0], [0, 0, 0]]
    pattern = read_fold(_fold(tmp_path, vertices_coords=points,
                              faces_vertices=[[0, 1, 2, 3], [3, 2, 4, 5]]),
                        planarity_tolerance=None)
    assert pattern.num_vertices == 6
