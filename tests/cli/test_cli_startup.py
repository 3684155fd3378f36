"""A command imports only what it uses: running one registers that command alone, and the
bending test runs without scipy (no sparse matrix is assembled on its path)."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

SCRIPT = """
import contextlib, io, json, sys
from kresling.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    status = main({args!r})
print(json.dumps([status, sorted({{m.split(".")[0] if not m.startswith("kresling.") else
                                  ".".join(m.split(".")[:2]) for m in sys.modules}})]))
"""


def loaded(args):
    result = subprocess.run([sys.executable, "-c", SCRIPT.format(args=args)],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    status, modules = json.loads(result.stdout.splitlines()[-1])
    assert status == 0
    return set(modules)


@pytest.mark.parametrize("args", [
    ["design", "--n", "10", "--lam", "0.9", "--Lc", "15", "--R", "30"],
    ["bend", "--n", "10", "--lam", "0.9", "--Lc", "15", "--json"],
])
def test_a_command_imports_only_what_it_uses(args):
    modules = loaded(args)
    assert "scipy" not in modules
    # Other commands' packages (the sweeps, the arm, the manipulator, the views, plotly).
    assert not modules & {"kresling.sweeps", "kresling.arm", "kresling.manipulator",
                          "kresling.view", "plotly", "matplotlib", "tqdm"}, modules
    assert ("kresling.analyses" in modules) == (args[0] == "bend")
    # The layers each needs, and no more: design the closed-form geometry; bend also the
    # specimen's model, the displacement-control solver and the bending and snap-through
    # tests (not the pattern readers, the assembly's matrices, the simulations).
    needs = {"kresling", "kresling.cli", "kresling.geometry", "kresling._core",
             "kresling._validation", "kresling._lazy"}
    if args[0] == "bend":
        needs |= {"kresling.model", "kresling.laws", "kresling.solvers", "kresling.analyses"}
    assert {m for m in modules if m.startswith("kresling")} == needs


def test_the_help_still_lists_every_command():
    from kresling.cli import _COMMANDS

    result = subprocess.run([sys.executable, "-m", "kresling", "--help"], capture_output=True,
                            text=True, timeout=120)
    assert result.returncode == 0
    assert all(command in result.stdout for command in _COMMANDS)
    wrong = subprocess.run([sys.executable, "-m", "kresling", "bnd"], capture_output=True,
                           text=True, timeout=120)
    assert wrong.returncode == 2 and "invalid choice: 'bnd'" in wrong.stderr
    assert "'reproduce'" in wrong.stderr
