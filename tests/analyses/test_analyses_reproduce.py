"""The analyses section of the reproduction report (quick mode)."""

import json

import pytest

from kresling.report.chapters import CHAPTERS


@pytest.fixture(scope="module")
def section(tmp_path_factory):
    import matplotlib

    matplotlib.use("Agg")
    out = tmp_path_factory.mktemp("analyses")
    chapter = next(c for c in CHAPTERS if c.key == "analyses")
    return out, chapter.load()(out, quick=True)


def test_every_check_passes_with_a_stated_tolerance(section):
    _, s = section
    failed = [(c.name, c.value, c.reference) for c in s.checks if not c.passed]
    assert not failed
    assert len(s.checks) >= 40
    assert all(c.tolerance > 0 or c.value == c.reference for c in s.checks)
    names = " ".join(c.name for c in s.checks)
    for topic in ("vs MERLIN2", "vs the thesis", "model vs experiment", "force histories",
                  "kf x 10", "Psi", "linearised", "bending axis angle", "snap force",
                  "de-duplicated"):
        assert topic in names, topic


def test_optimum_ratio_check(section):
    _, s = section
    check = next(c for c in s.checks if c.name == "K_B ratio, n=10 Lc=15 lambda=0.9, vs the thesis")
    assert check.reference == 16.77 and check.value == pytest.approx(16.795, abs=1e-3)


def test_figures_tables_and_fold_file(section):
    out, s = section
    assert len(s.figures) == 5 and len(s.tables) == 3
    for path, caption in s.figures + s.tables:
        assert path.is_file() and path.stat().st_size > 300 and caption
    document = json.loads((out / "optimal_specimen.fold").read_text())
    assert document["file_frames"][0]["frame_title"] == "end of the 5 mm bending test"
    assert "16.80" in s.summary
