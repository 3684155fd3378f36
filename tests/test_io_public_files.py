"""Public crease-pattern files as their tools write them (tests/data/public/, with their
origins and licences in its README): each loads, takes a small push, and folds as its tool
shows it; the same file at 1 mm, 100 mm and 1 m gives the same normalised path; and read,
written and read again, each builds the same model."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest

from kresling.io import fold_angles, read_fold, read_pattern, write_fold
from kresling.model import ManualProperties, build_pattern_model
from kresling.simulate import simulate

PUBLIC = Path(__file__).resolve().parent / "data" / "public"
SPEC, RABBIT_EAR, ORIGAMI_SIMULATOR = (PUBLIC / "fold_spec", PUBLIC / "rabbit_ear",
                                       PUBLIC / "origami_simulator")
#: Stiff bars, panels as stiff in bending as the creases in folding (N, mm).
STIFF = {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
         "fold_stiffness": 1.0, "bend_stiffness": 1.0}
MANUAL = ManualProperties(bar_modulus=1e5, bar_area=1.0, fold_stiffness=1.0, bend_stiffness=1.0)
#: The unit-square files (FOLD's "unit") are read as a 100 mm sheet.
SHEET = {"unit": "unit", "scale": 100.0}

#: Files whose key frame is a model to start from: (file, [pattern] keys).
OPEN = [(SPEC / "diagonal-cp.fold", SHEET), (SPEC / "squaretwist.fold", SHEET),
        (RABBIT_EAR / "wavy-miura-no-faces.fold", SHEET),
        (RABBIT_EAR / "bird-base-3d-cp.fold", SHEET), (RABBIT_EAR / "bird-base-3d.fold",
                                                       dict(SHEET, frame=1)),
        (RABBIT_EAR / "crane.fold", dict(SHEET, frame=1)),
        (RABBIT_EAR / "crane-cp-bmvfcj.fold", SHEET),
        (ORIGAMI_SIMULATOR / "flappingBird.svg", {}), (ORIGAMI_SIMULATOR / "birdBase.svg", {}),
        (ORIGAMI_SIMULATOR / "waterbombBase.svg", {}), (ORIGAMI_SIMULATOR / "miura-ori.svg", {}),
        (ORIGAMI_SIMULATOR / "waterbomb.svg", {}),
        (ORIGAMI_SIMULATOR / "BoxPleatInOutWave-corner.fold",
         dict(SHEET, assignments="origami_simulator"))]


def _read(path, keys):
    return read_pattern(path, **{k: v for k, v in keys.items() if k in ("unit", "scale", "frame")})


def _held_and_far(pattern):
    """The corners of the first panel (held: no rigid-body motion, nothing blocked) and the
    vertex farthest from them."""
    held = list(pattern.faces[0][:3])
    distance = np.linalg.norm(pattern.vertices - pattern.vertices[held[0]], axis=1)
    distance[held] = -1.0
    return held, int(np.argmax(distance))


def _size(pattern) -> float:
    return float(np.linalg.norm(np.ptp(pattern.vertices, axis=0)))


def _push(path, keys, steps=8, scale=1.0, material=STIFF):
    pattern = _read(path, keys)
    held, far = _held_and_far(pattern)
    normal = np.cross(*(pattern.vertices[held[1:]] - pattern.vertices[held[0]]))
    push = 0.01 * _size(pattern) * normal / np.linalg.norm(normal)
    problem = {"pattern": {"file": str(path), **keys}, "material": dict(material),
               "support": [{"nodes": held, "fix": "xyz"}],
               "load": [{"node": far, "displacement": [0.0, 0.0, 0.0]}],
               "analysis": {"method": "displacement_control", "steps": steps}}
    # Push the far vertex off the held panel's plane along the axis nearest its normal.
    axis = int(np.argmax(np.abs(push)))
    problem["load"][0]["displacement"][axis] = float(push[axis])
    return pattern, far, axis, simulate(problem, progress=False)


@pytest.mark.parametrize("path, keys", OPEN, ids=lambda v: getattr(v, "name", ""))
def test_each_file_takes_a_small_push_with_its_work_stored_as_energy(path, keys):
    pattern, far, axis, sim = _push(path, keys)
    assert sim.completed, sim.path.message
    assert sim.path.num_steps >= 8
    u = sim.path.displacement[:, 3 * far + axis]
    force = -sim.path.constraint_force[:, 0]        # the path holds -f_int there
    energy = sim.history_columns()["energy_total"]
    # The work of the driving force (trapezoids over the increments, from rest) is the
    # energy stored: an independent balance. The force is nearly linear in a push of 1 % of
    # the size; the trapezoids' error, measured, is below 0.6 % on these files.
    work = np.concatenate([[0.0], np.cumsum(0.5 * (force[1:] + force[:-1]) * np.diff(u))])
    work += 0.5 * force[0] * u[0]
    assert energy[-1] > 0
    np.testing.assert_allclose(work, energy, rtol=1e-2, atol=1e-3 * energy[-1])



def test_rabbit_ears_sheet_of_edges_only_gets_the_faces_its_edges_enclose():
    path = RABBIT_EAR / "wavy-miura-no-faces.fold"
    document = json.loads(path.read_text())
    assert "faces_vertices" not in document
    pattern = read_fold(path)
    # One sheet, a disc: Euler's formula V - E + F = 1 (the outside not counted).
    assert pattern.num_faces == len(document["edges_vertices"]) - pattern.num_vertices + 1 == 64
    # Each face's sides are the file's edges; each crease lies between two faces, each
    # boundary edge on one.
    sides = {}
    for face in pattern.faces:
        for u, v in zip(face, face[1:] + face[:1]):
            sides[tuple(sorted((u, v)))] = sides.get(tuple(sorted((u, v))), 0) + 1
    edges = {tuple(sorted(e)): a for e, a in zip(document["edges_vertices"],
                                                 document["edges_assignment"])}
    assert set(sides) == set(edges)
    assert all(sides[e] == (1 if a == "B" else 2) for e, a in edges.items())


# -- folded flat: named up front -------------------------------------------------------------

def _flat_folded_creases(pattern) -> int:
    """Creases (any letter with a hinge) whose two faces lie on each other in the key frame,
    counted from the geometry alone: |fold angle| within 1 deg of 180."""
    angles = np.degrees(fold_angles(pattern.faces, pattern.edges, pattern.vertices))
    hinged = np.array([a in "MVFUJ" for a in pattern.edges_assignment])
    return int(np.sum(hinged & (np.abs(angles) > 179.0)))


@pytest.mark.parametrize("path", [SPEC / "box.fold", SPEC / "simple.fold",
                                  SPEC / "diagonal-folded.fold",
                                  RABBIT_EAR / "pleats-angle-3d.fold"], ids=lambda p: p.name)
def test_a_folded_flat_key_frame_is_refused_up_front_naming_its_hinges(path):
    pattern = read_fold(path)
    count = _flat_folded_creases(pattern)
    assert count > 0
    word = "hinge is" if count == 1 else "hinges are"
    with pytest.raises(ValueError, match=rf"{path.name}: {count} {word} folded flat at rest "
                                         r".*\[pattern\] frame = K"):
        build_pattern_model(pattern, material=MANUAL)


# -- folding as the tools show it ------------------------------------------------------------

def _fold(path, keys, targets, steps):
    """Fold the pattern's creases (M and V) to ``targets`` [deg], one per edge; the model's
    vertices at the end and the fold's summary."""
    pattern = _read(path, keys)
    held, _ = _held_and_far(pattern)
    actuation = [{"edges": [edge], "fold_angle_deg": float(target)}
                 for edge, letter, target in zip(pattern.edges.tolist(),
                                                 pattern.edges_assignment, targets)
                 if letter in "MV"]
    sim = simulate({"pattern": {"file": str(path), **keys}, "material": STIFF,
                    "laws": {"fold_limits_deg": [1.0, 359.0]},
                    "support": [{"nodes": held, "fix": "xyz"}], "actuation": actuation,
                    "analysis": {"method": "fold", "steps": steps}}, progress=False)
    assert sim.completed, sim.path.message
    x = (sim.model.nodes + sim.path.displacement[-1].reshape(-1, 3))[:pattern.num_vertices]
    return pattern, x, sim.summary()["fold"]


def _distances(x):
    return np.linalg.norm(x[:, None] - x[None], axis=2)


def test_the_fold_specs_diagonal_folds_about_its_diagonal_as_a_rigid_rotation():
    # diagonal-cp.fold: a unit square, one valley from corner 3 to corner 1 with
    # edges_foldAngle 180 (diagonal-folded.fold is that state). 180 deg itself, faces on
    # each other, is outside the spring laws' range: fold to 170 deg.
    cp = read_fold(SPEC / "diagonal-cp.fold", **SHEET)
    assert cp.edges_fold_angle[4] == 180.0
    pattern, x, report = _fold(SPEC / "diagonal-cp.fold", SHEET, [170.0] * 5, steps=17)
    assert report["short_of_target"] == 0 and report["left_branch"] == 0
    # The closed form: the first triangle (0, 1, 3) is held; corner 2 turns about the
    # diagonal 3-1 by 170 deg, to 10 deg short of lying on corner 0, on the +z side (a
    # valley, the faces counter-clockwise seen from +z).
    assert _held_and_far(pattern)[0] == [0, 1, 3]
    centre, radius = np.array([50.0, 50.0, 0.0]), 50.0 * math.sqrt(2.0)
    towards_0 = -centre / radius
    expected = centre + radius * (math.cos(math.radians(10.0)) * towards_0
                                  + math.sin(math.radians(10.0)) * np.array([0.0, 0.0, 1.0]))
    np.testing.assert_allclose(x[2], expected, atol=1e-6 * 100.0)      # stiff bars: 1e-6
    folded = read_fold(SPEC / "diagonal-folded.fold", **SHEET, planarity_tolerance=None)
    assert np.linalg.norm(x[2] - folded.vertices[2]) == pytest.approx(
        2 * radius * math.sin(math.radians(5.0)), rel=1e-6)


@pytest.mark.parametrize("path, crease_frame, folded_frame", [
    (RABBIT_EAR / "bird-base-3d.fold", 1, 0), (RABBIT_EAR / "bird-base-3d-cp.fold", 0, 1)],
    ids=lambda v: getattr(v, "name", str(v)))
def test_the_bird_base_folds_into_its_files_folded_frame(path, crease_frame, folded_frame):
    # Rabbit Ear's 3D bird base: a crease pattern and a folded frame that is not flat. Folded
    # to the folded frame's angles (measured on it), the model takes its shape.
    folded = read_fold(path, frame=folded_frame, **SHEET)
    targets = np.degrees(fold_angles(folded.faces, folded.edges, folded.vertices))
    # The file's own edges_foldAngle agree with its geometry to 0.14 deg.
    stated = read_fold(path, **SHEET).edges_fold_angle
    assert np.nanmax(np.abs(stated - targets)) < 0.14
    pattern, x, report = _fold(path, dict(SHEET, frame=crease_frame), targets, steps=20)
    assert report["short_of_target"] == 0 and report["left_branch"] == 0
    # Every distance between vertices as in the folded frame, to 0.12 % of the 100 mm sheet
    # (measured 0.116 mm: the frame is stress-free for its creases only to the 0.14 deg
    # above, so the panels strain a little).
    np.testing.assert_allclose(_distances(x), _distances(folded.vertices), atol=0.12)


#: Folding every crease at once from flat, the model sends some creases of these two the other
#: way (measured: the crane 13 of 102 at a tenth of the way, and 5 to 19 with other
#: stiffness ratios or N4B5; the flapping bird 2 or 3 of 37 at 10 % to 60 %). Recorded here
#: until the fold from flat follows the assignments on patterns that are not rigidly
#: foldable.
NOT_YET = pytest.mark.xfail(strict=True, reason="simultaneous folding from flat takes a few "
                                                "creases the other way (see NOT_YET)")


@NOT_YET
def test_the_crane_folds_towards_its_folded_frame_each_crease_in_its_sense():
    # Rabbit Ear's crane: the key frame is the folded crane (flat: every crease at +-180),
    # frame 1 its crease pattern. The flat-folded crane is out of reach (faces on each other,
    # and the pattern is not rigidly foldable: its panels must bend on the way), so the
    # crease pattern is folded to a tenth of the way, as a simulator's slider shows it
    # starting; every crease that moves (more than 1 deg) goes the way the crane has it.
    crane = read_fold(RABBIT_EAR / "crane.fold", **SHEET)
    creases = np.array([a in "MV" for a in crane.edges_assignment])
    measured = np.degrees(fold_angles(crane.faces, crane.edges, crane.vertices))
    assert np.all(np.abs(np.abs(measured[creases]) - 180.0) < 1e-6)
    # Folded flat, the geometry cannot tell +180 from -180: the letters say which.
    targets = np.where(np.array(crane.edges_assignment) == "M", -180.0, 180.0)
    pattern, x, report = _fold(RABBIT_EAR / "crane.fold", dict(SHEET, frame=1), 0.1 * targets,
                               steps=10)
    assert report["creases_driven"] == creases.sum() == 102
    assert report["left_branch"] == 0
    reached = np.degrees(fold_angles(pattern.faces, pattern.edges, x))[creases]
    moved = np.abs(reached) > 1.0
    assert moved.sum() > 0.5 * creases.sum()
    assert np.all(np.sign(reached[moved]) == np.sign(targets[creases][moved]))


@pytest.mark.parametrize("name, steps", [
    ("birdBase.svg", 20), ("waterbombBase.svg", 20), ("waterbomb.svg", 60),
    pytest.param("flappingBird.svg", 20, marks=NOT_YET)])
def test_origami_simulators_patterns_fold_at_its_default_percent_each_crease_in_its_sense(
        name, steps):
    # Origami Simulator opens a pattern folded to 60 % of each crease's target, the stroke
    # opacity times 180 deg (creasePercent = 0.6 in its js/globals.js): fold to that. The
    # creases cannot all reach it together (none of these is rigidly foldable with its
    # creases at one common fraction: the panels bend and the creases share the strain), so
    # what is checked is the sense of every crease and that each goes at least half way.
    # (The waterbomb tessellation's first increments need to be small: with 10 steps to 30 %
    # the first one fails even after its bisections.)
    path = ORIGAMI_SIMULATOR / name
    pattern = read_pattern(path)
    targets = 0.6 * np.nan_to_num(pattern.edges_fold_angle)
    _, x, report = _fold(path, {}, targets, steps=steps)
    assert report["left_branch"] == 0
    creases = np.array([a in "MV" for a in pattern.edges_assignment])
    reached = np.degrees(fold_angles(pattern.faces, pattern.edges, x))[creases]
    assert np.all(np.sign(reached) == np.sign(targets[creases]))
    assert np.all(np.abs(reached) > 0.5 * np.abs(targets[creases]))


# -- FOLD's letters and frames on the files ----------------------------------------------------

def _copies_along_cuts(pattern) -> int:
    """Vertex copies a cut makes, counted independently: round each vertex on a C edge, the
    faces joined to each other through edges that are not cuts form groups; each group after
    the first needs its own copy."""
    letter = {tuple(sorted(e)): a for e, a in zip(pattern.edges.tolist(),
                                                  pattern.edges_assignment)}
    on_cut = {v for e, a in letter.items() if a == "C" for v in e}
    copies = 0
    for v in on_cut:
        faces = [k for k, face in enumerate(pattern.faces) if v in face]
        group = {k: k for k in faces}

        def root(k):
            while group[k] != k:
                k = group[k]
            return k
        for i in faces:
            for j in faces:
                shared = set(pattern.faces[i]) & set(pattern.faces[j]) - {v}
                if i < j and any(letter.get(tuple(sorted((v, w)))) not in ("C", None)
                                 for w in shared):
                    group[root(i)] = root(j)
        copies += len({root(k) for k in faces}) - 1
    return copies


def test_rabbit_ears_crane_with_every_letter_builds_each_family_from_its_letter():
    path = RABBIT_EAR / "crane-cp-bmvfcj.fold"
    pattern = read_fold(path)
    count = {a: pattern.edges_assignment.count(a) for a in "BMVFUCJ"}
    assert count == {"B": 14, "M": 61, "V": 42, "F": 8, "U": 14, "C": 2, "J": 46}
    assert all(len(face) == 3 for face in pattern.faces)      # no panel-splitting bends
    fold = build_pattern_model(pattern, material=MANUAL)
    assert {f: fold.hinge_family.count(f) for f in set(fold.hinge_family)} == {
        "mountain": 61, "valley": 42, "flat": 8, "unassigned": 14, "bend": 46}
    simulator = build_pattern_model(pattern, material=MANUAL, assignments="origami_simulator")
    assert {f: simulator.hinge_family.count(f) for f in set(simulator.hinge_family)} == {
        "mountain": 61, "valley": 42, "bend": 46 + 8}
    copies = _copies_along_cuts(pattern)
    assert copies > 0
    assert fold.model.num_nodes == simulator.model.num_nodes == pattern.num_vertices + copies



def test_origami_simulators_own_fold_file_reads_in_its_plane_with_its_facet_creases():
    # Its box-pleated tessellations are written by it: "unit", 2D patterns mapped to the
    # x-z plane, F for its facet creases (flat, stiff), as FOLD files of 3 coordinates.
    path = ORIGAMI_SIMULATOR / "BoxPleatInOutWave-corner.fold"
    document = json.loads(path.read_text())
    assert document["frame_unit"] == "unit"
    assert {v[1] for v in document["vertices_coords"]} == {0}
    pattern = read_fold(path, **SHEET)
    np.testing.assert_array_equal(pattern.vertices[:, 1], 0.0)     # read in its plane
    np.testing.assert_allclose(pattern.vertices[:, [0, 2]],
                               100.0 * np.array(document["vertices_coords"])[:, [0, 2]])
    letters = {a: document["edges_assignment"].count(a) for a in "MVF"}
    assert letters == {"M": 95, "V": 73, "F": 96}
    for convention, expected in (("fold", {"mountain": 95, "valley": 73, "flat": 96}),
                                 ("origami_simulator", {"mountain": 95, "valley": 73})):
        families = build_pattern_model(pattern, material=MANUAL,
                                       assignments=convention).hinge_family
        # Each of the 144 square panels adds 4 bends about its centre (N5B8); Origami
        # Simulator's F are bends too.
        bends = 4 * 144 + (96 if convention == "origami_simulator" else 0)
        assert {f: families.count(f) for f in set(families)} == dict(expected, bend=bends)


def _resolved(document, k):
    """Frame k's arrays as FOLD's frame inheritance gives them (frame 0: the top level)."""
    frames = [document] + document.get("file_frames", [])
    arrays = {}
    while True:
        for key in ("vertices_coords", "faces_vertices", "edges_vertices"):
            if key not in arrays and key in frames[k]:
                arrays[key] = frames[k][key]
        if k == 0 or not frames[k].get("frame_inherit"):
            return arrays
        k = frames[k]["frame_parent"]


def test_rabbit_ears_nested_frames_each_read_with_the_arrays_it_inherits():
    path = RABBIT_EAR / "nested-frames.fold"
    document = json.loads(path.read_text())
    resolved = [_resolved(document, k) for k in range(len(document["file_frames"]) + 1)]
    for k, arrays in enumerate(resolved):
        pattern = read_fold(path, frame=k)
        assert pattern.num_vertices == len(arrays["vertices_coords"])
        assert [list(f) for f in pattern.faces] == arrays["faces_vertices"]
        # The frames kept beside it are the others that move the same mesh.
        same_mesh = [j for j, other in enumerate(resolved) if j != k and
                     other["faces_vertices"] == arrays["faces_vertices"] and
                     len(other["vertices_coords"]) == len(arrays["vertices_coords"])]
        assert len(pattern.frames) == len(same_mesh), k


# -- read, written, read again ---------------------------------------------------------------

def _families(pm):
    """The model as a set of bars and of (hinge nodes, family)."""
    bars = {tuple(sorted(b)) for b in pm.model.bars.tolist()}
    hinges = {(tuple(sorted(h[:2])), tuple(sorted(h[2:])), f)
              for h, f in zip(pm.model.hinges.tolist(), pm.hinge_family)}
    return bars, hinges


@pytest.mark.parametrize("path, keys", [
    (SPEC / "squaretwist.fold", {}), (RABBIT_EAR / "wavy-miura-no-faces.fold", {}),
    (RABBIT_EAR / "crane-cp-bmvfcj.fold", {}), (RABBIT_EAR / "bird-base-3d-cp.fold", {}),
    (RABBIT_EAR / "nested-frames.fold", {"frame": 2}),
    (ORIGAMI_SIMULATOR / "flappingBird.svg", {}), (ORIGAMI_SIMULATOR / "waterbomb.svg", {}),
    (ORIGAMI_SIMULATOR / "BoxPleatInOutWave-corner.fold", {})],
    ids=lambda v: getattr(v, "name", str(v)))
def test_a_public_file_read_written_and_read_again_builds_the_same_model(tmp_path, path, keys):
    first = read_pattern(path, **keys)
    again = read_fold(write_fold(tmp_path / "again.fold", first))
    # A drawing (or Origami Simulator's file) gives its boundary no fold angle; write_fold
    # states 0 for them.
    boundary = np.array(first.edges_assignment) == "B"
    if path.parent == ORIGAMI_SIMULATOR:
        assert np.all(np.isnan(first.edges_fold_angle[boundary]))
        first = dataclasses.replace(first, edges_fold_angle=np.where(
            boundary, 0.0, first.edges_fold_angle))
    assert again == first
    np.testing.assert_array_equal(again.vertices, first.vertices)
    assignments = "origami_simulator" if path.parent == ORIGAMI_SIMULATOR else "fold"
    models = [build_pattern_model(p, material=MANUAL, assignments=assignments)
              for p in (first, again)]
    assert _families(models[0]) == _families(models[1])
    assert models[0].hinge_family == models[1].hinge_family
    np.testing.assert_array_equal(models[0].model.nodes, models[1].model.nodes)


# -- any scale --------------------------------------------------------------------------------

def test_a_public_file_at_1_mm_100_mm_and_1_m_follows_the_same_normalised_path():
    # Rabbit Ear's bird base crease pattern, a unit square, read at s mm per unit. Lengths
    # scale by s; with bar areas and hinge stiffnesses (per unit length) scaled by s^2, every
    # energy scales by s^3, forces by s^2, displacements by s.
    path = RABBIT_EAR / "bird-base-3d-cp.fold"
    runs = {}
    for s in (1.0, 100.0, 1000.0):
        material = {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1e-2 * s ** 2,
                    "fold_stiffness": 1e-3 * s ** 2, "bend_stiffness": 1e-2 * s ** 2}
        _, far, axis, sim = _push(path, {"unit": "unit", "scale": s}, material=material)
        assert sim.completed, sim.path.message
        runs[s] = sim
    reference = runs[1.0]
    size = _size(read_fold(path))                      # sqrt(2) units
    energy = reference.history_columns()["energy_total"]
    force = np.abs(reference.path.constraint_force).max()
    for s, sim in runs.items():
        np.testing.assert_array_equal(sim.path.iterations, reference.path.iterations)
        # Each equilibrium is found to Newton's default tolerance, 1e-8 of the size: the runs
        # agree to that (in units of the size), not to the last bit.
        np.testing.assert_allclose(sim.path.displacement / s, reference.path.displacement,
                                   rtol=0, atol=1e-8 * size)
        np.testing.assert_allclose(sim.path.constraint_force / s ** 2,
                                   reference.path.constraint_force, rtol=0, atol=1e-6 * force)
        np.testing.assert_allclose(sim.history_columns()["energy_total"] / s ** 3, energy,
                                   rtol=1e-6)
