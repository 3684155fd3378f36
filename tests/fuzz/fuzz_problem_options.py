"""Fuzz: the problem keys and command-line options that choose a pattern's reading, its
material and its outputs, one target each - [pattern] snap_tolerance and simulate's and
pattern's --snap-tolerance, [material] preset, [analysis] fold_percent and
--fold-percent, [output] formats, and `kresling pattern --check` - with values of every
kind. A value is used (the run ends finite, or stopped saying why; the files asked for are
written) or refused with a ValueError naming the key (the CLI: exit 2 with one line
naming the option or key; --check: exit 1 with simulate's reason); never a traceback."""

import contextlib
import copy
import io
import os
import tempfile
from pathlib import Path

from hypothesis import event, given
from hypothesis import strategies as st

from _fuzz import edgy_floats, fuzz, junk, mostly, path_ok
from kresling.cli import main
from kresling.model.material_presets import MATERIAL_PRESETS
from kresling.simulate import load_problem, simulate

DATA = Path(__file__).resolve().parents[1] / "data"
SVG = DATA / "patterns" / "flapping_bird.svg"
SHEET = {"vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]],
         "panels": [[0, 1, 4, 3], [1, 2, 5, 4]]}
FOLD = {"pattern": dict(SHEET),
        "actuation": [{"edges": [[1, 4]], "fold_angle_deg": 60.0}],
        "analysis": {"method": "fold", "steps": 2}}
TEXT_VALUES = ["0", "1", "-1", "0.5", "3", "50", "100", "100.5", "1e-310", "1e308", "nan",
               "inf", "-inf", "abc", "", "1e400"]


def _cli(argv, cwd):
    out, err = io.StringIO(), io.StringIO()
    here = os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                status = main(argv)
            except SystemExit as exit_:  # argparse: a value of the wrong type
                status = ("argparse", exit_.code)
    finally:
        os.chdir(here)
    text = err.getvalue()
    assert "Traceback" not in text and "Traceback" not in out.getvalue(), (argv, text)
    if isinstance(status, tuple):
        assert status[1] == 2, (argv, status)
        return 2, text
    assert status in (0, 1, 2), (argv, status, text)
    if status == 2:
        assert text.strip().splitlines()[-1].startswith(f"kresling {argv[0]}: error: "), text
    if status == 1:
        assert text.strip(), (argv, "exit 1 without saying why")
    return status, text


def _load_or_named(problem, *keys):
    try:
        return load_problem(problem)
    except ValueError as error:
        assert any(key in str(error) for key in keys), f"names none of {keys}: {error}"
        event("refused")
        return None


def _fold(problem):
    run = simulate(problem, progress=False)
    path_ok(run.path)
    return run


@fuzz(30)
@given(mostly(st.floats(1e-3, 50), edgy_floats, junk), st.booleans())
def test_snap_tolerance_key(value, svg):
    problem = copy.deepcopy(FOLD)
    problem["pattern"] = {"file": str(SVG)} if svg else dict(SHEET)
    problem["pattern"]["snap_tolerance"] = value
    problem["actuation"] = [{"family": "fold", "fold_angle_deg": "file"}]
    loaded = _load_or_named(problem, "snap_tolerance", SVG.name)
    if loaded is not None:
        assert svg, "snap_tolerance taken for a pattern that is not an SVG drawing"
        event(f"{loaded.pattern.num_vertices} vertices")


@fuzz(12)
@given(st.sampled_from(TEXT_VALUES + ["2", "0.001"]),
       st.sampled_from(["simulate", "pattern --check", "pattern --from"]))
def test_snap_tolerance_option(value, command):
    with tempfile.TemporaryDirectory() as directory:
        folder = Path(directory)
        (folder / "bird.svg").write_bytes(SVG.read_bytes())
        (folder / "problem.toml").write_text(
            '[pattern]\nfile = "bird.svg"\n\n[[actuation]]\nfamily = "fold"\n'
            'fold_angle_deg = "file"\n\n[analysis]\nmethod = "fold"\nsteps = 2\n')
        argv = {"simulate": ["simulate", "problem.toml", "--quiet", "--no-view"],
                "pattern --check": ["pattern", "--check", "bird.svg"],
                "pattern --from": ["pattern", "--from", "bird.svg", "-o", "out.fold"]}[command]
        status, err = _cli(argv + [f"--snap-tolerance={value}"], folder)
        if status == 2 and "argument" not in err:    # argparse names the argument
            assert "snap" in err or "bird.svg" in err, err
        if command == "pattern --from" and status == 0:
            assert (folder / "out.fold").stat().st_size > 0


@fuzz(20)
@given(mostly(st.sampled_from(sorted(MATERIAL_PRESETS)), junk, st.text(max_size=8)),
       st.fixed_dictionaries({}, optional={
           "density": mostly(st.floats(1e-12, 1e-6), edgy_floats, junk),
           "thickness": mostly(st.floats(0.01, 1), edgy_floats, junk),
           "calibration": st.sampled_from(["manual", "auto", 3]),
           "merlin2_compat": st.one_of(st.booleans(), junk),
           "E": mostly(st.floats(1, 1e4), junk)}),
       st.booleans())
def test_material_preset(preset, extra, run):
    problem = copy.deepcopy(FOLD)
    problem["material"] = {"preset": preset, **extra}
    loaded = _load_or_named(problem, "preset", *extra)
    if loaded is not None and run:
        _fold(loaded)


@fuzz(20)
@given(mostly(st.floats(1e-3, 100), edgy_floats, junk, st.sampled_from([0, 100, 100.0001])))
def test_fold_percent_key(percent):
    problem = copy.deepcopy(FOLD)
    problem["analysis"]["fold_percent"] = percent
    loaded = _load_or_named(problem, "fold_percent")
    if loaded is not None:
        assert 0 < loaded.analysis.fold_percent <= 100
        _fold(loaded)


@fuzz(10)
@given(st.sampled_from(TEXT_VALUES + ["25", "99.9"]))
def test_fold_percent_option(value):
    with tempfile.TemporaryDirectory() as directory:
        folder = Path(directory)
        (folder / "problem.toml").write_text(
            "[pattern]\nvertices = " + str(SHEET["vertices"]) + "\npanels = "
            + str(SHEET["panels"]) + '\n\n[[actuation]]\nedges = [[1, 4]]\n'
            'fold_angle_deg = 60.0\n\n[analysis]\nmethod = "fold"\nsteps = 2\n')
        status, err = _cli(["simulate", "problem.toml", "--quiet", "--no-view",
                            f"--fold-percent={value}"], folder)
        if status == 2 and "argument" not in err:
            assert "fold_percent" in err or "fold-percent" in err, err


@fuzz(20)
@given(mostly(st.lists(st.sampled_from(["stl", "obj"]), max_size=3), junk,
              st.lists(st.sampled_from(["stl", "obj", "ply", "STL", "", 3]), max_size=3)),
       st.sampled_from(["fold", "displacement_control"]))
def test_output_formats(formats, method):
    problem = copy.deepcopy(FOLD)
    if method == "displacement_control":
        problem = {"pattern": dict(SHEET, split="N4B5"),
                   "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                                "fold_stiffness": 0.1, "bend_stiffness": 1.0},
                   "support": [{"nodes": [0, 3], "fix": "xyz"}, {"node": 1, "fix": "yz"},
                               {"node": 4, "fix": "z"}],
                   "load": [{"nodes": [2, 5], "displacement": [0.0, 0.0, 0.2]}],
                   "analysis": {"method": "displacement_control", "steps": 2}}
    problem["output"] = {"formats": formats}
    loaded = _load_or_named(problem, "formats")
    if loaded is None:
        return
    run = _fold(loaded)
    with tempfile.TemporaryDirectory() as folder:
        written = run.write(folder, view=False)
        for name in set(loaded.output.formats):
            assert (Path(folder) / f"folded.{name}").stat().st_size > 0, written


@fuzz(15)
@given(st.sampled_from(sorted(DATA.rglob("*.fold")) + sorted(DATA.rglob("*.svg"))
                       + sorted(DATA.rglob("*.obj"))),
       st.sampled_from(["N5B8", "N4B5", "N6B9"]), st.booleans())
def test_pattern_check(path, split, as_json):
    with tempfile.TemporaryDirectory() as directory:
        argv = ["pattern", "--check", str(path), f"--split={split}"] + (
            ["--json"] if as_json else [])
        status, err = _cli(argv, directory)
        if status == 1:
            assert "simulate would refuse it: " in err, err
