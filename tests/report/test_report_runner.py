"""The report's runner and chapter registry: failing, raising and missing sections."""

import pytest

from kresling.report.chapters import CHAPTERS, Chapter, SectionNotAvailable, select_chapters
from kresling.report.runner import ERROR, NOT_AVAILABLE, RAN, run_section, run_sections


def fake(key, function):
    return Chapter(key, f"Part {key}", f"Title {key}", "report_fakes", function)


MISSING = Chapter("later", "Chapter 9", "Written later", "kresling.not_written_yet")


def test_a_passing_section_runs_in_its_own_directory_and_is_timed(tmp_path):
    run = run_section(fake("good", "passing"), tmp_path, quick=False)
    assert run.status == RAN and run.error == "" and run.traceback == ""
    assert run.section.summary == "quick=False"
    assert (tmp_path / "good" / "line.png").is_file()
    assert 0.05 <= run.seconds < 10 and run.section.seconds == run.seconds
    assert (run.checks_passed, len(run.checks)) == (2, 2)
    assert (run.checks_text, run.outcome) == ("2/2", "all within tolerance")


def test_checks_outside_tolerance_are_counted_not_errors(tmp_path):
    run = run_section(fake("off", "off_tolerance"), tmp_path)
    assert run.status == RAN
    assert run.checks_passed == 1 and isinstance(run.checks_passed, int)
    assert (run.checks_text, run.outcome) == ("1/3", "2 outside tolerance")


@pytest.mark.parametrize("function, error", [
    ("raising", "RuntimeError: boom <b>"),
    ("not_a_section", "TypeError: reproduce() returned int, not a Section"),
    ("figure_not_written", "FileNotFoundError: the section lists figure"),
])
def test_a_failing_section_is_recorded_with_its_error(tmp_path, function, error):
    run = run_section(fake("bad", function), tmp_path)
    assert run.status == ERROR and run.section is None and run.checks == []
    assert run.error.startswith(error)
    assert "Traceback" in run.traceback
    assert run.outcome == f"error: {run.error}"


def test_the_other_sections_still_run_after_one_raises(tmp_path):
    runs = run_sections([fake("a", "raising"), MISSING, fake("b", "passing")], tmp_path)
    assert [run.status for run in runs] == [ERROR, NOT_AVAILABLE, RAN]
    assert [run.chapter.key for run in runs] == ["a", "later", "b"]


def test_a_missing_module_is_not_available_not_an_error(tmp_path):
    run = run_section(MISSING, tmp_path)
    assert run.status == NOT_AVAILABLE
    assert run.error == "module kresling.not_written_yet does not exist yet"
    assert run.title == "Written later" and run.outcome == "not yet available"
    assert run.checks_text == "-"
    with pytest.raises(SectionNotAvailable):
        Chapter("x", "", "", "kresling.fits", "no_such_function").load()


def test_a_module_that_fails_to_import_is_an_error(tmp_path, monkeypatch):
    (tmp_path / "broken_area.py").write_text("import a_dependency_nobody_installed_xyz\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    run = run_section(Chapter("broken", "", "", "broken_area"), tmp_path / "out")
    assert run.status == ERROR
    assert "a_dependency_nobody_installed_xyz" in run.error


def test_figures_a_section_leaves_open_are_closed_but_not_the_callers(tmp_path):
    import matplotlib.pyplot as plt

    mine = plt.figure()
    try:
        before = set(plt.get_fignums())
        run_section(fake("open", "leaves_a_figure_open"), tmp_path)
        assert set(plt.get_fignums()) == before
    finally:
        plt.close(mine)


def test_the_registry_lists_the_thesis_in_order_and_loads_what_exists():
    keys = [chapter.key for chapter in CHAPTERS]
    assert keys == ["geometry", "experiments", "analyses", "sweeps", "fabrication",
                    "manipulator", "arm"]
    for key in ("geometry", "experiments", "fabrication", "manipulator", "arm"):
        function = next(c for c in CHAPTERS if c.key == key).load()
        assert callable(function) and function.__name__ == "reproduce"


def test_select_chapters_keeps_report_order_and_rejects_unknown_names():
    assert [c.key for c in select_chapters(["manipulator", "geometry"])] == \
        ["geometry", "manipulator"]
    assert select_chapters(None) == CHAPTERS
    with pytest.raises(ValueError, match="unknown section 'geometri': must be one of "
                                         "geometry, experiments"):
        select_chapters(["geometri"])
