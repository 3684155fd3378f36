"""The ``kresling manipulator`` command."""

import json
import math

import pytest

from kresling.cli import main
from cli_helpers import run_kresling


def run_cli(*args, cwd):
    return run_kresling("manipulator", *args, cwd=cwd)


def test_json_markers_tendons_and_counts(tmp_path):
    result = run_cli("--config", "101", "--k", "10", "--json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    out = json.loads(result.stdout)
    theta = 2 * math.asin(10 / 32)
    L = 2 * 55.8194667799374
    assert len(out["markers"]) == 4 and all(len(p) == 3 for p in out["markers"])
    assert out["markers"][1] == pytest.approx([0, 0, L], abs=1e-9)
    assert out["markers"][3] == pytest.approx(
        [30 * math.sin(theta / 2) + L * math.sin(theta), 0.0,
         L + 30 * math.cos(theta / 2) + L * math.cos(theta)], abs=1e-9)
    assert out["tendon_lengths"] == {"module2": [10.0, 40.0, 40.0]}
    cpm = 4704 / (math.pi * 20)
    assert out["motor_counts"] == pytest.approx({"motor1": 10 * cpm, "motor2": 10 * cpm,
                                                 "motor3": -20 * cpm})


def test_table_and_inverse(capsys):
    assert main(["manipulator", "--config", "000", "--k", "3"]) == 0
    assert "marker" in capsys.readouterr().out
    # Beyond reach: the nearest point is printed and the status says it was not reached.
    assert main(["manipulator", "--target", "0", "0", "2000", "--json"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert out["reachable"] is False and out["config"] == "111"


@pytest.mark.parametrize(
    "args, message",
    [
        (["--config", "121"], "configuration = '121' is invalid"),
        (["--config", "101", "--k", "16"], "--k = 16.0 is invalid: must be in [-30, 15] mm"),
        (["--config", "101", "--d", "-1"], "tendon_radius = -1"),
        (["--config", "101", "--modules", "0"], "modules = 0 is invalid"),
    ],
)
def test_bad_input_exits_2_without_traceback(tmp_path, args, message):
    result = run_cli(*args, "--json", cwd=tmp_path)
    assert result.returncode == 2
    assert message in result.stderr and "Traceback" not in result.stderr
