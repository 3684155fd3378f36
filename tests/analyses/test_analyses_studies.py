"""The chapter 3 study scripts run at small size; one number pinned in each."""

import importlib.util
from pathlib import Path

import pytest

STUDIES = Path(__file__).resolve().parents[2] / "studies"


def load(name):
    spec = importlib.util.spec_from_file_location(name, STUDIES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_table3(capsys, tmp_path):
    assert load("table3").main(["--skip-extras", "--csv", str(tmp_path / "t.csv")]) == 0
    out = capsys.readouterr().out
    assert "n=10 Lc=15   lam=0.9        16.79511  16.79511" in out
    assert "printed   4.91  of means   4.38" in out
    assert (tmp_path / "t.csv").read_text().startswith("n,Lc_mm,lambda,ours_extended")


@pytest.mark.parametrize("name, args, pinned", [
    ("bending_figures", [], "n=10: 3.357/0.200 ratio 16.80"),
    ("snap_through", ["--steps", "50"], "n=8  Lc=30   lam=0.8    4.340 N"),
    ("orientation", ["--points", "3"], "n=10  K_ext   +4.0 %  K_con   +8.0 %"),
])
def test_figure_studies(capsys, tmp_path, name, args, pinned):
    assert load(name).main(args + ["--out", str(tmp_path)]) == 0
    assert pinned in capsys.readouterr().out
    assert list(tmp_path.glob("*.png"))
