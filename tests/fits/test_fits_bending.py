"""Bending stiffness (eqns 20-23): conversions, the two slopes, the contracted-state offset,
recovery from synthetic trials, and bad trial files."""

import math

import numpy as np
import pytest

from kresling.fits.bending import (BendingTrial, fit_bending, fit_bending_trial, mean_curve,
                                   moment_and_angle, slope_through_origin)
from kresling.fits.bending_files import fit_bending_files, read_bending_trial
from kresling.fits.records import RecordError
from kresling.fits.recovery import bending_recovery
from kresling.fits.synthetic import synthetic_bending_trials


def test_eqns_20_21_by_hand():
    angle, moment = moment_and_angle([0.0, 60.0], [2.0, 2.0], 60.0)
    assert angle == pytest.approx([0.0, math.pi / 4], abs=1e-15)  # y = Lm: 45 degrees
    assert moment == pytest.approx([0.12, 0.12], abs=1e-15)      # 2 N x 60 mm = 0.12 N*m


def test_slope_through_origin_is_matlab_backslash():
    x, y = np.array([1.0, 2.0, 3.0]), np.array([2.0, 4.5, 5.5])
    assert slope_through_origin(x, y) == pytest.approx(np.linalg.lstsq(x[:, None], y,
                                                                       rcond=None)[0][0])


def line_trial(state, K=2.0, intercept=0.0, Lm=60.0):
    y = np.linspace(0.0, 5.0, 51)
    moment = K * np.arctan(y / Lm) + intercept
    return BendingTrial(state, Lm, y, moment * 1e3 / Lm)


def test_intercept_and_origin_fits_on_exact_lines():
    exact = fit_bending_trial(line_trial("extended"), method="origin")
    assert exact.K == pytest.approx(2.0, rel=1e-12) and exact.points == 51
    shifted = fit_bending_trial(line_trial("contracted", intercept=0.01))
    assert (shifted.K, shifted.intercept) == pytest.approx((2.0, 0.01), rel=1e-10)
    assert shifted.offset == 0.03 and shifted.points < 51   # the contracted default


def test_offset_leaves_too_few_points():
    with pytest.raises(ValueError, match="past the offset") as error:
        fit_bending_trial(line_trial("contracted"), offset=0.5)
    assert "contracted trial" in str(error.value)


# Tolerance 2 %, the required accuracy; the noise model's actual errors are ~0.2 %.
@pytest.mark.parametrize("case", [
    dict(K=3.50, state="extended", module_length=110.6),                      # no offset
    dict(K=0.80, state="contracted", module_length=60.0),                      # past 0.03
    dict(K=0.80, state="contracted", module_length=60.0, rise=False, offset=0.0),
    dict(K=0.29, state="contracted", module_length=30.0, method="origin", rise=False),
])
def test_K_recovered_from_synthetic_trials_within_2_percent(case):
    errors = bending_recovery(seed=11, **case)
    assert np.abs(errors).max() < 0.02


def test_the_residual_rise_biases_fits_that_ignore_the_offset():
    # Why the thesis fits past 0.03 rad: without the offset the rise inflates K_B.
    errors = bending_recovery(0.80, "contracted", 60.0, seed=11, offset=0.0)
    assert errors.min() > 0.05
    through_origin = bending_recovery(0.80, "contracted", 60.0, seed=11, method="origin")
    assert through_origin.min() > 0.2


def test_ratio_and_its_first_order_uncertainty():
    rng = np.random.default_rng(5)
    trials = (synthetic_bending_trials(3.5, 1, 110.6, rng, trial_cv=0.08)[0]
              + synthetic_bending_trials(0.8, 0, 60.0, rng, trial_cv=0.08)[0])
    result = fit_bending(trials)
    K1, K0 = result.summaries["extended"], result.summaries["contracted"]
    assert result.ratio.value == pytest.approx(K1.mean / K0.mean, rel=1e-12)
    expected_sd = result.ratio.value * math.hypot(K1.sd / K1.mean, K0.sd / K0.mean)
    assert result.ratio.sd == pytest.approx(expected_sd, rel=1e-12)
    assert result.ratio.se == pytest.approx(expected_sd / math.sqrt(3), rel=1e-12)
    assert set(result.as_dict()["K"]) == {"extended", "contracted"}


def test_mean_curve_of_identical_trials_has_no_spread():
    fits = [fit_bending_trial(line_trial("extended")) for _ in range(3)]
    angle, mean, sd = mean_curve(fits, points=20)
    assert angle.shape == mean.shape == sd.shape == (20,)
    assert np.allclose(sd, 0.0) and mean == pytest.approx(2.0 * angle, abs=1e-12)


def write_trial(tmp_path, header_lines, rows="0,0,0\n1,0.1,0.2\n2,0.2,0.4\n", name="t.csv"):
    path = tmp_path / name
    path.write_text("".join(f"# {line}\n" for line in header_lines)
                    + "time_s,displacement_mm,force_N\n" + rows)
    return path


def test_trial_metadata_and_overrides(tmp_path):
    path = write_trial(tmp_path, ["state: 0", "module_length: 6 cm"])
    trial, skipped = read_bending_trial(path)
    assert (trial.state, trial.module_length, skipped) == ("contracted", 60.0, [])
    trial, _ = read_bending_trial(path, state="extended", module_length=110.0)
    assert (trial.state, trial.module_length) == ("extended", 110.0)


@pytest.mark.parametrize("lines, line, words", [
    (["module_length: 60 mm"], None, "no '# state"),
    (["state: 1"], None, "no '# module_length"),
    (["state: bent", "module_length: 60 mm"], 1, "state = 'bent' is invalid"),
    (["state: 1", "module_length: 0 mm"], 2, "must be > 0"),
    (["state: 1", "module_length: -60 mm"], 2, "must be > 0"),
    (["state: 1", "module_length: 60 kg"], 2, "not a length unit"),
])
def test_bad_trial_metadata_names_file_and_line(tmp_path, lines, line, words):
    path = write_trial(tmp_path, lines)
    with pytest.raises(RecordError, match=words) as error:
        read_bending_trial(path)
    assert error.value.path == str(path) and error.value.line == line


def test_fit_files_counts_skipped_lines_across_trials(tmp_path):
    rows = "0,0,0\n\n1,1,2\n2,2,4\n3,3,6\n"
    paths = [write_trial(tmp_path, ["state: 1", "module_length: 10 mm"], rows, f"{i}.csv")
             for i in range(2)]
    result = fit_bending_files(paths)
    assert len(result.skipped) == 2 and result.ratio is None
    assert result.as_dict()["ratio"] is None
