"""The ``kresling pattern`` command: each format from the extension, the module sheet, and
errors on stderr without a traceback."""

import json
import xml.etree.ElementTree as ET

import pytest

from kresling.cli import main
from cli_helpers import run_kresling

DESIGN = ["--n", "10", "--lam", "0.9", "--Lc", "15", "--R", "30"]


def run_cli(*args, cwd):
    return run_kresling("pattern", *args, cwd=cwd)


def test_the_documented_command_writes_the_laminate_svg(tmp_path):
    result = run_cli(*DESIGN, "--process", "laminate", "-o", "cell.svg", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "wrote cell.svg" in result.stdout and result.stderr == ""
    root = ET.parse(tmp_path / "cell.svg").getroot()
    assert root.get("width").endswith("mm")


@pytest.mark.parametrize("name", ["cell.dxf", "cell.fold", "cell.png"])
def test_other_formats(name, tmp_path, capsys):
    assert main(["pattern", *DESIGN, "--process", "paper", "-o", str(tmp_path / name)]) == 0
    assert (tmp_path / name).stat().st_size > 1000
    assert name in capsys.readouterr().out


def test_module_json_summary(tmp_path, capsys):
    out = tmp_path / "module.svg"
    assert main(["pattern", *DESIGN, "--module", "--gap-width", "1.2", "--kerf", "0.1",
                 "-o", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["module"] is True and summary["process"] == "laminate"
    assert summary["layers"] == {"cut layer 1: base polygon, valley gaps, crease cuts": 64,
                                 "cut layer 2: outline": 6}
    assert summary["height_mm"] > 2 * 100


@pytest.mark.parametrize(
    "args, message",
    [
        (["--process", "plastic", "-o", "c.svg"], "process = 'plastic' is invalid"),
        (["-o", "c.pdf"], "file extension '.pdf' of 'c.pdf' is invalid"),
        (["--gap-width", "40", "-o", "c.svg"], "gap_width = 40.0 mm is invalid"),
        (["--process", "paper", "--gap-width", "1", "-o", "c.svg"],
         "gap_width is not a parameter of the paper process"),
        (["--tab-height", "29", "-o", "c.svg"], "tab_height = 29.0 mm is invalid"),
        (["--module", "-o", "c.fold"], "module = True is invalid with .fold"),
        (["--lam", "1.2", "-o", "c.svg"], "lam = 1.2 is invalid"),
    ],
)
def test_bad_input_exits_nonzero_without_traceback(args, message, tmp_path, capsys,
                                                  monkeypatch):
    monkeypatch.chdir(tmp_path)
    base = DESIGN if "--lam" not in args else ["--n", "10", "--Lc", "15"]
    assert main(["pattern", *base, *args]) == 2
    captured = capsys.readouterr()
    assert message in captured.err
    assert "Traceback" not in captured.err and captured.out == ""
    assert list(tmp_path.iterdir()) == []                 # nothing half-written


def test_bad_input_in_a_real_process(tmp_path):
    result = run_cli(*DESIGN, "--process", "plastic", "-o", "c.svg", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.startswith("kresling pattern: error: process = 'plastic' is invalid")
    assert "Traceback" not in result.stderr and result.stdout == ""
