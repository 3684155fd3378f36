"""Marker files, their comparison with the model (figures 4.13-4.15), Table 5, the shipped
synthetic data set, and motor counts."""

import math

import numpy as np
import pytest

from kresling import data
from kresling.manipulator import (Manipulator, MarkerPerturbation, TendonDrive, compare_markers,
                                  joint_length_table, read_markers, synthetic_markers,
                                  write_markers)
from kresling.manipulator.synthetic import SHIPPED_FILE


def test_model_data_compare_with_zero_error(tmp_path):
    arm = Manipulator()
    exact = synthetic_markers(arm, MarkerPerturbation.none())
    comparison = compare_markers(arm, read_markers(write_markers(tmp_path / "m.csv", exact, 9)))
    assert comparison.error.max() < 1e-8  # written with 9 decimals
    tip = comparison.marker == 4
    # The normalising length is the sum of predicted module lengths: 3 L for (111).
    rows = tip & (comparison.config == "111")
    np.testing.assert_allclose(comparison.length_from_base[rows], 3 * arm.extended_length)
    assert np.isnan(comparison.normalized_error[comparison.marker == 1]).all()


def test_known_module_offsets_are_recovered():
    # Length offsets only: at every step each measured module length is the predicted one
    # (30 mm, the protocol's chord) plus that module's offset (the tendons' mean moves by it).
    arm = Manipulator()
    perturbation = MarkerPerturbation(module_length_sd=1.0, bend_efficiency=1.0,
                                      bend_efficiency_sd=0.0, noise_sd=0.0, seed=1)
    measured = synthetic_markers(arm, perturbation)
    offsets = np.random.default_rng(1).normal(0.0, 1.0, 3)  # the first configuration's (000)
    _, lengths = measured.module_lengths("000")
    np.testing.assert_allclose(lengths, np.tile(30.0 + offsets, (11, 1)), atol=1e-9)


def test_shipped_synthetic_file_is_what_the_generator_makes():
    shipped = read_markers(data.path(SHIPPED_FILE))
    made = synthetic_markers()
    assert shipped.config.tolist() == made.config.tolist()
    np.testing.assert_allclose(shipped.xy, made.xy, atol=5.1e-5)  # written with 4 decimals
    summary = compare_markers(Manipulator(), shipped).summary()
    assert set(summary) == {"000", "001", "010", "011", "100", "101", "110", "111"}
    assert all(0.1 < s["mean_error_mm"] < 5 for s in summary.values())


def test_error_grid_for_the_figures():
    comparison = compare_markers(Manipulator(), read_markers(data.path(SHIPPED_FILE)))
    steps, errors = comparison.grid("100")
    assert steps.tolist() == list(range(11)) and errors.shape == (11, 4)
    assert np.all(errors[:, 0] == 0.0)  # the base marker is the origin of the measurements
    _, normalized = comparison.grid("100", normalized=True)
    assert np.isnan(normalized[:, 0]).all() and np.isfinite(normalized[:, 1:]).all()


def test_table5_comparison():
    rows = joint_length_table(Manipulator())
    assert len(rows) == 24
    by_key = {(r["config"], r["joint"]): r for r in rows}
    # Predicted module lengths are constant under the protocol: 30 mm or 2 Le.
    assert by_key["101", 2]["predicted_min_mm"] == pytest.approx(30.0, abs=1e-9)
    assert by_key["101", 2]["predicted_max_mm"] == pytest.approx(30.0, abs=1e-9)
    assert by_key["101", 1]["predicted_min_mm"] == pytest.approx(111.6389336, abs=1e-6)
    # (000) joint 3 measured [29.4, 31.3] contains 30; (101) joint 2 [28.3, 28.9] does not.
    assert by_key["000", 3]["inside"] and not by_key["101", 2]["inside"]
    assert by_key["101", 2]["outside_by_mm"] == pytest.approx(1.1, abs=1e-9)


def header_and_rows(text):
    return "config,step,marker,x,y\n" + text


@pytest.mark.parametrize(
    "content, message",
    [
        ("config,step,marker,x\n101,1,1,0\n", r"m.csv: missing column\(s\) 'y'"),
        (header_and_rows("101,1,2,0,0\n101,1,3,abc,0\n"), r"m.csv, line 3, column 'x': 'abc' is not a number"),
        (header_and_rows("121,1,2,0,0\n"), r"line 2, column 'config': '121' is not a configuration of 3"),
        (header_and_rows("1010,1,2,0,0\n"), r"line 2, column 'config'"),
        (header_and_rows("101,1,5,0,0\n"), r"line 2, column 'marker': '5' is invalid"),
        (header_and_rows("101,-1,2,0,0\n"), r"line 2, column 'step'"),
        (header_and_rows("101,1,2,0,nan\n"), r"line 2, column 'y': 'nan' is not a finite number"),
        (header_and_rows("101,1,2,0,\n"), r"line 2, column 'y': '' is not a number"),
        (header_and_rows("101,1,2,0,0\n101,1,2,1,1\n"), r"line 3, column 'marker': repeats .* of line 2"),
    ],
)
def test_bad_marker_files(tmp_path, content, message):
    path = tmp_path / "m.csv"
    path.write_text(content)
    with pytest.raises(ValueError, match=message):
        read_markers(path)


def test_motor_counts_follow_appendix_e():
    drive, arm = TendonDrive(), Manipulator()
    assert drive.counts_per_mm == pytest.approx(4704 / (math.pi * 20), rel=1e-15)
    cpm = 4 * 1176 / (math.pi * 0.02)  # Appendix E's CLconv, counts per metre
    # (0 0 0) at L1 = 10 per module: tendon 1 shortened by 3 x 20 mm.
    counts = drive.motor_counts(arm, "000", [10.0, 40.0, 40.0])
    np.testing.assert_allclose(counts, [-(30 - 40) * 3 * 0.001 * cpm, -(30 - 40) * 3 * 0.001 * cpm,
                                        -(30 - 10) * 3 * 0.001 * cpm], rtol=1e-12)
    assert drive.snap_counts(arm) == pytest.approx((55.8194667799374 - 15) * 2 * 0.001 * cpm, rel=1e-10)
    assert np.all(drive.motor_counts(arm, "111", None) == 0)
    custom = TendonDrive(pulley_diameter=10.0, motor_of_tendon=(1, 2, 3), sign=1)
    np.testing.assert_allclose(custom.motor_counts(arm, "011", [20.0, 30.0, 35.0]),
                               np.array([10.0, 0.0, -5.0]) * 4704 / (math.pi * 10))
    with pytest.raises(ValueError, match="motor_of_tendon"):
        TendonDrive(motor_of_tendon=(1, 1, 2))
