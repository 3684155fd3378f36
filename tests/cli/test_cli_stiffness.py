"""``--kf`` on the bending and snap-through commands: every element's stiffness scales with
the crease stiffness (the thesis's ratios), so forces and K_B scale with it exactly while
the K_B ratio does not move (to the Newton tolerance, ~1e-9 relative)."""

from __future__ import annotations


import pytest

from cli_helpers import run_kresling, run_kresling_json

DESIGN = ("--n", "4", "--lam", "0.7", "--Lc", "30")


def run_json(tmp_path, *args):
    return run_kresling_json(*args, cwd=tmp_path)


def test_bend_scales_with_kf(tmp_path):
    base = run_json(tmp_path, "bend", *DESIGN, "--deflection-rad", "0.001")
    double = run_json(tmp_path, "bend", *DESIGN, "--deflection-rad", "0.001", "--kf", "0.094")
    assert base["kf"] == 0.047 and double["kf"] == 0.094
    assert double["K_ext"] == pytest.approx(2 * base["K_ext"], rel=1e-7)
    assert double["K_con"] == pytest.approx(2 * base["K_con"], rel=1e-7)
    assert double["ratio"] == pytest.approx(base["ratio"], rel=1e-7)
    assert double["snap_force"] == pytest.approx(2 * base["snap_force"], rel=1e-7)


def test_snap_scales_with_kf(tmp_path):
    base = run_json(tmp_path, "snap", *DESIGN)
    half = run_json(tmp_path, "snap", *DESIGN, "--kf", "0.0235")
    assert half["snap_force"] == pytest.approx(base["snap_force"] / 2, rel=1e-7)
    assert half["snap_displacement"] == pytest.approx(base["snap_displacement"], rel=1e-7)


@pytest.mark.parametrize("value", ["0", "-1", "nan", "inf"])
def test_bad_kf_is_named(tmp_path, value):
    result = run_kresling("snap", *DESIGN, f"--kf={value}", cwd=tmp_path)
    assert result.returncode == 2
    assert "--kf" in result.stderr and "Traceback" not in result.stderr
