"""What `kresling simulate` refuses in a pattern file, `kresling pattern --check` and
`--from` refuse too, with the same message naming the pattern's file: a vertex on no panel
(an edge hanging into a face), a key frame folded flat."""

import contextlib
import io
import json

import pytest

from kresling.cli import main

# A square panel and an edge from its corner 0 to a point inside: vertex 4 is on no panel.
HANGING = {"vertices_coords": [[0, 0], [10, 0], [10, 10], [0, 10], [5, 5]],
           "edges_vertices": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 4]],
           "edges_assignment": ["B", "B", "B", "B", "V"]}
# Two triangles folded flat onto each other.
FLAT = {"vertices_coords": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 0, 1e-12]],
        "faces_vertices": [[0, 1, 2], [0, 2, 3]], "edges_vertices": [[0, 2]],
        "edges_assignment": ["V"]}


def _run(*argv):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(list(argv))
    return status, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("document, reason", [
    (HANGING, "vertex 4 is a corner of no panel"), (FLAT, "folded flat at rest")])
def test_check_and_from_refuse_what_simulate_refuses_with_its_message(tmp_path, monkeypatch,
                                                                      document, reason):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sheet.fold").write_text(json.dumps(document))
    (tmp_path / "problem.toml").write_text(
        '[pattern]\nfile = "sheet.fold"\n\n[[actuation]]\nfamily = "fold"\n'
        'fold_angle_deg = 30.0\n\n[analysis]\nmethod = "fold"\nsteps = 2\n')
    status, _, simulated = _run("simulate", "problem.toml", "--quiet", "--no-view")
    assert status == 2 and "sheet.fold: " in simulated and reason in simulated
    # The refusal after the problem file's own prefix: the pattern's part of the message.
    said = simulated.split("(building the model): ", 1)[1].strip()
    for argv in (["--check", "sheet.fold"], ["--from", "sheet.fold", "-o", "out.fold"]):
        status, _, err = _run("pattern", *argv)
        assert status == 1, argv
        assert "simulate would refuse it" in err and said in err, (argv, err)
    assert not (tmp_path / "out.fold").exists()


def test_from_converts_what_simulate_takes(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    document = dict(HANGING, edges_vertices=HANGING["edges_vertices"][:4],
                    edges_assignment=["B"] * 4, vertices_coords=HANGING["vertices_coords"][:4])
    (tmp_path / "sheet.fold").write_text(json.dumps(document))
    status, out, err = _run("pattern", "--from", "sheet.fold", "-o", "out.fold")
    assert status == 0, err
    assert (tmp_path / "out.fold").exists()
