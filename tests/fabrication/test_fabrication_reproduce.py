"""The fabrication section of the reproduction report: checks pass and the files exist."""

import math

import pytest

from kresling.report.sections.fabrication import reproduce
from kresling.report import Section


def test_reproduce_writes_the_cut_files_and_passes(tmp_path):
    section = reproduce(tmp_path, quick=True)
    assert isinstance(section, Section)
    failed = [(c.name, c.value, c.reference) for c in section.checks if not c.passed]
    assert not failed
    names = {c.name for c in section.checks}
    assert {"valley crease length, flat pattern", "facet angle P-Vg, flat pattern",
            "strip closure gap, extended", "face isometry, contracted",
            "laminate valley gap width"} <= names
    # Known answers: the tab crease turns by pi - Psi; n = 10 optimum (Psi_ext of
    # Design(10, 0.9, 15)).
    tab = next(c for c in section.checks if c.name == "tab crease fold angle, extended")
    assert tab.reference == pytest.approx(math.pi - 1.513498162614344, abs=1e-12)
    for name in ("cell_n10_laminate", "cell_n10_paper"):
        assert (tmp_path / f"{name}.svg").stat().st_size > 1000
        assert (tmp_path / f"{name}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert [path.name for path, _ in section.figures] == ["cell_n10_laminate.png",
                                                          "cell_n10_paper.png"]
