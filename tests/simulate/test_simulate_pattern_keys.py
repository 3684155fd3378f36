"""The [pattern] keys for patterns from other tools: unit, scale, frame, assignments; bad
values named with the file, table and key."""

import json

import numpy as np
import pytest

from kresling.simulate import build_problem_model, load_problem

SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]


def _problem(tmp_path, pattern_keys, document=None):
    fold = tmp_path / "sheet.fold"
    fold.write_text(json.dumps(document or {
        "frame_unit": "in", "vertices_coords": SQUARE, "faces_vertices": [[0, 1, 2], [0, 2, 3]],
        "edges_vertices": [[0, 2]], "edges_assignment": ["F"],
        "file_frames": [{"frame_inherit": True, "frame_parent": 0,
                         "vertices_coords": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0.5, 0.5, 0.5]]}]}))
    keys = "".join(f"{k} = {json.dumps(v)}\n" for k, v in pattern_keys.items())
    problem = tmp_path / "problem.toml"
    problem.write_text(f'[pattern]\nfile = "sheet.fold"\n{keys}'
                       '[material]\ncalibration = "manual"\nbar_modulus = 1e3\nbar_area = 1.0\n'
                       'fold_stiffness = 0.1\nbend_stiffness = 1.0\n'
                       '[[support]]\nnodes = [0, 1, 2]\nfix = "xyz"\n'
                       '[[load]]\nnode = 3\ndisplacement = [0.0, 0.0, 1.0]\n'
                       '[analysis]\nmethod = "displacement_control"\nsteps = 2\n')
    return problem


def test_unit_scale_frame_and_assignments_reach_the_model(tmp_path):
    inches = load_problem(_problem(tmp_path, {}))
    assert inches.pattern.vertices.max() == 25.4 and inches.assignments == "fold"
    scaled = load_problem(_problem(tmp_path, {"unit": "unit", "scale": 40.0}))
    assert scaled.pattern.vertices.max() == 40.0
    assert scaled.analysis.tolerance == pytest.approx(1e-8 * 40.0 * np.sqrt(2))
    folded = load_problem(_problem(tmp_path, {"frame": 1}))
    assert folded.pattern.vertices[3, 2] == pytest.approx(0.5 * 25.4)
    assert build_problem_model(_problem(tmp_path, {})).hinge_family == ("flat",)
    facet = build_problem_model(_problem(tmp_path, {"assignments": "origami_simulator"}))
    assert facet.hinge_family == ("bend",)


@pytest.mark.parametrize("keys, message", [
    ({"unit": "furlong"}, r"\[pattern\] key 'unit' = 'furlong' is invalid: must be one of"),
    ({"scale": 2.0}, r"\[pattern\] key 'scale' = 2\.0 applies only with unit = \"unit\""),
    ({"unit": "mm", "scale": 2.0}, r"key 'scale' = 2\.0 applies only with unit"),
    ({"frame": -1}, r"\[pattern\] key 'frame' = -1 is invalid: must be >= 0"),
    ({"frame": 5}, r"sheet\.fold: frame = 5 is invalid: the file has frames 0 to 1"),
    ({"assignments": "rabbit"}, r"\[pattern\] key 'assignments' = 'rabbit' is invalid"),
])
def test_bad_pattern_keys_are_named(tmp_path, keys, message):
    with pytest.raises(ValueError, match=message):
        load_problem(_problem(tmp_path, keys))


# A 2 x 1 strip whose right square uses a copy (vertex 2) of vertex 1: read, the copy is
# merged and the vertices after it are numbered one lower.
_STRIP_WITH_A_COPY = {"vertices_coords": [[0.0, 0.0], [10.0, 0.0], [10.0, 0.0], [20.0, 0.0],
                                          [0.0, 10.0], [10.0, 10.0], [20.0, 10.0]],
                      "faces_vertices": [[0, 1, 5, 4], [2, 3, 6, 5]],
                      "edges_vertices": [[1, 5]], "edges_assignment": ["V"],
                      "edges_foldAngle": [30]}


@pytest.mark.parametrize("named", [
    {"support": [{"node": 3, "fix": "xyz"}]},
    {"actuation": [{"edges": [[1, 5]], "fold_angle_deg": 30.0}]},
])
def test_node_numbers_of_a_file_with_a_merged_copy_are_refused(tmp_path, named):
    import json

    path = tmp_path / "strip.fold"
    path.write_text(json.dumps(_STRIP_WITH_A_COPY))
    problem = {"pattern": {"file": str(path)}, "analysis": {"method": "fold"},
               "actuation": [{"family": "fold", "fold_angle_deg": "file"}], **named}
    # Node 3 of the file is the strip's corner (20, 0); of the merged pattern, (0, 10).
    with pytest.raises(ValueError, match=r"numbers nodes of a pattern whose file writes a "
                                         r"vertex twice \(.*strip.fold: 1 coincident vertex"):
        load_problem(problem)


def test_a_file_with_a_merged_copy_folds_when_no_node_is_named(tmp_path):
    import json

    path = tmp_path / "strip.fold"
    path.write_text(json.dumps(_STRIP_WITH_A_COPY))
    problem = load_problem({"pattern": {"file": str(path)}, "analysis": {"method": "fold"},
                            "actuation": [{"family": "fold", "fold_angle_deg": "file"}]})
    assert problem.renumbered and problem.pattern.num_vertices == 6
