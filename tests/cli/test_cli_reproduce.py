"""``kresling reproduce`` on fake sections: output, progress, exit codes, options."""

import json

import pytest

from kresling.cli import main
from kresling.report import chapters
from kresling.report.chapters import Chapter

GOOD = Chapter("good", "Part 1", "Good", "report_fakes", "passing")
OFF = Chapter("off", "Part 2", "Off", "report_fakes", "off_tolerance")
LATER = Chapter("later", "Part 3", "Written later", "kresling.not_written_yet")
BROKEN = Chapter("broken", "Part 4", "Broken", "report_fakes", "raising")


@pytest.fixture
def use_chapters(monkeypatch):
    def use(*selected):
        monkeypatch.setattr(chapters, "CHAPTERS", selected)
    return use


def test_failed_checks_and_missing_sections_still_exit_0(use_chapters, tmp_path, capsys):
    use_chapters(GOOD, OFF, LATER)
    assert main(["reproduce", "--quick", "--out", str(tmp_path)]) == 0
    out, err = capsys.readouterr()
    lines = out.splitlines()
    assert lines[0].split() == ["section", "thesis", "checks", "seconds", "outcome"]
    assert lines[2].split() == ["good", "Part", "1", "2/2", lines[2].split()[4], "all",
                                "within", "tolerance"]
    assert lines[3].split()[3] == "1/3" and lines[3].endswith("2 outside tolerance")
    assert lines[4].split()[:4] == ["later", "Part", "3", "-"] and "not yet available" in lines[4]
    assert f"report: {tmp_path / 'report.html'}" in lines
    assert (tmp_path / "report.html").is_file() and (tmp_path / "report.json").is_file()
    # Progress on stderr: a line as each section starts and one as it ends.
    assert "[reproduce] good: started (Part 1)" in err
    assert "[reproduce] later: not yet available" in err
    assert "[reproduce] off: 1/3 checks passed, 2 outside tolerance (" in err
    assert err.count("started") == 3


def test_a_raising_section_exits_1_after_the_others_ran(use_chapters, tmp_path, capsys):
    use_chapters(BROKEN, GOOD)
    assert main(["reproduce", "--out", str(tmp_path)]) == 1
    out, err = capsys.readouterr()
    assert "kresling reproduce: error: 1 section(s) raised: broken" in err
    assert "[reproduce] broken: error: RuntimeError: boom <b>" in err
    document = json.loads((tmp_path / "report.json").read_text())
    assert [s["status"] for s in document["sections"]] == ["error", "ran"]


def test_full_and_only(use_chapters, tmp_path):
    use_chapters(GOOD, OFF, LATER)
    assert main(["reproduce", "--full", "--out", str(tmp_path), "--only", "good"]) == 0
    document = json.loads((tmp_path / "report.json").read_text())
    assert document["mode"] == "full"
    assert document["command"] == f"kresling reproduce --full --out {tmp_path} --only good"
    assert [s["key"] for s in document["sections"]] == ["good"]
    assert document["sections"][0]["summary"] == "quick=False"


def test_an_unknown_section_is_a_usage_error(use_chapters, tmp_path, capsys):
    use_chapters(GOOD, OFF)
    assert main(["reproduce", "--out", str(tmp_path / "r"), "--only", "goood"]) == 2
    err = capsys.readouterr().err
    assert err.strip() == ("kresling reproduce: error: unknown section 'goood': must be one "
                           "of good, off")
    assert not (tmp_path / "r").exists()


def test_quick_and_full_exclude_each_other(capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(["reproduce", "--quick", "--full"])
    assert exit_info.value.code == 2
    assert "not allowed with argument" in capsys.readouterr().err


def test_list_shows_every_section_and_whether_it_exists(use_chapters, tmp_path, capsys):
    use_chapters(GOOD, LATER, Chapter("bad", "Part 5", "Bad", "report_fakes", "nothing"))
    assert main(["reproduce", "--list"]) == 0
    rows = {line.split()[0]: line for line in capsys.readouterr().out.splitlines()[2:]}
    assert "available" in rows["good"].split()
    assert "not yet available" in rows["later"]
    assert "not yet available" in rows["bad"]


def test_the_real_registry_is_listed(capsys):
    assert main(["reproduce", "--list"]) == 0
    out = capsys.readouterr().out
    for chapter in chapters.CHAPTERS:
        assert chapter.key in out
