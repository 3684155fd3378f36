"""path.fold is a FOLD file other tools read: faces, FOLD's letters, fold angles per frame, mm;
reading it back gives the model it came from (bars, hinges by family: joins come back as
bend hinges), a pattern read, written and read again builds the same model, and Origami
Simulator's rules for reading a FOLD file accept it."""

import json

import numpy as np
import pytest

from kresling.io import fold_angles, pattern_from_arrays, read_fold, write_fold
from kresling.model import ManualProperties, build_pattern_model
from kresling.simulate import simulate

MANUAL = {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
          "fold_stiffness": 0.05, "bend_stiffness": 0.5}


def _sheet():
    """Two by two quads (N5B8 gives them centre nodes), creases M and V, a cut slit."""
    points = [[x, y] for y in (0.0, 10.0, 20.0) for x in (0.0, 10.0, 20.0)]
    faces = [[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]]
    return pattern_from_arrays(points, faces, edges=[[1, 4], [3, 4], [4, 5], [4, 7]],
                               edges_assignment=["V", "M", "M", "C"])


def _problem(pattern_file):
    return {"pattern": {"file": str(pattern_file)}, "material": dict(MANUAL),
            "support": [{"nodes": [0, 1, 2], "fix": "xyz"}, {"nodes": [3, 5], "fix": "z"}],
            "load": [{"nodes": [6, 8], "displacement": [0.0, 0.0, 3.0]}],
            "analysis": {"method": "displacement_control", "steps": 4}}


def _families(pm):
    """The model as a set of bars and of (hinge nodes, family)."""
    bars = {tuple(sorted(b)) for b in pm.model.bars.tolist()}
    hinges = {(tuple(sorted(h[:2])), tuple(sorted(h[2:])), f)
              for h, f in zip(pm.model.hinges.tolist(), pm.hinge_family)}
    return bars, hinges


def _origami_simulator_problems(document) -> list:
    """Origami Simulator's rules for a FOLD file it is given (amandaghassaei/OrigamiSimulator,
    commit 7855983, reproduced, not its code; its code itself opens path.fold in
    tests/io/test_io_origami_simulator.py): js/importer.js line 112 needs vertices_coords,
    edges_vertices, edges_assignment and faces_vertices, lines 119-126 take edges_foldAngle
    (else it asks for one), and it reads the top level only (no file_frames); js/pattern.js
    processFold (line 564) takes 2 or 3 coordinates per vertex, splits cuts (line 584),
    triangulates faces of more than 3 corners (triangulatePolys, line 984), and builds a
    crease for each M, V or F edge with a non-null angle only where it finds two faces
    holding both its ends (getFacesAndVerticesForEdges, line 820), a facet crease when the
    angle is 0; js/model.js buildModel (line 195) stops on no vertices, faces or edges."""
    problems = []
    for key in ("vertices_coords", "edges_vertices", "edges_assignment", "faces_vertices"):
        if not document.get(key):
            problems.append(f"{key} missing or empty")
    if problems:
        return problems
    vertices, edges = document["vertices_coords"], document["edges_vertices"]
    if any(len(v) not in (2, 3) for v in vertices):
        problems.append("a vertex without 2 or 3 coordinates")
    if any(not (0 <= i < len(vertices)) for e in edges for i in e) or \
            any(not (0 <= i < len(vertices)) for f in document["faces_vertices"] for i in f):
        problems.append("an index out of range")
    angles = document.get("edges_foldAngle")
    if angles is None or len(angles) != len(edges):
        problems.append("edges_foldAngle missing or not one per edge")
        return problems
    if any(a not in "BMVFUCJ" for a in document["edges_assignment"]):
        problems.append("an assignment Origami Simulator does not know")
    faces = [set(f) for f in document["faces_vertices"]]
    for (u, v), letter, angle in zip(edges, document["edges_assignment"], angles):
        if letter in "MVF" and angle is not None:
            if not -180 <= angle <= 180:
                problems.append(f"edge {u}-{v}: angle {angle} out of [-180, 180]")
            if sum(1 for f in faces if u in f and v in f) != 2:
                problems.append(f"crease {u}-{v} ({letter}) is not between two faces")
    return problems


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("path")
    source = write_fold(folder / "sheet.fold", _sheet())
    simulation = simulate(_problem(source), progress=False)
    simulation.write(folder / "out", view=False)
    return simulation, folder / "out" / "path.fold"


def test_path_fold_has_faces_fold_letters_and_angles_per_frame_in_mm(run):
    simulation, path = run
    document = json.loads(path.read_text())
    assert document["frame_unit"] == "mm"
    assert len(document["faces_vertices"]) == len(simulation.pattern_model.elements.triangles)
    assert set(document["edges_assignment"]) <= {"B", "M", "V", "J", "C"}
    assert document["edges_assignment"].count("J") == 4 * 4      # the spokes of 4 quads
    frames = document["file_frames"]
    assert len(frames) == simulation.path.num_steps
    faces, edges = document["faces_vertices"], document["edges_vertices"]
    for frame in frames:
        # Each frame's angles are its geometry's, in FOLD's convention (+ valley).
        expected = np.degrees(fold_angles(faces, edges, frame["vertices_coords"]))
        np.testing.assert_allclose(frame["edges_foldAngle"], expected, atol=1e-9)
    last = dict(zip(map(tuple, edges), frames[-1]["edges_foldAngle"]))
    # Lifting the far row folds the middle row's creases up (a valley's sense: positive),
    # the crease across it far less.
    assert last[(3, 4)] > 10 and last[(4, 5)] > 10
    assert abs(last[(1, 4)]) < 0.2 * last[(3, 4)]
    assert _origami_simulator_problems(document) == []


def test_origami_simulators_rules_refuse_what_it_refuses(run):
    _, path = run
    document = json.loads(path.read_text())
    assert _origami_simulator_problems(dict(document, faces_vertices=[])) == [
        "faces_vertices missing or empty"]
    broken = dict(document, faces_vertices=[f for f in document["faces_vertices"] if 4 not in f])
    assert any("is not between two faces" in p for p in _origami_simulator_problems(broken))


def test_reading_path_fold_back_gives_the_same_model(run):
    simulation, path = run
    back = build_pattern_model(read_fold(path), material=ManualProperties(
        bar_modulus=1e3, bar_area=1.0, fold_stiffness=0.05, bend_stiffness=0.5))
    assert back.model.num_nodes == simulation.model.num_nodes   # triangles: no new centres
    assert _families(back) == _families(simulation.pattern_model)
    assert back.hinge_family.count("bend") == simulation.pattern_model.hinge_family.count(
        "bend") == 16


@pytest.mark.parametrize("split", ["N5B8", "N4B5"])
def test_a_pattern_read_written_and_read_again_builds_the_same_model(tmp_path, split):
    first = read_fold(write_fold(tmp_path / "a.fold", _sheet()))
    again = read_fold(write_fold(tmp_path / "b.fold", first))
    assert again == first
    material = ManualProperties(bar_modulus=1e3, bar_area=1.0, fold_stiffness=0.05,
                                bend_stiffness=0.5)
    models = [build_pattern_model(p, material=material, split=split) for p in (first, again)]
    assert _families(models[0]) == _families(models[1])
    np.testing.assert_array_equal(models[0].model.nodes, models[1].model.nodes)
