"""Bad input on the command line: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""

import json
import signal
import time

import pytest

from bad_input_helpers import run_cli, assert_one_line_error, driven_cell
from kresling import Design
from kresling.solvers import (solve_displacement_control)


def _default_sigint():  # runs in a child before exec: Python installs its handler again
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_subnormal_bad_value_on_the_command_line(capsys):
    status, _, err = run_cli(capsys, "design", "--n", "10", "--lam", "0.8", "--Lc=-1e-310")
    assert_one_line_error(status, err, "design", "Lc = -1e-310 is invalid")


# 4. Lc = 0: snap forces of 4.9e13 N (a parabola through a -3.9e14 N sample at the flat
# state) and bending errors that did not say why.
def test_snap_through_at_lc_zero_names_lc(capsys):
    from kresling.analyses import snap_through
    with pytest.raises(ValueError, match=r"^Lc = 0 is invalid: must be > 0 for the snap-through"):
        snap_through(Design(4, 0.6, 0.0))
    status, out, err = run_cli(capsys, "snap", "--n", "4", "--lam", "0.6", "--Lc", "0")
    assert_one_line_error(status, err, "snap", "Lc = 0 is invalid")
    assert out == ""


@pytest.mark.parametrize("extra", [[], ["--deflection-rad", "0.001"]])
def test_bend_at_lc_zero_names_lc(capsys, extra):
    status, _, err = run_cli(capsys, "bend", "--n", "10", "--lam", "0.8", "--Lc", "0", *extra)
    assert_one_line_error(status, err, "bend", "Lc = 0 is invalid: must be > 0 for the bending "
                                               "test in the contracted state")


# 5. kresling manipulator --config 111 crashed printing a table with no rows.
def test_manipulator_with_every_module_rigid(capsys):
    status, out, err = run_cli(capsys, "manipulator", "--config", "111")
    assert status == 0 and err == ""
    assert "every module is extended" in out
    status, out, _ = run_cli(capsys, "manipulator", "--config", "111", "--json")
    assert status == 0 and json.loads(out)["config"] == "111"


# 6. Large integers: TypeErrors from numpy and from pybind11's int conversion.
def test_large_integers_are_value_errors(capsys):
    with pytest.raises(ValueError, match=r"^n = 100000000000000000000 is invalid: must be an "
                                         r"integer >= 3 and <= 2147483647"):
        Design(10**20, 0.8, 20)
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^steps = 2147483648 is invalid"):
        solve_displacement_control(model, prescribed, 2**31)
    with pytest.raises(ValueError, match=r"^steps = 100001 is invalid: must be an integer in "
                                         r"\[1, 100000\]"):
        solve_displacement_control(model, prescribed, 100001)
    with pytest.raises(ValueError, match=r"^max_iterations = 2147483648 is invalid"):
        solve_displacement_control(model, prescribed, 2, max_iterations=2**31)
    status, _, err = run_cli(capsys, "design", "--n", str(10**20), "--lam", "0.8", "--Lc", "1")
    assert_one_line_error(status, err, "design", "n = 100000000000000000000 is invalid")
    status, _, err = run_cli(capsys, "snap", "--n", "4", "--lam", "0.8", "--Lc", "1", "--steps",
                             str(10**20))
    assert_one_line_error(status, err, "snap", "steps = 100000000000000000000 is invalid")


# 7. A record or marker file with a line over 128 KiB raised _csv.Error.
def test_csv_line_over_csvs_limit_names_file_and_line(tmp_path, capsys):
    from kresling.fits.records import read_machine_record
    from kresling.manipulator.markers import read_markers
    record = tmp_path / "record.csv"
    record.write_text("displacement (mm),force (N)\n0,0\n1," + "2" * 200_000 + "\n2,4\n")
    with pytest.raises(ValueError, match=r"record.csv, line 3: not a CSV line \(field larger"):
        read_machine_record(record)
    assert len(read_machine_record(record, on_invalid="skip")) == 2
    markers = tmp_path / "markers.csv"
    markers.write_text("config,step,marker,x,y\n101,0,1,0," + "1" * 200_000 + "\n")
    with pytest.raises(ValueError, match=r"markers.csv, line 2: not a CSV line"):
        read_markers(markers)
    status, _, err = run_cli(capsys, "fit", "bending", str(record), "--state", "extended",
                             "--module-length", "60")
    assert_one_line_error(status, err, "fit", "line 3")


def test_truncated_manifest_names_the_file(tmp_path, capsys):
    from kresling.sweeps import design_grid, sweep
    out = tmp_path / "sweep"
    sweep(design_grid((4,), 2), ["psi_ratio"], out=out, progress=False, workers=1)
    manifest = out / "manifest.json"
    manifest.write_bytes(manifest.read_bytes()[:40])
    with pytest.raises(ValueError, match=r"manifest.json is damaged \(not JSON"):
        sweep(design_grid((4,), 2), ["psi_ratio"], out=out, progress=False, workers=1)
    status, _, err = run_cli(capsys, "sweep", "--n", "4", "--grid", "2", "--metrics",
                             "psi_ratio", "--out", str(out), "--no-progress")
    assert_one_line_error(status, err, "sweep", "manifest.json is damaged")


def test_ctrl_c_stops_a_long_command(tmp_path):
    import subprocess
    import sys
    # About 13 s of C++ (100000 increments of a 60-gon); it ignored Ctrl-C to the end. The
    # child gets the default disposition of SIGINT (a user's terminal), not this run's.
    process = subprocess.Popen([sys.executable, "-m", "kresling", "snap", "--n", "60", "--lam",
                                "0.8", "--Lc", "30", "--steps", "100000"], cwd=tmp_path,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               preexec_fn=_default_sigint)
    time.sleep(3.0)  # past the imports, inside the C++ drive
    process.send_signal(signal.SIGINT)
    signalled = time.perf_counter()
    try:
        _, err = process.communicate(timeout=30)
    finally:
        process.kill()
    assert process.returncode == 130, err
    assert err.strip() == "kresling snap: interrupted"
    assert time.perf_counter() - signalled < 5.0
