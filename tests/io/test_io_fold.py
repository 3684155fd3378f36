"""FOLD files through kresling.io: our fabrication files read back exactly, writing and reading
again is the identity, frames and FOLD 1.2 assignments survive, and every malformed file is
rejected with a ValueError naming the file and the element."""

import ast
import json
import math
from pathlib import Path

import numpy as np
import pytest

import kresling
from kresling.fabrication import write_pattern
from kresling.io import (ASSIGNMENTS, Pattern, PatternFileError, pattern_from_arrays,
                         pattern_from_fold, read_fold, read_pattern, write_fold)

PATTERNS = Path(__file__).resolve().parents[1] / "data" / "patterns"
SQUARE = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
# Two triangles sharing the diagonal 0-2, folded up by 90 degrees in the frame below.
TRIANGLES = [[0, 1, 2], [0, 2, 3]]
FOLDED = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [5, 5, math.sqrt(50)]]


def _fabrication_file(tmp_path, n, lam, Lc, process="laminate"):
    path = write_pattern(tmp_path / f"cell_n{n}.fold", kresling.Design(n, lam, Lc, 30.0), process)
    return path, json.loads(path.read_text())


def _write(tmp_path, document, name="sheet.fold"):
    path = tmp_path / name
    path.write_text(document if isinstance(document, str) else json.dumps(document))
    return path


def _valid(**changes):
    document = {"file_spec": 1.1, "vertices_coords": SQUARE, "faces_vertices": TRIANGLES,
                "edges_vertices": [[0, 2]], "edges_assignment": ["V"], "edges_foldAngle": [90]}
    document.update(changes)
    return {k: v for k, v in document.items() if v is not None}


# -- our own files -------------------------------------------------------------------------

@pytest.mark.parametrize("n, lam, Lc", [(10, 0.9, 15.0), (4, 0.7, 30.0)])
def test_fabrication_files_read_back_exactly(tmp_path, n, lam, Lc):
    path, document = _fabrication_file(tmp_path, n, lam, Lc)
    pattern = read_fold(path)
    assert pattern.source == str(path)
    flat = np.array(document["vertices_coords"])
    np.testing.assert_allclose(pattern.vertices[:, :2], flat, rtol=0, atol=1e-12)
    assert np.all(pattern.vertices[:, 2] == 0)
    assert pattern.faces == tuple(tuple(face) for face in document["faces_vertices"])
    np.testing.assert_array_equal(pattern.edges, document["edges_vertices"])
    assert pattern.edges_assignment == tuple(document["edges_assignment"])
    np.testing.assert_allclose(pattern.edges_fold_angle, document["edges_foldAngle"],
                               rtol=0, atol=1e-12)
    assert [frame.shape for frame in pattern.frames] == [(4 * n + 4, 3)] * 2
    for frame, written in zip(pattern.frames, document["file_frames"]):
        np.testing.assert_allclose(frame, written["vertices_coords"], rtol=0, atol=1e-12)
    assert pattern.num_vertices == 4 * n + 4 and pattern.num_faces == len(pattern.faces)


@pytest.mark.parametrize("n, lam, Lc", [(10, 0.9, 15.0), (4, 0.7, 30.0)])
def test_writing_what_was_read_is_the_identity(tmp_path, n, lam, Lc):
    path, _ = _fabrication_file(tmp_path, n, lam, Lc)
    first = read_fold(path)
    again = read_fold(write_fold(tmp_path / "again.fold", first))
    assert again == first and again.source.endswith("again.fold")
    # And the file written from it is a fixed point.
    third = write_fold(tmp_path / "third.fold", again)
    assert third.read_text() == (tmp_path / "again.fold").read_text()


def test_paper_cell_has_cut_edges_and_fold_1_2(tmp_path):
    path, document = _fabrication_file(tmp_path, 8, 0.8, 15.0, "paper")
    assert document["file_spec"] == 1.2
    pattern = read_fold(path)
    assert "C" in pattern.edges_assignment
    rewritten = json.loads(write_fold(tmp_path / "paper.fold", pattern).read_text())
    assert rewritten["file_spec"] == 1.2


@pytest.mark.parametrize("letter, spec", [("C", 1.2), ("J", 1.2), ("M", 1.1), ("F", 1.1)])
def test_file_spec_is_1_2_only_with_cut_or_join_edges(tmp_path, letter, spec):
    path = write_fold(tmp_path / "square.fold", SQUARE, TRIANGLES, edges=[[0, 2]],
                      edges_assignment=[letter])
    assert json.loads(path.read_text())["file_spec"] == spec
    assert read_fold(path).edges_assignment[0] == letter


def test_five_frames_of_a_path_read_back(tmp_path):
    rng = np.random.default_rng(1)
    frames = [np.array(FOLDED) + 0.1 * k * rng.standard_normal((4, 3)) for k in range(5)]
    path = write_fold(tmp_path / "path.fold", SQUARE, TRIANGLES, frames=frames,
                      frame_title="a path in 5 increments")
    document = json.loads(path.read_text())
    assert document["frame_title"] == "a path in 5 increments"
    assert [f["frame_title"] for f in document["file_frames"]] == [f"frame {k}" for k in
                                                                   range(1, 6)]
    for frame in document["file_frames"]:
        assert frame["frame_inherit"] is True and frame["frame_parent"] == 0
        assert frame["frame_classes"] == ["foldedForm"]
    pattern = read_fold(path)
    assert len(pattern.frames) == 5
    for read, written in zip(pattern.frames, frames):
        np.testing.assert_array_equal(read, written)
        assert not read.flags.writeable
    titles = ["flat", "a", "b", "c", "d", "e"]
    document = json.loads(write_fold(tmp_path / "titled.fold", pattern,
                                     frame_title=titles).read_text())
    written = [document["frame_title"]] + [f["frame_title"] for f in document["file_frames"]]
    assert written == titles
    with pytest.raises(ValueError, match="frame_title"):
        write_fold(tmp_path / "bad.fold", pattern, frame_title=["too", "few"])
    with pytest.raises(ValueError, match=r"frames\[1\] has shape \(3, 3\)"):
        write_fold(tmp_path / "bad.fold", pattern, frames=[FOLDED, FOLDED[:3]])


def test_frames_written_again_give_the_same_bytes_as_written_afresh(tmp_path):
    # A path's file is rewritten as the path grows and each frame's text is kept between
    # the writes: every file must be what a first write of the same frames gives, byte for
    # byte, and a frame that differs in a title, a class or one bit of a coordinate or an
    # angle must not take another's text.
    from kresling.io.fold_format import forget_frame_texts

    rng = np.random.default_rng(5)
    frames = [np.array(FOLDED) + 0.1 * k * rng.standard_normal((4, 3)) for k in range(6)]
    edges = [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]]
    angles = [rng.uniform(-90, 90, size=len(edges)) for _ in frames]

    def write(name, count, **changes):
        arguments = dict(edges=edges, frames=frames[:count], frame_fold_angles=angles[:count],
                         frame_title="a path") | changes
        return write_fold(tmp_path / name, SQUARE, TRIANGLES, **arguments).read_bytes()

    forget_frame_texts()
    growing = [write(f"grow{count}.fold", count) for count in (2, 4, 6)]
    for count, text in zip((2, 4, 6), growing):
        forget_frame_texts()
        assert text == write(f"fresh{count}.fold", count)
    nudged = [f.copy() for f in frames]
    nudged[3][2, 1] = np.nextafter(nudged[3][2, 1], np.inf)
    turned = [a.copy() for a in angles]
    turned[1][4] = np.nextafter(turned[1][4], -np.inf)
    for name, changes in (("nudged", dict(frames=nudged)),
                          ("turned", dict(frame_fold_angles=turned)),
                          ("titled", dict(frame_title=["a"] + [f"t{k}" for k in range(6)]))):
        write(f"{name}-kept.fold", 6)     # every frame's text kept, then a changed frame
        kept = write(f"{name}.fold", 6, **changes)
        forget_frame_texts()
        assert kept == write(f"{name}-fresh.fold", 6, **changes) != growing[-1]


def test_written_document_keys(tmp_path):
    path = write_fold(tmp_path / "square.fold", SQUARE, TRIANGLES, edges=[[0, 2]],
                      edges_assignment="v", edges_fold_angle=[90.0],
                      metadata={"frame_unit": "cm", "file_title": "square",
                                "kresling:note": [1, 2]})
    document = json.loads(path.read_text())
    assert document["file_creator"] == "kresling"
    assert document["frame_unit"] == "cm" and document["file_title"] == "square"
    assert document["frame_classes"] == ["creasePattern"]
    # 2D (every z is 0), written in the file's unit: the mm given are 1/10 of a cm.
    assert document["vertices_coords"] == [[x / 10 for x in p] for p in SQUARE]
    assert document["faces_vertices"] == TRIANGLES
    assert document["edges_vertices"] == [[0, 2], [0, 1], [1, 2], [2, 3], [3, 0]]
    assert document["edges_assignment"] == ["V", "B", "B", "B", "B"]
    assert document["edges_foldAngle"] == [90.0, 0.0, 0.0, 0.0, 0.0]  # unknown on B: 0
    assert "file_frames" not in document
    three_d = json.loads(write_fold(tmp_path / "folded.fold", FOLDED, TRIANGLES).read_text())
    assert three_d["frame_classes"] == ["foldedForm"] and len(three_d["vertices_coords"][0]) == 3
    assert "edges_foldAngle" not in three_d                        # nothing known


def test_unknown_fold_angles(tmp_path):
    path = write_fold(tmp_path / "square.fold", SQUARE, TRIANGLES, edges=[[0, 2], [0, 1]],
                      edges_assignment=["M", "B"], edges_fold_angle=[None, float("nan")])
    assert "edges_foldAngle" not in json.loads(path.read_text())
    assert np.isnan(read_fold(path).edges_fold_angle).all()
    pattern = pattern_from_arrays(SQUARE, TRIANGLES, edges=[[0, 2], [0, 1], [1, 2]],
                                  edges_assignment="MBB", edges_fold_angle=[np.nan, np.nan, 0])
    document = json.loads(write_fold(tmp_path / "partly.fold", pattern).read_text())
    assert document["edges_foldAngle"][:3] == [None, 0.0, 0.0]     # M unknown: null
    read = read_fold(tmp_path / "partly.fold")
    assert np.isnan(read.edges_fold_angle[0]) and read.edges_fold_angle[1] == 0


def test_metadata_cannot_replace_the_geometry(tmp_path):
    for key in ("faces_vertices", "file_frames", "edges_foldAngle"):
        with pytest.raises(ValueError, match=f"metadata key '{key}' is invalid"):
            write_fold(tmp_path / "x.fold", SQUARE, TRIANGLES, metadata={key: []})
    with pytest.raises(ValueError, match="metadata is invalid: not JSON"):
        write_fold(tmp_path / "x.fold", SQUARE, TRIANGLES, metadata={"a": object()})
    with pytest.raises(ValueError, match="faces and edges are invalid with a Pattern"):
        write_fold(tmp_path / "x.fold", pattern_from_arrays(SQUARE, TRIANGLES), TRIANGLES)
    with pytest.raises(ValueError, match="faces is missing"):
        write_fold(tmp_path / "x.fold", SQUARE)


def test_hand_written_fold_1_2_file():
    pattern = read_pattern(PATTERNS / "square_twist_1.2.fold")
    assert pattern.faces == ((0, 1, 2), (0, 2, 3), (1, 4, 5, 2))
    # File edges first, then the faces' other sides in order of first appearance.
    assert pattern.edges.tolist() == [[0, 2], [1, 2], [0, 1], [2, 3], [3, 0], [1, 4], [4, 5],
                                      [5, 2]]
    assert pattern.edges_assignment == ("V", "C", "B", "B", "B", "B", "B", "B")  # upper-cased
    assert pattern.edges_fold_angle[0] == 90 and np.isnan(pattern.edges_fold_angle[1:]).all()
    assert len(pattern.frames) == 1                      # the frame without coordinates is skipped
    assert pattern.frames[0][3] == pytest.approx([5, 5, math.sqrt(50)])
    assert pattern.face_edges() == ((2, 1, 0), (0, 3, 4), (5, 6, 7, 1))


def test_derived_edges_are_unassigned_inside_and_boundary_outside(tmp_path):
    pattern = read_fold(_write(tmp_path, {"vertices_coords": SQUARE, "faces_vertices": TRIANGLES}))
    assert pattern.edges.tolist() == [[0, 1], [1, 2], [2, 0], [2, 3], [3, 0]]
    assert pattern.edges_assignment == ("B", "B", "U", "B", "B")
    assert np.isnan(pattern.edges_fold_angle).all()


def test_in_memory_document_and_pattern_values(tmp_path):
    pattern = pattern_from_fold(_valid(), planarity_tolerance=None)
    assert pattern.source == "" and pattern.vertices.dtype == np.float64
    assert pattern.edges.dtype == np.int64
    for array in (pattern.vertices, pattern.edges, pattern.edges_fold_angle):
        assert not array.flags.writeable
    with pytest.raises(AttributeError):
        pattern.faces = ()
    assert pattern == read_fold(_write(tmp_path, _valid()))       # source is not compared
    assert pattern != pattern_from_arrays(SQUARE, TRIANGLES)
    assert "4 vertices, 2 faces" in repr(pattern)
    assert set(ASSIGNMENTS) == set("MVFBCUJ")


def test_read_pattern_dispatches_on_the_suffix_in_any_case(tmp_path):
    for name in ("a.FOLD", "b.Fold", "c.fold"):
        assert read_pattern(_write(tmp_path, _valid(), name)).num_faces == 2
    with pytest.raises(ValueError, match=r"file extension '\.stl' of .*x\.stl.* is invalid"):
        read_pattern(tmp_path / "x.stl")


def test_missing_file_names_the_path(tmp_path):
    with pytest.raises(FileNotFoundError, match="nowhere.fold"):
        read_fold(tmp_path / "nowhere.fold")
    with pytest.raises(OSError, match="nowhere.fold"):
        read_pattern(tmp_path / "nowhere.fold")


def test_planarity_tolerance(tmp_path):
    bent = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0.1]]
    path = _write(tmp_path, {"vertices_coords": bent, "faces_vertices": [[0, 1, 2, 3]]})
    with pytest.raises(ValueError, match=r"sheet\.fold: face 0 is not planar: its corner at "
                                         r"vertex \d lies 0\.025 mm off its plane \(tolerance "
                                         r"0\.001 of its 14\.1 mm size; a larger planarity_tolerance"):
        read_fold(path)
    assert read_fold(path, planarity_tolerance=1e-2).num_faces == 1
    assert read_fold(path, planarity_tolerance=None).num_faces == 1
    with pytest.raises(ValueError, match="planarity_tolerance = -1.0 is invalid"):
        read_fold(path, planarity_tolerance=-1.0)


# -- malformed files -----------------------------------------------------------------------

MALFORMED = {
    "syntax": ('{"vertices_coords": [[0, 0],\n  [1, 0]]\n  "faces_vertices": []}',
               r"sheet\.fold:3:3: not valid JSON: Expecting ',' delimiter"),
    "empty file": ("", r"sheet\.fold:1:1: not valid JSON"),
    "top level": ("[1, 2]", r"sheet\.fold: not a FOLD document: the top level is a JSON array"),
    "no faces": (_valid(faces_vertices=None, edges_vertices=None, edges_assignment=None,
                        edges_foldAngle=None),
                 r"sheet\.fold: key 'faces_vertices' is missing: a FOLD file needs "
                 r"faces_vertices, or edges_vertices to derive them from"),
    "no vertices": (_valid(vertices_coords=None), r"sheet\.fold: key 'vertices_coords' is "
                                                  r"missing"),
    "vertex type": (_valid(vertices_coords=[[0, 0], [1, 0], [1, 1], [1, 1], [1, "a"]]),
                    r"sheet\.fold: key 'vertices_coords'\[4\] = \[1, 'a'\] is invalid: must "
                    r"be 2 or 3 numbers"),
    "vertex size": (_valid(vertices_coords=[[0, 0], [1, 0, 0, 0], [1, 1], [0, 1]]),
                    r"key 'vertices_coords'\[1\] = \[1, 0, 0, 0\] is invalid"),
    "vertex bool": (_valid(vertices_coords=[[0, 0], [1, 0], [True, 1], [0, 1]]),
                    r"key 'vertices_coords'\[2\] = \[True, 1\] is invalid"),
    "vertices not a list": (_valid(vertices_coords={"0": [0, 0]}),
                            r"key 'vertices_coords' = \{'0': \[0, 0\]\} is invalid: must be a "
                            r"JSON array"),
    "non-finite": ('{"vertices_coords": [[0, 0], [1, 0], [NaN, 1]], "faces_vertices": '
                   '[[0, 1, 2]]}', r"sheet\.fold: key 'vertices_coords'\[2\]: vertex 2 has a "
                                   r"non-finite coordinate"),
    "infinite": ('{"vertices_coords": [[0, 0], [1, 0], [1e400, 1]], "faces_vertices": '
                 '[[0, 1, 2]]}', r"key 'vertices_coords'\[2\]: vertex 2 has a non-finite"),
    "face out of range": (_valid(faces_vertices=[[0, 1, 2], [0, 2, 3], [0, 3, 40]]),
                          r"sheet\.fold: key 'faces_vertices'\[2\]: face 2 has vertex 40 out "
                          r"of range \[0, 3\]"),
    "face negative": (_valid(faces_vertices=[[0, 1, -1]]),
                      r"key 'faces_vertices'\[0\]: face 0 has vertex -1 out of range"),
    "face repeat": (_valid(faces_vertices=[[0, 1, 2], [0, 2, 3, 2]]),
                    r"key 'faces_vertices'\[1\]: face 1 repeats vertex 2"),
    "face too small": (_valid(faces_vertices=[[0, 1, 2], [0, 2]]),
                       r"key 'faces_vertices'\[1\]: face 1 has 2 vertices: a face needs at "
                       r"least 3"),
    "face index type": (_valid(faces_vertices=[[0, 1, 2], [0, "2", 3]]),
                        r"key 'faces_vertices'\[1\]: face 1 has vertex '2': must be an integer"),
    "face fraction": (_valid(faces_vertices=[[0, 1, 2.5]]),
                      r"key 'faces_vertices'\[0\]: face 0 has vertex 2\.5"),
    "face not a list": (_valid(faces_vertices=[[0, 1, 2], 3]),
                        r"key 'faces_vertices'\[1\] = 3 is invalid: must be a list"),
    "faces empty": (_valid(faces_vertices=[]), r"key 'faces_vertices' is empty"),
    "degenerate": (_valid(vertices_coords=[[0, 0], [1, 0], [2, 0], [0, 1]],
                          faces_vertices=[[0, 3, 1], [0, 1, 2]], edges_vertices=None,
                          edges_assignment=None, edges_foldAngle=None),
                   r"sheet\.fold: face 1 is degenerate: its area 0 mm\^2 is below 1e-12"),
    "coincident corners": (_valid(vertices_coords=[[0, 0], [1, 0], [1, 0], [0, 1]],
                                  faces_vertices=[[0, 1, 2, 3]], edges_vertices=None,
                                  edges_assignment=None, edges_foldAngle=None),
                           r"sheet\.fold: face 0 is degenerate: its corners at vertices 1 and "
                           r"2 coincide"),
    "edge out of range": (_valid(edges_vertices=[[0, 2], [3, 9]], edges_assignment=["V", "M"],
                                 edges_foldAngle=[90, -90]),
                          r"sheet\.fold: key 'edges_vertices'\[1\] = \[3, 9\] is invalid: "
                          r"vertex 9 is out of range \[0, 3\]"),
    "edge loop": (_valid(edges_vertices=[[2, 2]]),
                  r"key 'edges_vertices'\[0\] = \[2, 2\] is invalid: an edge needs two"),
    "edge repeated": (_valid(edges_vertices=[[0, 2], [2, 0]], edges_assignment=["V", "V"],
                             edges_foldAngle=[1, 1]),
                      r"key 'edges_vertices'\[1\] = \[2, 0\] is invalid: repeats edge 0"),
    "edge shape": (_valid(edges_vertices=[[0, 1, 2]]),
                   r"key 'edges_vertices'\[0\] = \[0, 1, 2\] is invalid: must be 2 vertex"),
    "assignment length": (_valid(edges_assignment=["V", "M"]),
                          r"sheet\.fold: key 'edges_assignment' has 2 entries: must have one "
                          r"per edge \(1\)"),
    "assignment letter": (_valid(edges_assignment=["X"]),
                          r"sheet\.fold: key 'edges_assignment'\[0\] = 'X' is invalid: must be "
                          r"one of"),
    "assignment type": (_valid(edges_assignment=[1]),
                        r"key 'edges_assignment'\[0\] = 1 is invalid"),
    "assignment string": (_valid(edges_assignment="V"),
                          r"key 'edges_assignment' = 'V' is invalid: must be a JSON array"),
    "assignment without edges": (_valid(edges_vertices=None, edges_foldAngle=None),
                                 r"key 'edges_assignment' is given without edges_vertices"),
    "fold angle type": (_valid(edges_foldAngle=["90"]),
                        r"sheet\.fold: key 'edges_foldAngle'\[0\] = '90' is invalid: must be a "
                        r"number"),
    "fold angle range": (_valid(edges_foldAngle=[270]),
                         r"key 'edges_foldAngle'\[0\] = 270 is invalid: must be in \[-180, 180\]"),
    "fold angle length": (_valid(edges_foldAngle=[1, 2]),
                          r"key 'edges_foldAngle' has 2 entries"),
    "frames type": (_valid(file_frames={"a": 1}),
                    r"key 'file_frames' = \{'a': 1\} is invalid: must be a JSON array"),
    "frame type": (_valid(file_frames=[[1]]),
                   r"key 'file_frames'\[0\] = \[1\] is invalid: must be an object"),
    "frame size": (_valid(file_frames=[{"vertices_coords": FOLDED},
                                       {"vertices_coords": SQUARE[:3]}]),
                   r"key 'file_frames'\[1\]\['vertices_coords'\]: has 3 vertices: must have 4"),
    "frame entry": (_valid(file_frames=[{"vertices_coords": [[0, 0], [1, 0], [1, None],
                                                             [0, 1]]}]),
                    r"key 'file_frames'\[0\]\['vertices_coords'\]\[2\] = \[1, None\] is invalid"),
}


@pytest.mark.parametrize("content, message", MALFORMED.values(), ids=MALFORMED.keys())
def test_malformed_files_name_the_file_and_the_element(tmp_path, content, message):
    path = _write(tmp_path, content)
    with pytest.raises(ValueError, match=message) as error:
        read_fold(path)
    assert isinstance(error.value, PatternFileError) and error.value.source == str(path)
    assert str(error.value).startswith(str(path))


def test_syntax_error_position_is_line_and_column(tmp_path):
    with pytest.raises(PatternFileError) as error:
        read_fold(_write(tmp_path, '{\n "a": [1,\n  2,,]}'))
    assert (error.value.line, error.value.column) == (3, 5)


def test_pattern_from_arrays_names_the_argument():
    cases = [
        (dict(vertices=SQUARE, faces=[[0, 1, 9]]), r"^faces\[0\]: face 0 has vertex 9 out of "
                                                   r"range \[0, 3\]$"),
        (dict(vertices=[[0, 0], [1, 0], [np.inf, 1]], faces=[[0, 1, 2]]),
         r"^vertices\[2\]: vertex 2 has a non-finite coordinate$"),
        (dict(vertices=np.zeros((3, 4)), faces=[[0, 1, 2]]), r"vertices has shape \(3, 4\)"),
        (dict(vertices=SQUARE, faces=TRIANGLES, edges=[[0, 2]], edges_assignment="VV"),
         r"edges_assignment has 2 entries: must have one per edge \(1\)"),
        (dict(vertices=SQUARE, faces=TRIANGLES, edges=[[0, 2]], edges_fold_angle=[200]),
         r"edges_fold_angle\[0\] = 200 is invalid"),
        (dict(vertices=SQUARE, faces=[]), r"faces is empty"),
    ]
    for arguments, message in cases:
        with pytest.raises(ValueError, match=message):
            pattern_from_arrays(**arguments)
    with pytest.raises(ValueError, match=r"side \(2, 3\) of face 1 is not in edges"):
        Pattern(SQUARE, TRIANGLES, [[0, 1], [1, 2], [2, 0]], "BBU", [np.nan] * 3)


def test_io_imports_nothing_from_the_package_but_validation():
    """kresling.io is the bottom layer: numpy, the standard library, kresling._validation,
    and two declared dependencies where a format needs them (scipy's k-d tree for snapping
    and coincident vertices, svgelements for SVG)."""
    package = Path(kresling.__file__).parent / "io"
    for module in package.glob("*.py"):
        tree = ast.parse(module.read_text())
        for node in ast.walk(tree):
            names = ([alias.name for alias in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) else [])
            for name in names:
                top = name.split(".")[0]
                assert top in {"kresling", "numpy", "__future__", "json", "re", "logging",
                               "numbers", "collections", "dataclasses", "typing", "pathlib",
                               "math", "itertools", "scipy", "svgelements"}, \
                    (module.name, name)
                if top == "kresling":
                    assert name == "kresling._validation" or name.startswith("kresling.io"), \
                        (module.name, name)


def test_fabrication_takes_the_fold_format_s_own_functions():
    from kresling import fabrication
    from kresling.io import fold_format

    assert fabrication.fold_document is fold_format.fold_document
    assert fabrication.fold_angles is fold_format.fold_angles
    assert fabrication.write_fold_document is fold_format.write_fold_document
