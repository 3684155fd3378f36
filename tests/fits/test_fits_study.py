"""The experimental-fits study runs at small size; one number pinned."""

import importlib.util
from pathlib import Path

STUDY = Path(__file__).resolve().parents[2] / "studies" / "experimental_fits.py"


def test_study_runs_and_prints_table1(capsys):
    spec = importlib.util.spec_from_file_location("experimental_fits", STUDY)
    study = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(study)
    assert study.main(["--repetitions", "20", "--no-figures"]) == 0
    out = capsys.readouterr().out
    assert "mean 0.04707  sample SD 0.01043" in out
    assert "printed   4.91  recomputed   4.38" in out
