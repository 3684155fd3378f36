"""Origami Simulator's own reader as the reference: its SVG importer's patterns (made by its
code, tests/data/public/origami_simulator/imported/) are the patterns kresling.io.read_svg
finds, vertex by vertex and crease by crease; and its FOLD opener, run in headless
Chromium, takes the FOLD files kresling writes (path.fold of a simulation among them)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import cKDTree

from kresling.io import read_fold, read_svg, separate_cuts, write_fold
from kresling.simulate import simulate
from browser import needs_browser
from kresling.testing.origami_simulator_page import import_svg, open_fold

PUBLIC = Path(__file__).resolve().parents[1] / "data" / "public"
DRAWINGS = PUBLIC / "origami_simulator"
IMPORTED = DRAWINGS / "imported"
NAMES = ["miura-ori", "waterbomb", "flappingBird", "birdBase", "waterbombBase"]
PX = 25.4 / 96                                   # mm per SVG user unit (a CSS pixel)


def _counts(vertices, faces, assignments) -> dict:
    return {"vertices": len(vertices), "faces": len(faces),
            **{letter: list(assignments).count(letter) for letter in "BMVFUCJ"}}


def _simulators_pattern(name):
    """Its importer's vertices in SVG user units as (x, y) of the drawing (it maps the
    drawing's y to its z), edges, letters and target angles [deg] (None: no target)."""
    document = json.loads((IMPORTED / f"{name}.fold").read_text())
    xy = np.array(document["vertices_coords"], dtype=float)[:, [0, 2]]
    return document, xy


@pytest.mark.parametrize("name", NAMES)
def test_svg_import_finds_the_vertices_faces_and_creases_origami_simulator_finds(name):
    ours = read_svg(DRAWINGS / f"{name}.svg")
    document, theirs = _simulators_pattern(name)
    assert _counts(ours.vertices, ours.faces, ours.edges_assignment) == _counts(
        theirs, document["faces_vertices"], document["edges_assignment"])
    # The same points: ours in mm with y up, the drawing's (and the simulator's) y down.
    # Its importer computes crossings in single precision (three.js vectors), ~1e-4 px on
    # these 2000 px drawings; 1e-2 px is far below the 3 px it merges points within.
    ours_xy = ours.vertices[:, :2] / PX * [1.0, -1.0]
    distance, match = cKDTree(theirs).query(ours_xy)
    assert distance.max() < 1e-2 and len(set(match.tolist())) == len(match)
    # The same edges between them, each with the same letter and target angle.
    theirs_edges = {tuple(sorted(e)): (a, angle) for e, a, angle in zip(
        document["edges_vertices"], document["edges_assignment"], document["edges_foldAngle"])}
    for (u, v), letter, angle in zip(ours.edges.tolist(), ours.edges_assignment,
                                     ours.edges_fold_angle):
        their_letter, their_angle = theirs_edges[tuple(sorted((match[u], match[v])))]
        assert letter == their_letter
        assert (their_angle is None and np.isnan(angle)) or angle == pytest.approx(their_angle)
    # And the same faces, as sets of corners.
    assert sorted(sorted(match[list(f)].tolist()) for f in ours.faces) == sorted(
        sorted(f) for f in document["faces_vertices"])


def test_the_bird_base_drawn_in_svg_has_the_counts_of_rabbit_ears_fold_file():
    drawn = read_svg(DRAWINGS / "birdBase.svg")
    fold = read_fold(PUBLIC / "rabbit_ear" / "bird-base-3d-cp.fold")
    assert _counts(drawn.vertices, drawn.faces, drawn.edges_assignment) == _counts(
        fold.vertices, fold.faces, fold.edges_assignment) == {
        "vertices": 13, "faces": 16, "B": 8, "M": 12, "V": 8, "F": 0, "U": 0, "C": 0, "J": 0}



def test_write_fold_lists_each_vertexs_neighbours_counter_clockwise_in_a_file_with_cuts(
        tmp_path):
    pattern = read_fold(PUBLIC / "rabbit_ear" / "crane-cp-bmvfcj.fold")
    document = json.loads(write_fold(tmp_path / "crane.fold", pattern).read_text())
    xy = np.array(document["vertices_coords"])[:, :2]
    edges = document["edges_vertices"]
    for v, (ring, ring_edges) in enumerate(zip(document["vertices_vertices"],
                                               document["vertices_edges"])):
        assert sorted(ring) == sorted(w for e in edges if v in e for w in e if w != v)
        assert [sorted(edges[k]) for k in ring_edges] == [sorted((v, w)) for w in ring]
        # Counter-clockwise (the sheet is flat, its faces counter-clockwise seen from +z):
        # the directions' angles increase round the ring, once round at most.
        angles = np.unwrap(np.arctan2(*(xy[ring] - xy[v]).T[::-1]))
        assert np.all(np.diff(angles) > 0) and angles[-1] - angles[0] < 2 * np.pi, v
    plain = read_fold(PUBLIC / "rabbit_ear" / "bird-base-3d-cp.fold")
    assert "vertices_vertices" not in json.loads(
        write_fold(tmp_path / "bird.fold", plain).read_text())


# -- in the browser: Origami Simulator's own code ------------------------------------------

@needs_browser
@pytest.mark.parametrize("name", ["flappingBird", "waterbombBase"])
def test_origami_simulators_importer_still_makes_the_imported_files(tmp_path, name):
    made = import_svg(DRAWINGS / f"{name}.svg", tmp_path)
    assert made["warnings"] == []
    stored = json.loads((IMPORTED / f"{name}.fold").read_text())
    for key in ("vertices_coords", "edges_vertices", "edges_assignment", "edges_foldAngle",
                "faces_vertices"):
        assert made["raw"][key] == stored[key], key


def _creases(document) -> int:
    """The creases Origami Simulator drives: M, V and F edges with a fold angle, between two
    faces (js/pattern.js, getFacesAndVerticesForEdges, line 820)."""
    faces = [set(f) for f in document["faces_vertices"]]
    return sum(1 for (u, v), a, angle in zip(document["edges_vertices"],
                                             document["edges_assignment"],
                                             document["edges_foldAngle"])
               if a in "MVF" and angle is not None
               and sum(1 for f in faces if u in f and v in f) == 2)


MANUAL = {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
          "fold_stiffness": 1.0, "bend_stiffness": 1.0}


def _folded_base(folder):
    """Origami Simulator's waterbomb base folded to 60 % of its targets: path.fold."""
    pattern = read_svg(DRAWINGS / "waterbombBase.svg")
    actuation = [{"edges": [e], "fold_angle_deg": 0.6 * angle} for e, a, angle in zip(
        pattern.edges.tolist(), pattern.edges_assignment, pattern.edges_fold_angle) if a in "MV"]
    return {"pattern": {"file": str(DRAWINGS / "waterbombBase.svg")}, "material": MANUAL,
            "support": [{"nodes": list(pattern.faces[0]), "fix": "xyz"}],
            "actuation": actuation, "laws": {"fold_limits_deg": [5.0, 355.0]},
            "analysis": {"method": "fold", "steps": 4}}


def _pushed_crane(folder):
    """Rabbit Ear's crane with every letter (cuts, joins, F, U) pushed: path.fold."""
    path = PUBLIC / "rabbit_ear" / "crane-cp-bmvfcj.fold"
    pattern = read_fold(path)
    return {"pattern": {"file": str(path), "unit": "unit", "scale": 100.0}, "material": MANUAL,
            "support": [{"nodes": list(pattern.faces[0]), "fix": "xyz"}],
            "load": [{"node": 5, "displacement": [0.0, 0.0, 1.0]}],
            "analysis": {"method": "displacement_control", "steps": 2}}


def _used(opened) -> int:
    return len({i for triangle in opened["triangles"] for i in triangle})


@needs_browser
@pytest.mark.parametrize("problem", [_folded_base, _pushed_crane], ids=["fold", "cuts"])
def test_origami_simulator_opens_path_fold_with_every_crease_and_its_angle(tmp_path, problem):
    sim = simulate(problem(tmp_path), progress=False)
    assert sim.path.completed, sim.path.message
    sim.write(tmp_path / "out", view=False)
    path = tmp_path / "out" / "path.fold"
    document = json.loads(path.read_text())
    opened = open_fold(path, tmp_path)
    assert opened["warnings"] == []
    # A flat key frame is written with 2 coordinates; it puts (x, y) at (x, 0, y)
    # (processFold, js/pattern.js line 564).
    assert opened["raw"]["vertices_coords"] == [
        [v[0], 0, v[1]] if len(v) == 2 else v for v in document["vertices_coords"]]
    # Its model: the file's triangles on the model's nodes (a cut, already separated in the
    # file, it separates again along its two sides: the slit's end vertices are copied and
    # the originals left unused, so the triangles use as many vertices as the model has),
    # one crease for each M, V and F edge between two faces (J, the panels' own edges, and
    # U it leaves free), each at the key frame's angle.
    assert len(opened["triangles"]) == len(document["faces_vertices"])
    assert _used(opened) == sim.model.num_nodes == len(document["vertices_coords"])
    assert len(opened["creases"]) == _creases(document) > 0
    driven = [angle for a, angle in zip(document["edges_assignment"],
                                        document["edges_foldAngle"]) if a in "MVF"]
    assert len(driven) == _creases(document)
    np.testing.assert_allclose(sorted(c[5] for c in opened["creases"]), sorted(driven),
                               rtol=0, atol=1e-9)


@needs_browser
@pytest.mark.parametrize("path", [PUBLIC / "rabbit_ear" / "crane-cp-bmvfcj.fold",
                                  PUBLIC / "rabbit_ear" / "bird-base-3d-cp.fold"],
                         ids=lambda p: p.name)
def test_origami_simulator_opens_what_write_fold_writes_of_a_public_file(tmp_path, path):
    # (Files with fold angles: without edges_foldAngle it asks the user in a dialogue.)
    pattern = read_fold(path)
    written = write_fold(tmp_path / path.name, pattern)
    document = json.loads(written.read_text())
    opened = open_fold(written, tmp_path)
    assert opened["warnings"] == []
    # It separates the cuts as kresling does (the crane's 2 cut edges: 2 copies).
    assert _used(opened) == separate_cuts(pattern).num_vertices
    assert len(opened["creases"]) == _creases(document) > 0


@needs_browser
def test_origami_simulator_needs_the_neighbour_order_to_separate_cuts(tmp_path):
    # Without vertices_vertices and vertices_edges, its cut separation (splitCuts,
    # js/pattern.js line 671) fails: the reason write_fold writes them with C edges.
    written = write_fold(tmp_path / "crane.fold", read_fold(PUBLIC / "rabbit_ear" /
                                                            "crane-cp-bmvfcj.fold"))
    document = json.loads(written.read_text())
    del document["vertices_vertices"], document["vertices_edges"]
    bare = tmp_path / "bare.fold"
    bare.write_text(json.dumps(document))
    assert open_fold(bare, tmp_path)["warnings"][0] == "Unable to parse FOLD json."
