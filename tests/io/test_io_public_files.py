"""Public crease-pattern files as their tools write them (tests/data/public/, with their
origins and licences in its README): each loads and takes a small push; FOLD's letters and
frames build what the specification says; the same file at 1 mm, 100 mm and 1 m gives the
same normalised path; and read, written and read again, each builds the same model. Their
folds are in tests/io/test_io_public_folds.py."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from kresling.io import read_fold, read_pattern, write_fold
from kresling.model import build_pattern_model
from kresling.simulate import simulate
from public_files import (MANUAL, ORIGAMI_SIMULATOR, RABBIT_EAR, SHEET, SPEC, STIFF,
                          diagonal, held_and_far, read)

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


def _push(path, keys, steps=8, scale=1.0, material=STIFF):
    pattern = read(path, keys)
    held, far = held_and_far(pattern)
    normal = np.cross(*(pattern.vertices[held[1:]] - pattern.vertices[held[0]]))
    push = 0.01 * diagonal(pattern) * normal / np.linalg.norm(normal)
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
    size = diagonal(read_fold(path))                  # sqrt(2) units
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
