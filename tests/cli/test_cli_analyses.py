"""``kresling bend`` and ``kresling snap``: JSON and tables, protocols, plots and bad input."""

import json

import pytest

from kresling.cli import main
from cli_helpers import run_kresling



def test_bend_json_is_table_3(tmp_path):
    result = run_kresling("bend", "--n", "8", "--lam", "0.8", "--Lc", "30", "--R", "30", "--json",
                     cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    values = json.loads(result.stdout)
    # MERLIN2 reference run (5 mm protocol): 2.797835 / 0.478514 / 5.846924.
    assert values["K_ext"] == pytest.approx(2.797835, abs=1e-6)
    assert values["K_con"] == pytest.approx(0.478514, abs=1e-6)
    assert values["ratio"] == pytest.approx(5.846924, abs=1e-6)
    assert values["snap_force"] == pytest.approx(4.34, abs=0.005) and values["bistable"] is True


def test_bend_gradient_json_has_every_quantity_by_every_variable(capsys):
    assert main(["bend", "--n", "8", "--lam", "0.8", "--Lc", "15", "--deflection-rad", "0.001",
                 "--gradient", "--json"]) == 0
    values = json.loads(capsys.readouterr().out)
    gradient = values["gradient"]
    assert list(gradient) == ["kb_ratio", "kb_extended", "kb_contracted", "snap_force",
                              "energy_barrier"]
    for row in gradient.values():
        assert list(row) == ["lam", "Lc", "R", "thickness", "kf"]
    # K_B is proportional to kf (every stiffness is a ratio to it); the ratio is not.
    assert gradient["kb_extended"]["kf"] == pytest.approx(values["K_ext"] / 0.047, rel=1e-6)
    assert abs(gradient["kb_ratio"]["kf"]) < 1e-9 * values["ratio"] / 0.047
    assert main(["bend", "--n", "8", "--lam", "0.8", "--Lc", "15", "--deflection-rad", "0.001",
                 "--gradient"]) == 0
    assert "d/dthickness" in capsys.readouterr().out


def test_snap_json(tmp_path):
    result = run_kresling("snap", "--n", "4", "--lam", "0.7", "--Lc", "30", "--json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    values = json.loads(result.stdout)
    assert values["snap_force"] == pytest.approx(1.536, abs=1e-3)
    assert values["bistable"] is False and values["energy_barrier"] is None


def test_small_deflection_protocol_and_plot(tmp_path, capsys):
    figure = tmp_path / "bend.png"
    assert main(["bend", "--n", "10", "--lam", "0.9", "--Lc", "15", "--deflection-rad", "0.001",
                 "--json", "--plot", str(figure)]) == 0
    values = json.loads(capsys.readouterr().out)
    assert values["protocol"] == "0.001 rad"
    assert values["K_ext"] == pytest.approx(3.28345, rel=1e-4)      # linearised: 3.283415
    assert figure.stat().st_size > 10_000


def test_tables_and_snap_plot(tmp_path, capsys):
    assert main(["bend", "--n", "4", "--lam", "0.7", "--Lc", "30"]) == 0
    out = capsys.readouterr().out
    assert "K_ext" in out and "3.6045" in out and "snap_force" in out
    figure = tmp_path / "snap.png"
    assert main(["snap", "--n", "10", "--lam", "0.7", "--Lc", "60", "--plot", str(figure)]) == 0
    assert "no local maximum" in capsys.readouterr().out and figure.stat().st_size > 10_000


@pytest.mark.parametrize("args, message", [
    (["bend", "--n", "5", "--lam", "0.9", "--Lc", "15"], "n = 5 is invalid: must be even for the bending test"),
    (["bend", "--n", "6", "--lam", "0.9", "--Lc", "15", "--deflection-rad", "0"], "--deflection-rad = 0.0 is invalid"),
    (["bend", "--n", "6", "--lam", "0.9", "--Lc", "15", "--deflection-rad", "1.5"], "--deflection-rad = 1.5 is invalid"),
    (["bend", "--n", "6", "--lam", "1.3", "--Lc", "15"], "lam = 1.3 is invalid"),
    (["snap", "--n", "6", "--lam", "0.9", "--Lc", "15", "--steps", "0"], "steps = 0 is invalid"),
    (["snap", "--n", "6", "--lam", "0.9", "--Lc", "-1"], "Lc = -1 is invalid"),
])
def test_bad_input_is_one_line_on_stderr(tmp_path, args, message):
    result = run_kresling(*args, cwd=tmp_path)
    assert result.returncode == 2
    assert message in result.stderr and "Traceback" not in result.stderr
    assert result.stdout == ""
