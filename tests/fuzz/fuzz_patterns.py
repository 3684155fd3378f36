"""Fuzz: the vendored crease patterns (FOLD and SVG files under tests/data) mutated by
structure (coordinates perturbed, edges dropped or duplicated, assignments changed, faces
reordered or given a copied vertex) and by bytes, read as ``kresling simulate`` reads them
and built into their fold's model. A pattern is read and built, or refused with a
ValueError naming its file; `kresling pattern --check` and `--from` agree with it (exit 0
together, or 1 with the same reason); a short fold of a small pattern ends finite."""

import contextlib
import io
import json
import os
import tempfile
from pathlib import Path

import numpy as np
from hypothesis import event, given
from hypothesis import strategies as st

from _fuzz import finite, fuzz, mutated, path_ok
from kresling.cli import main
from kresling.simulate import build_problem_model, load_problem, simulate

DATA = Path(__file__).resolve().parents[1] / "data"
FOLDS = sorted(p for p in DATA.rglob("*.fold")
               if "faces_vertices" in json.loads(p.read_text()))
SVGS = sorted(DATA.rglob("*.svg"))
#: Files small enough to fold in a fuzz example (a few hundred ms).
SMALL = 40
WORDS = [b"", b"0", b"-1", b"1e308", b"nan", b"null", b"[]", b"]", b"\"", b",", b"\x00",
         b"\xff", b"9" * 40, b"\"C\"", b"\"B\"", b"stroke=\"red\"", b"<line/>"]


def _structural(document, draw):
    """``document`` (a FOLD dict) with one structural mutation drawn."""
    doc = json.loads(json.dumps(document))
    vertices, faces = doc["vertices_coords"], doc["faces_vertices"]
    edges = doc.get("edges_vertices", [])
    kind = draw(st.sampled_from(["perturb", "drop_edge", "duplicate_edge", "assignment",
                                 "reorder_faces", "reverse_face", "copy_vertex", "drop_face"]))
    event(kind)
    k = draw(st.integers(0, 10**6))
    if kind == "perturb":
        size = float(np.ptp(np.asarray(vertices, dtype=float), axis=0).max()) or 1.0
        scale = draw(st.sampled_from([1e-9, 1e-7, 1e-4, 1e-2, 0.3]))
        v = vertices[k % len(vertices)]
        v[k % len(v)] = float(v[k % len(v)]) + scale * size
    elif kind == "drop_edge" and edges:
        index = k % len(edges)
        for key in ("edges_vertices", "edges_assignment", "edges_foldAngle"):
            if key in doc and len(doc[key]) == len(edges):
                del doc[key][index]
    elif kind == "duplicate_edge" and edges:
        index = k % len(edges)
        for key in ("edges_vertices", "edges_assignment", "edges_foldAngle"):
            if key in doc and len(doc[key]) == len(edges):
                doc[key].append(doc[key][index])
    elif kind == "assignment" and "edges_assignment" in doc and doc["edges_assignment"]:
        doc["edges_assignment"][k % len(doc["edges_assignment"])] = draw(
            st.sampled_from(list("BMVFUCJ") + ["q", "", 3]))
    elif kind == "reorder_faces":
        np.random.default_rng(k).shuffle(faces)
    elif kind == "reverse_face":
        faces[k % len(faces)].reverse()
    elif kind == "copy_vertex":
        face = faces[k % len(faces)]
        corner = k % len(face)
        vertices.append(list(vertices[face[corner]]))
        face[corner] = len(vertices) - 1
    elif kind == "drop_face" and len(faces) > 1:
        del faces[k % len(faces)]
    return doc


@st.composite
def pattern_files(draw):
    """(name, bytes) of a vendored pattern, mutated by structure or by bytes."""
    if draw(st.booleans()):
        path = draw(st.sampled_from(FOLDS))
        data = json.dumps(_structural(json.loads(path.read_text()), draw)).encode()
    else:
        path = draw(st.sampled_from(FOLDS + SVGS))
        data = path.read_bytes()
    if draw(st.integers(0, 3)) == 0:   # bytes flipped, cut out, words spliced in
        cuts = draw(st.lists(st.tuples(st.integers(0, 10**6), st.integers(1, 30)), max_size=2))
        words = draw(st.lists(st.tuples(st.integers(0, 10**6), st.sampled_from(WORDS)),
                              max_size=2))
        data = bytearray(mutated(data, cuts, words))
        for position in draw(st.lists(st.integers(0, 10**6), max_size=3)):
            if data:
                data[position % len(data)] ^= 1 << (position % 8)
        data = bytes(data)
    return f"fuzzed{path.suffix}", data


def _cli(*argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))
    assert "Traceback" not in err.getvalue()
    return status, err.getvalue()


@fuzz(40)
@given(pattern_files(), st.sampled_from(["N5B8", "N4B5"]))
def test_mutated_patterns_are_read_and_built_or_refused_naming_the_file(file, split):
    name, data = file
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / name
        path.write_bytes(data)
        problem = {"pattern": {"file": str(path), "split": split},
                   "actuation": [{"family": "fold", "fold_angle_deg": 30.0}],
                   "analysis": {"method": "fold", "steps": 2}}
        try:
            loaded = load_problem(problem)
            pm = build_problem_model(loaded)
        except ValueError as error:
            # Naming the pattern's file (the problem's own keys are not fuzzed here).
            assert name in str(error), f"the message does not name {name}: {error}"
            event("refused")
            refusal = str(error)
        else:
            refusal = None
            finite(pm.model.nodes)
            event("built")
        cwd = os.getcwd()
        os.chdir(directory)
        try:
            checked, err = _cli("pattern", "--check", name, "--split", split)
            converted, err_from = _cli("pattern", "--from", name, "--split", split,
                                       "-o", "out.fold")
        finally:
            os.chdir(cwd)
        # --check folds to the file's own angles (not 30 deg): the same pattern and model,
        # so the same refusal about the pattern, or none; --from refuses what --check does,
        # with the same message.
        if refusal is not None and "actuation" not in refusal:
            assert checked == 1, (refusal, err)
        assert checked in (0, 1) and converted == checked, (err, err_from)
        if checked == 1:
            assert err.strip() == err_from.strip(), (err, err_from)
        if refusal is not None or loaded.pattern.num_vertices > SMALL:
            return
        # A short fold of a small pattern: finite, or stopped saying why.
        try:
            run = simulate(loaded, progress=False)
        except ValueError as error:      # the fold's own keys: an actuation of no crease
            assert "actuation" in str(error) or name in str(error), str(error)
            return
        path_ok(run.path)
