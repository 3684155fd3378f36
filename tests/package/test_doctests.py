"""The examples in the docstrings of every module of the package run, and print what they say.

Every module is found by walking the package (a new module is picked up without touching this
file). Each module is one test: a module that cannot be imported fails here (a missing
dependency is named in the error, never skipped), and a failing example shows doctest's
report. This runs under ``pytest``, ``pytest tests`` or any subset that includes this file.
"""

import doctest
import importlib
import pkgutil

import matplotlib
import pytest

import kresling

matplotlib.use("Agg")  # examples that draw must never open a window

#: ``python -m kresling`` runs the command line when imported: not a module with examples.
NOT_IMPORTED = {"kresling.__main__"}

MODULES = sorted(
    {"kresling"} | {info.name for info in pkgutil.walk_packages(kresling.__path__, "kresling.")}
    - NOT_IMPORTED)

#: Modules whose docstrings are known to hold examples (at least one must be found and run).
WITH_EXAMPLES = {
    "kresling", "kresling.geometry", "kresling.data.tables", "kresling.fabrication",
    "kresling.fabrication.accuracy", "kresling.analyses.linear_bending",
    "kresling.analyses.orientation", "kresling.analyses.snap_through",
    "kresling.analyses.facet_angle", "kresling.sweeps", "kresling.sweeps.designs",
    "kresling.sweeps.table", "kresling.sweeps.sweep", "kresling.manipulator",
    "kresling.manipulator.model", "kresling.manipulator.constant_curvature",
    "kresling.manipulator.forward", "kresling.manipulator.motors",
    "kresling.manipulator.inverse", "kresling.report.html_report",
}


def run_examples(module):
    """Run the examples of ``module`` (not those of modules it imports); return the number
    attempted, the number failed and doctest's report of the failures."""
    report = []
    runner = doctest.DocTestRunner()
    for test in doctest.DocTestFinder().find(module, module.__name__):
        runner.run(test, out=report.append)
    return runner.tries, runner.failures, "".join(report)


def test_every_module_is_found():
    assert WITH_EXAMPLES <= set(MODULES)
    assert {"kresling.report.chapters", "kresling.laws", "kresling.cli"} <= set(MODULES)


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    attempted, failed, report = run_examples(module)
    assert failed == 0, f"{failed} of {attempted} examples of {name} failed:\n{report}"
    if name in WITH_EXAMPLES:
        assert attempted > 0, f"{name} lost its examples"
