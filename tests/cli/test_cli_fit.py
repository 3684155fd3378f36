"""``kresling fit crease`` and ``kresling fit bending``: JSON, tables, and errors as one
line on stderr with exit status 2."""

import json
import subprocess
import sys

import pytest

from kresling import data
from kresling.cli import main

TABLE1 = str(data.path("thesis_table1_crease_stiffness.csv"))
CREASE_RUNS = str(data.path("examples/synthetic_crease/runs.csv"))
BENDING = [str(data.path(f"examples/synthetic_bending/{state}_{i}.csv"))
           for state in ("extended", "contracted") for i in (1, 2, 3)]


def run_json(capsys, *args):
    assert main(list(args)) == 0
    return json.loads(capsys.readouterr().out)


def test_crease_table_json(capsys):
    out = run_json(capsys, "fit", "crease", TABLE1, "--json")
    assert out["n"] == 15 and out["unit"] == "N/rad"
    assert out["mean"] == pytest.approx(0.0471, abs=1e-4)
    assert out["sd"] == pytest.approx(0.01043, abs=1e-5)
    assert out["skipped"]["count"] == 0 and len(out["samples"]) == 5


def test_crease_raw_records_json(capsys):
    out = run_json(capsys, "fit", "crease", CREASE_RUNS, "--json")
    # The example's truth is 0.047 N/rad (examples/README.md).
    assert out["mean"] == pytest.approx(0.047, rel=0.02)
    assert out["ci"][0] < 0.047 < out["ci"][1]
    assert {"F1", "F2", "beta1", "beta2", "d", "k"} <= set(out["runs"][0])


def test_bending_json(capsys):
    out = run_json(capsys, "fit", "bending", *BENDING, "--json")
    K = out["K"]
    assert out["ratio"] == pytest.approx(K["extended"] / K["contracted"])
    # Example truth: mean of the trials' true K_B in truth.csv (3.569 and 0.825).
    assert K["extended"] == pytest.approx(3.569, rel=0.02)
    assert K["contracted"] == pytest.approx(0.825, rel=0.02)
    assert out["states"]["contracted"]["trials"][0]["offset"] == 0.03


def test_text_outputs(capsys):
    assert main(["fit", "crease", TABLE1]) == 0
    out = capsys.readouterr().out
    assert "0.04707 ± 0.01043" in out and "skipped lines: 0" in out
    assert main(["fit", "bending", *BENDING, "--method", "origin"]) == 0
    assert "K_B ratio:" in capsys.readouterr().out


def test_skipped_rows_are_reported(tmp_path, capsys):
    path = tmp_path / "t.csv"
    path.write_text("sample,run,k_N_per_rad\n1,1,0.04\n1,2,oops\n\n2,1,0.05\n2,2,0.06\n")
    out = run_json(capsys, "fit", "crease", str(path), "--json", "--skip-invalid")
    assert out["n"] == 3 and out["skipped"]["count"] == 2
    assert "line 3" in out["skipped"]["rows"][0] and "'oops'" in out["skipped"]["rows"][0]


def test_configurable_column_names_and_units(tmp_path, capsys):
    path = tmp_path / "t.csv"
    path.write_text("Probe,Go,Kcrease\nA,1,0.04\nA,2,0.05\n")
    out = run_json(capsys, "fit", "crease", str(path), "--json", "--column", "sample=Probe",
                   "--column", "run=Go", "--column", "stiffness=Kcrease",
                   "--unit", "stiffness=mN/rad")
    assert out["mean"] == pytest.approx(4.5e-5)


@pytest.mark.parametrize("args, message", [
    (["crease", "MISSING.csv"], "No such file"),
    (["crease", TABLE1, "--column", "stiffness=K_x"], "no column named 'K_x'"),
    (["bending", BENDING[0], "--module-length", "-5"], "must be > 0"),
    (["crease", TABLE1, "--negate", "force"], "negate apply to the records"),
])
def test_errors_are_one_line_with_status_2(capsys, args, message):
    assert main(["fit", *args, "--json"]) == 2
    captured = capsys.readouterr()
    assert message in captured.err and captured.err.count("\n") == 1
    assert captured.out == ""


def test_malformed_option_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as exit_status:
        main(["fit", "crease", TABLE1, "--column", "oops"])
    assert exit_status.value.code == 2 and "is not KEY=VALUE" in capsys.readouterr().err


def test_the_installed_command_shows_no_traceback(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("sample,run,stiffness_N_per_rad\n1,1,0.04\n1,2,nan\n")
    result = subprocess.run([sys.executable, "-m", "kresling", "fit", "crease", str(bad)],
                            capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert f"{bad}, line 3, column 'stiffness_N_per_rad'" in result.stderr
