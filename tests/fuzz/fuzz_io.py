"""Fuzz: the crease-pattern readers (FOLD, OBJ) on random bytes and on mutated valid files,
and patterns from arrays and FOLD documents. A bad file is a ValueError naming the file (or
an OSError); a pattern read is finite."""

import json
import tempfile
from pathlib import Path

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, fuzz, junk, mostly, mutated
from kresling.io import pattern_from_arrays, pattern_from_fold, read_fold, read_obj, read_pattern
from kresling.io.vertex_neighbours import vertices_neighbours

DATA = Path(__file__).resolve().parents[1] / "data" / "patterns"
VALID = {".fold": (DATA / "square_twist_1.2.fold").read_bytes(),
         ".obj": (DATA / "mixed_polygons.obj").read_bytes()}
READERS = {".fold": read_fold, ".obj": read_obj}
WORDS = [b"", b"0", b"-1", b"1e308", b"1e999", b"nan", b"inf", b"null", b"true", b"[]", b"{}",
         b"[[", b"]]", b"\"", b",", b"f", b"v", b"f 1 2", b"f 1/2/3 99 -7", b"v 1 2",
         b"\x00", b"\xff\xfe", b"\n", b"9" * 400, b"\"faces_vertices\": [[0, 0, 0]]",
         b"\"vertices_coords\": [[1e400, 0]]", b"\"edges_assignment\": [\"Q\"]",
         b"\"file_frames\": [{\"frame_parent\": 5}]"]


def check_read(data: bytes, suffix: str, reader) -> None:
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / f"fuzzed{suffix}"
        path.write_bytes(data)
        try:
            pattern = reader(path)
        except OSError:
            return
        except ValueError as error:
            assert "fuzzed" in str(error), f"the message does not name the file: {error}"
            return
    finite(pattern.vertices)
    assert all(len(face) >= 3 for face in pattern.faces)
    assert all(0 <= v < pattern.num_vertices for face in pattern.faces for v in face)


@fuzz(150)
@given(st.binary(max_size=400), st.sampled_from([".fold", ".obj"]),
       st.sampled_from([None, read_pattern]))
def test_random_bytes(data, suffix, reader):
    check_read(data, suffix, reader or READERS[suffix])


@fuzz(250)
@given(st.sampled_from([".fold", ".obj"]),
       st.lists(st.tuples(st.integers(0, 10**6), st.integers(1, 40)), max_size=3),
       st.lists(st.tuples(st.integers(0, 10**6), st.sampled_from(WORDS)), max_size=4))
def test_mutated_valid_files(suffix, cuts, insertions):
    check_read(mutated(VALID[suffix], cuts, insertions), suffix, READERS[suffix])


coordinates = st.lists(st.lists(mostly(st.floats(-10, 10), edgy_floats), min_size=2, max_size=3),
                       min_size=0, max_size=7)
faces = mostly(st.lists(st.lists(mostly(st.integers(0, 6), st.integers(-2, 9), junk),
                                 min_size=0, max_size=5), max_size=4), junk)


@fuzz(200)
@given(mostly(coordinates, junk), faces,
       st.fixed_dictionaries({}, optional={
           "edges": mostly(st.lists(st.lists(st.integers(-1, 7), min_size=2, max_size=2),
                                    max_size=4), junk),
           "edges_assignment": mostly(st.lists(st.sampled_from(list("MVFUJCBmvq")), max_size=4),
                                      junk),
           "edges_fold_angle": mostly(st.lists(mostly(st.floats(-180, 180), edgy_floats),
                                               max_size=4), junk),
           "planarity_tolerance": mostly(st.floats(1e-6, 1), edgy_floats, junk)}))
def test_pattern_from_arrays(vertices, faces, options):
    pattern = attempt(lambda: pattern_from_arrays(vertices, faces, **options),
                      "vertices", "faces", "edges", "edges_assignment", "edges_fold_angle",
                      "planarity_tolerance", "face", "vertex", "edge")
    if pattern is not None:
        finite(pattern.vertices)
        # What write_fold writes for a file with cuts: each vertex's neighbours through its
        # edges, each once, with the edge to each.
        ring, ring_edges = vertices_neighbours(pattern.faces, pattern.edges,
                                               pattern.num_vertices)
        for v in range(pattern.num_vertices):
            around = {int(w) for e in pattern.edges for w in e if v in e and w != v}
            assert sorted(ring[v]) == sorted(around)
            assert [set(pattern.edges[k].tolist()) for k in ring_edges[v]] == [
                {v, w} for w in ring[v]]


fold_values = st.recursive(
    st.one_of(st.none(), st.booleans(), st.integers(-5, 10), edgy_floats, st.text(max_size=4)),
    lambda inner: st.one_of(st.lists(inner, max_size=4),
                            st.dictionaries(st.text(max_size=4), inner, max_size=3)),
    max_leaves=12)
FOLD_KEYS = ["vertices_coords", "faces_vertices", "edges_vertices", "edges_assignment",
             "edges_foldAngle", "file_spec", "frame_unit", "file_frames", "frame_classes"]


@fuzz(200)
@given(st.dictionaries(st.sampled_from(FOLD_KEYS), fold_values, max_size=6),
       st.booleans())
def test_pattern_from_fold(document, start_valid):
    if start_valid:
        document = {**json.loads(VALID[".fold"]), **document}
    pattern = attempt(lambda: pattern_from_fold(document, source="fuzzed.fold"), "fuzzed.fold")
    if pattern is not None:
        finite(pattern.vertices)
