"""Fuzz: every subcommand of the ``kresling`` command line, with arguments drawn from its
own options (read from the parser, so a new subcommand or option is fuzzed too) and values
of every kind. The property: exit 0 (or 1 with a warning for a run that stopped early), or
a usage error from argparse, or exit 2 (3 for a missing extra) with one line on stderr
naming what is wrong - never a traceback, never another exception."""

import contextlib
import io
import os
import shutil
import tempfile
from pathlib import Path

from hypothesis import event, given
from hypothesis import strategies as st

from _fuzz import fuzz
from kresling import data
from kresling.cli import build_parser, main

TESTS = Path(__file__).resolve().parents[1]
FILES = {  # inputs a positional argument may name, copied into the working directory
    "pattern.fold": TESTS / "data" / "patterns" / "square_twist_1.2.fold",
    "pattern.obj": TESTS / "data" / "patterns" / "mixed_polygons.obj",
    "record.csv": Path(data.path("examples/synthetic_bending/extended_1.csv")),
    "runs.csv": Path(data.path("examples/synthetic_crease/runs.csv")),
}
PROBLEM = """[pattern]
vertices = [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]]
panels = [[0, 1, 4, 3], [1, 2, 5, 4]]
[material]
calibration = "auto"
E = 1000.0
nu = 0.3
thickness = 0.25
[[support]]
nodes = [0, 3]
fix = "xyz"
[[support]]
node = 1
fix = "z"
[[load]]
nodes = [2, 5]
force = [0.0, 0.0, 0.01]
[analysis]
method = "mgdcm"
max_increments = 3
"""
VALUES = ["0", "1", "-1", "2", "3", "4", "6", "8", "10", "0.5", "0.6", "0.8", "0.9", "15", "30",
          "1e-310", "-1e-310", "5e-324", "nan", "inf", "-inf", "1e400", "1e308",
          "100000000000000000000", "2147483648", "abc", "", "-", "101", "111", "000", "(1 0 1)",
          "x", "y", "z", "extended", "contracted", "laminate", "paper", "psi_ratio", "kb_ratio",
          "threads", "processes", "out.svg", "out.fold", "out.png", "out.dxf", "out.html",
          "missing.csv", "pattern.fold", "pattern.obj", "problem.toml", "record.csv",
          "runs.csv", "junk.bin", ".", "dir", "force=Load", "force=lbf", "=", "1,2,3"]
PLAUSIBLE_INTS = ["1", "2", "3", "4", "6", "8", "10"]
PLAUSIBLE_FLOATS = ["0.6", "0.7", "0.8", "0.9", "1", "5", "15", "30", "0.001"]
POSITIONAL = ["pattern.fold", "pattern.obj", "problem.toml", "record.csv", "runs.csv",
              "junk.bin", "missing.toml", "dir", "", "-x"]
POSITIONAL_OF = {"problem": ["problem.toml"], "pattern": ["pattern.fold", "pattern.obj"],
                 "table": ["runs.csv"], "records": ["record.csv"]}
OPTION_VALUES = {  # plausible values of options whose type says little (or costs much)
    "grid": ["1", "2"], "metrics": ["psi_ratio", "kb_ratio_linear", "snap_force"],
    "column": ["force=Load", "displacement=Position", "time=t"],
    "record_column": ["force=Load", "displacement=Position"],
    "unit": ["force=N", "force=lbf", "displacement=mm"],
    "record_unit": ["force=N", "displacement=in"], "negate": ["force", "displacement"],
    "target": ["0", "10", "200", "-50"], "out": ["out", "out.html", "dir"],
    "output": ["out.svg", "out.dxf", "out.fold", "out.png"], "plot": ["plot.png"],
    "view": ["view.html"], "steps": ["2", "5", "20"], "workers": ["1", "2"],
    # kresling snap --dynamic: short runs (a full one takes 2 s of simulated time)
    "duration": ["0.35", "0.5"], "time_step": ["1e-3", "5e-4"], "hold": ["0.1", "0.3"],
    "margin": ["0.05", "0.5"], "damping": ["0.05", "0.3"], "eccentricity": ["0", "0.1"],
    "modes": ["1", "3"],
}
#: Options left out: a cluster address waits for its connection to time out.
SKIPPED_OPTIONS = {"scheduler"}
SLOW = {"reproduce", "explore"}  # minutes of work at any size: only their argument errors


def _subcommands():
    parser = build_parser()
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    commands = {}
    for name, subparser in sub.choices.items():
        nested = [a for a in subparser._actions if a.__class__.__name__ == "_SubParsersAction"]
        if nested:
            for inner, parser_ in nested[0].choices.items():
                commands[f"{name} {inner}"] = parser_
        else:
            commands[name] = subparser
    return commands


COMMANDS = _subcommands()


def rarely(valid, invalid):
    """``valid`` nine times in ten: a command line with many options then mostly reaches
    the command instead of stopping at argparse."""
    return st.integers(0, 9).flatmap(lambda k: valid if k < 9 else invalid)


@st.composite
def command_lines(draw, name):
    parser = COMMANDS[name]
    argv = name.split()
    for action in parser._actions:
        if "-h" in action.option_strings or action.dest in SKIPPED_OPTIONS:
            continue
        if not action.option_strings:  # positional
            count = 1 if action.nargs in (None, 1) else draw(st.integers(0, 3))
            fitting = POSITIONAL_OF.get(action.dest, POSITIONAL)
            argv += [draw(rarely(st.sampled_from(fitting), st.sampled_from(POSITIONAL)))
                     for _ in range(count)]
            continue
        if not action.required and not draw(st.booleans()):
            continue
        option = draw(st.sampled_from(action.option_strings))
        if action.nargs == 0:
            argv.append(option)
            continue
        count = {None: 1, "?": 1, "+": draw(st.integers(1, 3)), "*": draw(st.integers(0, 3))}.get(
            action.nargs, action.nargs if isinstance(action.nargs, int) else 1)
        plausible = (OPTION_VALUES[action.dest] if action.dest in OPTION_VALUES else
                     [str(c) for c in action.choices] if action.choices else
                     PLAUSIBLE_INTS if action.type is int else
                     PLAUSIBLE_FLOATS if action.type is float else VALUES)
        values = [draw(rarely(st.sampled_from(plausible), st.sampled_from(VALUES)))
                  for _ in range(count)]
        argv += [option + "=" + values[0], *values[1:]] if values and values[0].startswith("-") \
            else [option, *values]
    if name in SLOW:
        argv.append("--no-such-option")  # argparse refuses it before any work
    if name == "sweep":  # not the thesis's 40 000 designs, not a process per core
        argv += [] if "--grid" in argv else ["--grid", "1"]
        argv += [] if "--workers" in argv else ["--workers", "1"]
    return argv


def run(argv):
    out, err = io.StringIO(), io.StringIO()
    with tempfile.TemporaryDirectory() as directory:
        cwd = os.getcwd()
        os.chdir(directory)
        try:
            for target, source in FILES.items():
                shutil.copy(source, target)
            for record in ("s1_r1.csv", "s1_r2.csv"):
                shutil.copy(FILES["runs.csv"].parent / record, record)
            Path("problem.toml").write_text(PROBLEM)
            Path("junk.bin").write_bytes(b"\x00\xff" * 50)
            Path("dir").mkdir()
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                try:
                    status = main(argv)
                except SystemExit as exit_:  # argparse: --help, --version or a usage error
                    status = ("argparse", exit_.code)
            event(f"exit {status[1] if isinstance(status, tuple) else status}"
                  + (" (argparse)" if isinstance(status, tuple) else ""))
        finally:
            os.chdir(cwd)
    return status, out.getvalue(), err.getvalue()


def check(argv):
    status, out, err = run(argv)
    assert "Traceback" not in err and "Traceback" not in out, f"{argv}: {err}"
    if isinstance(status, tuple):
        assert status[1] in (0, 2), f"{argv}: argparse exit {status[1]}"
        return
    assert status in (0, 1, 2, 3), f"{argv}: exit {status}"
    if status in (2, 3):
        lines = err.strip().splitlines()
        prefix = f"kresling {argv[0]}: error: "
        errors = [line for line in lines if line.startswith(prefix)]
        assert len(errors) == 1 and lines[-1] == errors[0], f"{argv}: stderr {err!r}"
        assert len(errors[0]) > len(prefix) + 5, f"{argv}: an empty message"
    if status == 1:
        assert err.strip(), f"{argv}: exit 1 without saying why"


EXAMPLES = {"bend": 10, "sweep": 10, "simulate": 15, "arm": 10}


def _test(name):
    @fuzz(EXAMPLES.get(name.split()[0], 25))
    @given(command_lines(name))
    def test(argv):
        check(argv)
    test.__name__ = f"test_{name.replace(' ', '_')}"
    return test


for _name in COMMANDS:
    globals()[f"test_{_name.replace(' ', '_')}"] = _test(_name)
