"""The chapter 2 (geometry) section of the report: known answers, files, and a check that
can fail."""

import csv

import pytest

from kresling.geometry import Design
from kresling.report.sections.geometry import DESIGNS, bar_length_errors, reproduce


@pytest.fixture(scope="module")
def section(tmp_path_factory):
    return reproduce(tmp_path_factory.mktemp("geometry"))


def test_every_check_passes(section):
    failed = [(c.name, c.value, c.reference) for c in section.checks if not c.passed]
    assert not failed
    assert len(section.checks) == 16


def test_the_checks_hold_the_thesis_numbers(section):
    by_name = {c.name: c for c in section.checks}
    optimum = by_name["Le, n=10 lambda=0.9 Lc=15 mm"]
    assert (optimum.reference, optimum.source) == (55.8194667799374, "thesis Appendix E (le)")
    assert by_name["Le, n=4 lambda=0.7 Lc=30 mm"].reference == 41.068587
    assert by_name["extended module length 2 Le, optimum"].value == pytest.approx(111.639,
                                                                                 abs=5e-4)
    assert by_name["Psi_ext, golden model n=4 lambda=0.7 Lc=30 mm"].reference == \
        1.2878022801111912
    # Tolerances are stated, never left at zero.
    assert all(c.tolerance > 0 for c in section.checks)


def test_the_files_are_written(section):
    assert [p.name for p, _ in section.figures] == ["optimal_cell_states.png",
                                                    "optimal_cell_kinematic_path.png"]
    for path, _ in section.figures:
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    (table, _), = section.tables
    rows = list(csv.DictReader(open(table)))
    assert [(int(r["n"]), float(r["lam"]), float(r["Lc"])) for r in rows] == list(DESIGNS)
    assert float(rows[0]["Le"]) == pytest.approx(55.8194667799374, abs=1e-9)


class _Mismatched:
    """The vertices of one design with the crease lengths of another."""

    def __init__(self, shape, lengths):
        self.vertices, self.chirality = shape.vertices, shape.chirality
        self.Vg, self.Mg, self.P = lengths.Vg, lengths.Mg, lengths.P


def test_bar_length_errors_sees_a_cell_that_is_not_stress_free():
    right = Design(8, 0.8, 30.0)
    assert max(bar_length_errors(right).values()) < 1e-12
    errors = bar_length_errors(_Mismatched(right, Design(8, 0.8, 15.0)))
    assert errors["valley"] > 1.0 and errors["mountain"] > 1.0
    assert errors["polygon"] < 1e-12  # same n and R
