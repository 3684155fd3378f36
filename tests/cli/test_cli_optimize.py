"""``kresling optimize``: the constrained optimum on exact gradients, JSON, bad input."""

import json

import pytest

from kresling.cli import main


def test_the_kb_con_floor_optimum(capsys):
    assert main(["optimize", "--n", "10", "--min", "kb_con", "0.3", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["success"] and result["design"]["lam"] == 0.9
    assert set(result["active"]) == {"lam max", "kb_con min"}
    assert result["values"]["kb_con"] == pytest.approx(0.3, rel=1e-6)
    # The optimum of forward differences, found by the library (tests/sweeps/test_sweeps_study.py).
    assert result["design"]["Lc"] == pytest.approx(29.3532947, rel=1e-6)
    assert main(["optimize", "--n", "10", "--min", "kb_con", "0.3"]) == 0
    assert "active bounds: lam max, kb_con min" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["--n", "7"], "--n = 7 is invalid for kb_ratio"),
    (["--n", "8", "--min", "nope", "1"], "unknown metric column 'nope'"),
    (["--n", "8", "--max", "kb_con", "x"], "--max kb_con 'x' is invalid: the bound must be a number"),
])
def test_bad_input_exits_2_naming_the_option(argv, message, capsys):
    assert main(["optimize", *argv]) == 2
    assert message in capsys.readouterr().err


def test_an_optimum_short_of_its_constraints_says_why_on_stderr(capsys):
    # (found by the fuzz target at scale 50: exit 1 with nothing on stderr)
    assert main(["optimize", "--n", "6", "--Lc", "0", "0.9", "--polygon-edge-ratio", "0.7",
                 "--bar-ratio", "0.6"]) == 1
    err = capsys.readouterr().err
    assert err.strip().startswith("kresling optimize: ") and "constraints not met" in err
