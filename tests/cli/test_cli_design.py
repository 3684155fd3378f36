"""The ``kresling design`` command: table, JSON, and errors without tracebacks."""

import json

import pytest

from kresling.cli import main
from cli_helpers import run_kresling

KEYS = ("P", "gamma", "V", "M", "Vg", "Mg", "theta_g", "alpha0", "alpha_e", "Le",
        "Psi_ext", "Psi_con")



def test_json_has_every_quantity(tmp_path):
    result = run_kresling("design", "--n", "10", "--lam", "0.9", "--Lc", "15", "--R", "30", "--json",
                     cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    values = json.loads(result.stdout)
    assert set(KEYS) <= set(values)
    assert values["Le"] == pytest.approx(55.8194667799374, abs=1e-9)


def test_table(capsys):
    assert main(["design", "--n", "8", "--lam", "0.8", "--Lc", "30"]) == 0
    out = capsys.readouterr().out
    assert "Le" in out and "55.31764" in out and "Psi_ext" in out


@pytest.mark.parametrize(
    "args, message",
    [
        (["--n", "10", "--lam", "1.2", "--Lc", "15"], "lam = 1.2 is invalid"),
        (["--n", "2", "--lam", "0.9", "--Lc", "15"], "n = 2 is invalid"),
        (["--n", "10", "--lam", "0.9", "--Lc", "-3"], "Lc = -3 is invalid"),
        (["--n", "10", "--lam", "nan", "--Lc", "15"], "lam = nan is invalid"),
        (["--n", "10", "--lam", "0.9", "--Lc", "15", "--R", "0"], "R = 0 is invalid"),
        (["--n", "ten", "--lam", "0.9", "--Lc", "15"], "invalid int value"),
    ],
)
def test_invalid_input_exits_nonzero_without_traceback(tmp_path, args, message):
    result = run_kresling("design", *args, "--json", cwd=tmp_path)
    assert result.returncode != 0
    assert message in result.stderr
    assert "Traceback" not in result.stderr
    assert result.stdout == ""
