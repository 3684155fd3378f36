"""``[[actuation]]`` with ``method = "dynamic"``: creases' rest angles driven in time (a
step, a ramp, a harmonic, a chirp), against a hinge's closed form, and their refusals."""

import copy
import re

import numpy as np
import pytest
from scipy.optimize import brentq

from kresling.simulate import load_problem, simulate
from kresling.solvers.dynamics import time_factor
from small_models import CREASED_SQUARE

# CREASED_SQUARE's free corner turns about the crease 0-2: a rotational spring of
# k = 0.05 N*mm/rad per mm * 20 sqrt(2) mm and a point mass of 1e-6 t at r = 20 / sqrt(2) mm.
K_HINGE = 0.05 * 20.0 * np.sqrt(2.0)   # [N*mm/rad]
INERTIA = 1e-6 * 200.0                  # m r^2 [t*mm^2]
OMEGA = np.sqrt(K_HINGE / INERTIA)      # [rad/s], 84 rad/s (13.4 Hz)
DT = 1e-4


def problem(actuation, duration=0.15, **dynamics):
    p = copy.deepcopy(CREASED_SQUARE)
    p["actuation"] = actuation
    p["dynamics"] = {"scheme": "newmark", "time_step": DT, "duration": duration, **dynamics}
    p["analysis"] = {"method": "dynamic", "tolerance": 1e-12}
    return p


def turn(run):
    """The free corner's turn about the crease at each step [rad] (+ towards +z)."""
    p = np.array([0.0, 20.0, 0.0]) + run.path.displacement[:, 9:12]
    d = p - np.array([10.0, 10.0, 0.0])
    return np.arctan2(d[:, 2], d @ (np.array([-1.0, 1.0, 0.0]) / np.sqrt(2.0)))


def folded_turn(angle_deg):
    """The turn a static fold of the crease to ``angle_deg`` reaches: the reference the
    motion oscillates about (its sign is the FOLD convention's, found by the fold)."""
    p = copy.deepcopy(CREASED_SQUARE)
    p["actuation"] = [{"edges": [[0, 2]], "fold_angle_deg": angle_deg}]
    p["analysis"] = {"method": "fold", "steps": 4, "tolerance": 1e-12}
    return turn(simulate(p))[-1]


def test_a_rest_angle_step_oscillates_as_the_hinge_s_closed_form():
    run = simulate(problem([{"edges": [[0, 2]], "fold_angle_deg": 1.0, "time": "step"}]))
    assert run.completed
    target = folded_turn(1.0)
    assert abs(target) == pytest.approx(np.radians(1.0), rel=1e-3)
    # A step of the rest angle by delta is a moment step k delta: the turn is
    # delta (1 - cos w_h t), w_h the average acceleration scheme's frequency
    # (tan(w_h dt / 2) = w dt / 2). What the one-DOF hinge leaves out, the bars' stretch
    # (hinge force / (50 N/mm) ~ 2e-5 mm against a 0.25 mm swing), stays below 1e-3 of it.
    w_h = 2.0 / DT * np.arctan(OMEGA * DT / 2.0)
    expected = target * (1.0 - np.cos(w_h * run.history.time))
    np.testing.assert_allclose(turn(run), expected, atol=1e-3 * abs(target))
    # The rest angle is set at t = 0: the actuation does no work after, and the balance
    # holds from the start's stored energy 1/2 k delta^2.
    h = run.history
    assert h.strain[0] == pytest.approx(0.5 * K_HINGE * target ** 2, rel=1e-3)
    np.testing.assert_array_equal(h.actuation_work, 0.0)


def test_a_ramped_rest_angle_does_the_work_the_energy_balance_asks():
    ramp = 0.05
    run = simulate(problem([{"edges": [[0, 2]], "fold_angle_deg": -2.0, "time": "ramp",
                             "ramp_time": ramp}]))
    h = run.history
    target = folded_turn(-2.0)
    # A ramp of the rest angle to delta over T: for the one-DOF hinge the turn is
    # delta (t / T - sin(w t) / (w T)) during it (a moment ramp).
    during = h.time <= ramp
    t = h.time[during]
    w_h = 2.0 / DT * np.arctan(OMEGA * DT / 2.0)
    np.testing.assert_allclose(turn(run)[during], target * (t / ramp - np.sin(w_h * t) /
                                                            (w_h * ramp)),
                               atol=2e-3 * abs(target))
    # The actuation's work balances the energies (to the scheme's O((w dt)^2) on a
    # geometrically nonlinear hinge: (84 * 1e-4)^2 ~ 7e-5 of the energies).
    balance = h.kinetic + h.strain + h.dissipated - h.work - h.actuation_work
    assert np.ptp(balance) < 1e-4 * h.actuation_work.max()
    # The start is at rest and unstrained: what the sheet holds at the end, the actuation
    # put in.
    assert h.strain[0] < 1e-3 * h.actuation_work[-1]
    assert h.kinetic[-1] + h.strain[-1] == pytest.approx(h.actuation_work[-1], rel=1e-3)
    columns = run.history_columns()
    np.testing.assert_allclose(columns["actuation_0_factor"], np.minimum(h.time / ramp, 1.0),
                               rtol=1e-12)


def test_a_chirp_s_frequency_goes_linearly_from_f0_to_f1_then_stays():
    amplitude, f0, f1, sweep = 2.0, 5.0, 45.0, 0.4
    chirp = {"chirp": (amplitude, f0, f1, sweep)}

    def factor(t):
        return float(time_factor(chirp, t)[0])

    grid = np.linspace(1e-6, 0.6, 60001)
    values = time_factor(chirp, grid)
    assert np.abs(values).max() == pytest.approx(amplitude, rel=1e-5)
    crossings = [brentq(factor, a, b, xtol=1e-15)
                 for a, b, fa, fb in zip(grid, grid[1:], values, values[1:]) if fa * fb < 0]
    # The phase advances by pi between zero crossings: the mean frequency over that half
    # period, 1 / (2 dt), is the linear frequency at its midpoint (exact for a linear
    # chirp, to the crossings' 1e-15 s).
    crossings = np.array(crossings)
    middle = 0.5 * (crossings[1:] + crossings[:-1])
    measured = 1.0 / (2.0 * np.diff(crossings))
    swept = middle < sweep - 0.02
    np.testing.assert_allclose(measured[swept], f0 + (f1 - f0) * middle[swept] / sweep,
                               rtol=1e-8)
    after = crossings[:-1] > sweep
    np.testing.assert_allclose(measured[after[:len(measured)]], f1, rtol=1e-8)
    # Continuous through the sweep's end: over +-1 ns it changes by at most its steepest
    # slope, 2 pi f1 amplitude, times 2 ns (a jump of the phase would be ~ amplitude).
    jump = abs(factor(sweep + 1e-9) - factor(sweep - 1e-9))
    assert jump <= 1.001 * 2e-9 * 2 * np.pi * f1 * amplitude


def test_a_chirped_crease_swings_its_rest_angle_about_the_start_in_degrees():
    chirp = [1.5, 10.0, 30.0, 0.1]
    run = simulate(problem([{"edges": [[0, 2]], "time": {"chirp": chirp}}], duration=0.093))
    assert run.completed
    h = run.history
    expected = time_factor({"chirp": chirp}, h.time)
    assert abs(expected[-1]) > 1.0   # the end well off a zero of the sine
    np.testing.assert_allclose(run.history_columns()["actuation_0_factor"], expected,
                               rtol=0, atol=1e-14)
    # The rest angle at the end: the start's (flat, pi) moved by the factor's degrees of
    # fold angle, the way a fold of +1 deg moves it.
    one_degree = simulate(problem([{"edges": [[0, 2]], "fold_angle_deg": 1.0}],
                                  duration=1e-3)).model_at(-1).hinge_rest_angle[0] - np.pi
    assert run.model_at(-1).hinge_rest_angle[0] - np.pi == pytest.approx(
        expected[-1] * one_degree, rel=1e-12)
    balance = h.kinetic + h.strain + h.dissipated - h.work - h.actuation_work
    assert np.ptp(balance) < 1e-4 * np.abs(h.actuation_work).max()


@pytest.mark.parametrize("change, message", [
    ({"time": {"chirp": [1.0, 0.0, 5.0, 1.0]}}, r"\[actuation\] key 'time'.*chirp's frequencies"),
    ({"time": {"chirp": [1.0, 5.0, 5.0, -1.0]}}, r"'time'.*sweep_s > 0"),
    ({"time": {"chirp": [1.0, 5.0]}}, r"'time'.*chirp = \[amplitude, f0_hz, f1_hz, sweep_s\]"),
    ({"time": {"harmonic": [1.0, 5.0]}, "fold_angle_deg": 3.0},
     r"'fold_angle_deg' applies only to a time that drives to a target"),
    ({"stage": 2}, r"actuation\[0\] key 'stage' = 2 applies only with \[analysis\] method = 'fold'"),
    ({"time": {"harmonic": [200.0, 5.0]}}, r"actuation\[0\] key 'time'.*beyond a flat fold"),
])
def test_bad_actuation_in_time_is_refused_naming_the_key(change, message):
    entry = {"edges": [[0, 2]], "fold_angle_deg": 5.0, **change}
    if isinstance(entry.get("time"), dict) and "fold_angle_deg" not in change:
        entry.pop("fold_angle_deg")
    with pytest.raises(ValueError, match=message):
        simulate(problem([entry]))


def test_actuation_times_and_schemes_are_refused_where_they_do_not_apply():
    fold = copy.deepcopy(CREASED_SQUARE)
    fold["actuation"] = [{"edges": [[0, 2]], "fold_angle_deg": 5.0, "time": "step"}]
    fold["analysis"] = {"method": "fold"}
    with pytest.raises(ValueError, match=r"actuation\[0\] key 'time' applies only with "
                                         r"\[analysis\] method = 'dynamic'"):
        load_problem(fold)
    explicit = problem([{"edges": [[0, 2]], "fold_angle_deg": 5.0}], scheme="explicit",
                       time_step=1e-6)
    with pytest.raises(ValueError, match=r"\[\[actuation\]\] drives creases only with "
                                         r"\[dynamics\] scheme = 'newmark' or 'hht'"):
        load_problem(explicit)
    forces = copy.deepcopy(fold)
    forces["actuation"][0].pop("time")
    forces["analysis"] = {"method": "force_control", "steps": 4}
    with pytest.raises(ValueError, match=r"method = 'fold' or 'dynamic'"):
        load_problem(forces)


def test_a_driven_stage_starts_where_a_fold_left_the_crease_and_hands_on_its_rest_angle():
    from kresling.model.fold_angles import fold_angles_deg, hinge_fold_signs, rest_angles_for

    p = copy.deepcopy(CREASED_SQUARE)
    p["stage"] = [
        {"name": "fold", "method": "fold", "steps": 5,
         "actuation": [{"edges": [[0, 2]], "fold_angle_deg": 45.0}]},
        {"name": "drive", "method": "dynamic", "tolerance": 1e-12,
         "dynamics": {"scheme": "newmark", "time_step": 1e-4, "duration": 0.05},
         "actuation": [{"edges": [[0, 2]], "fold_angle_deg": 60.0, "time": "ramp",
                        "ramp_time": 0.02}]},
        {"name": "modes", "method": "modes", "modes": 1}]
    run = simulate(p)
    assert run.completed
    drive, modes = run.runs[1][1], run.runs[2][1]
    sign = hinge_fold_signs(drive.pattern_model)[0]
    # The drive's rest angle starts at the fold's 45 deg (the ramp's factor 0) and the
    # motion from rest there.
    assert drive.model.hinge_rest_angle[0] == pytest.approx(rest_angles_for(45.0, sign),
                                                            abs=1e-12)
    first = fold_angles_deg(drive.pattern_model, drive.path.displacement[0])[0]
    assert first == pytest.approx(45.0, abs=1e-3)
    # After the ramp the crease rests at 60 deg, and the next stage starts there.
    target = rest_angles_for(60.0, sign)
    assert drive.model_at(-1).hinge_rest_angle[0] == pytest.approx(target, abs=1e-12)
    assert modes.model.hinge_rest_angle[0] == pytest.approx(target, abs=1e-12)


def test_kresling_simulate_refuses_a_bad_chirp_in_one_line_naming_the_file_and_key(tmp_path):
    from pathlib import Path

    from cli_helpers import run_kresling

    example = Path(__file__).resolve().parents[2] / "examples" / "fold_then_chirp"
    bad = tmp_path / "bad.toml"
    bad.write_text((example / "problem.toml").read_text().replace(
        "chirp = [2.0, 5.0, 25.0, 0.6]", "chirp = [2.0, 5.0, -25.0, 0.6]"))
    result = run_kresling("simulate", str(bad), "--out", str(tmp_path / "out"), cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert re.search(r"bad.toml.*\[actuation\] key 'time' = .* the chirp's frequencies",
                     result.stderr)
