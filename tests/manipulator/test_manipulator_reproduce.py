"""The manipulator's report section: every check passes and the figures are written."""

from kresling.report.sections.manipulator import reproduce


def test_reproduce_quick(tmp_path):
    section = reproduce(tmp_path, quick=True)
    failed = [(c.name, c.value, c.reference) for c in section.checks if not c.passed]
    assert not failed
    assert len(section.checks) >= 15
    assert len(section.figures) == 5 and all(path.stat().st_size > 10_000 for path, _ in section.figures)
    assert all(path.is_file() for path, _ in section.tables)
