"""Crease stiffness (eqns 17-19): known values, an exact physical case, Table 1, and bad
input in a list of runs located by file, line and column."""

import csv
import math

import numpy as np
import pytest

from kresling import data
from kresling.fits.crease import (CreaseRun, end_forces, fit_crease_run, panel_angle,
                                  stiffness_per_length, summarize_crease)
from kresling.fits.crease_files import MARKER_KEYS, fit_crease_file, read_stiffness_table
from kresling.fits.records import RecordError
from kresling.fits.synthetic import CreaseRig, crease_force
from kresling.fits.synthetic_files import write_crease_example


@pytest.mark.parametrize("upper, lower, beta", [
    ((0, 2), (3, 0), math.pi / 2),        # 3-4-5 style right angle
    ((1, 1), (5, 0), math.pi / 4),
    ((-2, 0), (1, 0), math.pi),           # flat
    ((4, 0), (1, 0), 0.0),                # closed: rounding must not give NaN
])
def test_cosine_rule_known_angles(upper, lower, beta):
    assert panel_angle((0, 0), upper, lower) == pytest.approx(beta, abs=1e-12)


def test_cosine_rule_ignores_camera_position_roll_and_scale():
    rng = np.random.default_rng(3)
    points = rng.uniform(0, 100, (3, 2))
    roll = 0.7
    rotation = np.array([[math.cos(roll), -math.sin(roll)], [math.sin(roll), math.cos(roll)]])
    moved = 13.7 * points @ rotation.T + [250.0, -40.0]
    assert panel_angle(*moved) == pytest.approx(panel_angle(*points), abs=1e-12)


def test_eqn_19_by_hand():
    # beta1 = 60 deg puts the load at d = Lp / 2 = 20 mm; a 0.05 N rise over 0.1 rad on a
    # 100 mm crease is 0.05 * 20 / (0.1 * 100) = 0.1 N/rad.
    d = 40.0 * math.cos(math.pi / 3)
    k = stiffness_per_length(0.10, 0.15, math.pi / 3, math.pi / 3 - 0.1, d, 100.0)
    assert k == pytest.approx(0.1, rel=1e-12)


def test_end_forces_of_an_exact_line():
    y = np.linspace(0.0, 5.0, 11)
    assert end_forces(y, 0.02 + 0.004 * y) == pytest.approx((0.02, 0.04), abs=1e-15)


def exact_run(kf=0.047, Lp=32.0, beta1=0.6, W=152.4):
    """A noise-free run of a hinge of stiffness kf (the synthetic generator's physics)."""
    d = Lp * math.cos(beta1)
    y = np.linspace(0.0, 5.0, 501)
    beta2 = math.atan(math.tan(beta1) - 5.0 / d)

    def frame(beta):
        return np.array([[0.0, 0.0], [40 * math.cos(beta), 40 * math.sin(beta)], [40.0, 0.0]])

    return CreaseRun("1", "1", y, crease_force(y, kf, W, d, beta1, 0.01), frame(beta1),
                     frame(beta2), Lp, W)


def test_exact_run_recovers_kf():
    fit = fit_crease_run(exact_run())
    # The only error is the straight line through a slightly curved F(y); its end-to-end
    # difference cancels to second order, so 0.1 % is generous.
    assert fit.k == pytest.approx(0.047, rel=1e-3)
    assert fit.beta1 == pytest.approx(0.6, abs=1e-12)


@pytest.mark.parametrize("change, words", [
    (dict(W=0.0), "W = 0.0 mm is invalid"),
    (dict(Lp=-3.0), "Lp = -3.0 mm is invalid"),
    (dict(displacement=np.zeros(1), force=np.zeros(1)), "a line needs at least 2"),
    (dict(displacement=np.ones(3), force=np.arange(3.0)), "never changes"),
    (dict(markers_first=np.zeros((3, 2))), "coincides with the vertex"),
    (dict(markers_last=np.zeros((2, 2))), "must be 3 finite"),
])
def test_fit_crease_run_rejects_bad_runs(change, words):
    run = exact_run()
    with pytest.raises(ValueError, match=words):
        fit_crease_run(CreaseRun(**{**run.__dict__, **change}))


def test_equal_first_and_last_angles_divide_by_zero():
    run = exact_run()
    with pytest.raises(ValueError, match="same panel angle"):
        fit_crease_run(CreaseRun(**{**run.__dict__, "markers_last": run.markers_first * 2}))


def test_table1_summary():
    result = read_stiffness_table(data.path("thesis_table1_crease_stiffness.csv"))
    assert result.overall.n == 15
    assert result.overall.mean == pytest.approx(0.0471, abs=1e-4)
    # Sample SD (n - 1) of the printed runs; the population SD (n) is 0.0101.
    assert result.overall.sd == pytest.approx(0.010430, abs=1e-6)
    assert result.k.std() == pytest.approx(0.010076, abs=1e-6)
    assert result.per_sample["2"].mean == pytest.approx(0.039, abs=1e-12)
    assert result.between_samples.n == 5
    assert not result.outliers.any()


def test_an_outlier_is_flagged_and_kept():
    k = [0.045, 0.056, 0.056, 0.028, 0.040, 0.049, 0.2]
    result = summarize_crease(list("1112223"), list("1231231"), k)
    assert result.outliers.tolist() == [False] * 6 + [True]
    assert result.overall.n == 7  # flagged, not dropped
    assert result.as_dict()["outliers"][0]["k"] == 0.2


@pytest.fixture
def runs_file(tmp_path):
    rig = CreaseRig(sample_rate=2.0)  # 101 points a record: fast and enough
    return write_crease_example(tmp_path, seed=1, rig=rig)


def edit_cells(path, row, values):
    """Set cells of data row ``row`` (0-based) of a CSV file, by header prefix -> value (a
    header prefix as value copies that cell); returns the file line of the row."""
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))

    def index(prefix):
        return [i for i, name in enumerate(rows[0]) if name.startswith(prefix)][0]

    cells = rows[row + 1]
    for column, value in values.items():
        cells[index(column)] = cells[index(value[1:])] if value.startswith("=") else value
    with open(path, "w", newline="") as handle:
        csv.writer(handle, lineterminator="\n").writerows(rows)
    return row + 2


def test_a_list_of_runs_recovers_its_truth(runs_file):
    result = fit_crease_file(runs_file)
    assert result.overall.n == 15 and len(result.fits) == 15
    assert result.overall.mean == pytest.approx(0.047, rel=0.03)  # 101-point records
    assert result.skipped == []


@pytest.mark.parametrize("column, value, words", [
    ("W", "0", "W = 0 must be > 0"),
    ("Lp", "-31.2", "Lp = -31.2 must be > 0"),
    ("Lp", "thirty", "'thirty' is not a number"),
    ("W", "nan", "not a finite number"),
    ("record", "missing.csv", "no record file"),
])
def test_bad_cells_in_a_list_of_runs(runs_file, column, value, words):
    line = edit_cells(runs_file, 3, {column: value})
    with pytest.raises(RecordError, match=words) as error:
        fit_crease_file(runs_file)
    assert error.value.line == line and error.value.path == str(runs_file)
    assert error.value.column.startswith(column)


def test_identical_frames_name_the_marker_columns(runs_file):
    last_is_first = {key: "=" + key[:-1] + "1" for key in MARKER_KEYS[6:]}
    line = edit_cells(runs_file, 1, last_is_first)
    with pytest.raises(RecordError, match="same panel angle") as error:
        fit_crease_file(runs_file)
    assert error.value.line == line and "vertex_x1_px" in error.value.column


def test_a_record_with_one_point_names_its_file_line_and_column(runs_file):
    record = runs_file.parent / "s2_r1.csv"
    record.write_text("time_s,displacement_mm,force_N\n0.0,0.0,0.01\n")
    with pytest.raises(RecordError, match="at least 2") as error:
        fit_crease_file(runs_file)
    assert error.value.path == str(record) and error.value.line == 2
    assert error.value.column == "displacement_mm"


def test_nan_rows_in_records_are_skipped_on_request_and_reported(runs_file):
    record = runs_file.parent / "s1_r2.csv"
    lines = record.read_text().splitlines()
    lines[10] = "nan,nan,nan"
    record.write_text("\n".join(lines) + "\n")
    with pytest.raises(RecordError, match="not a finite number"):
        fit_crease_file(runs_file)
    result = fit_crease_file(runs_file, on_invalid="skip")
    assert len(result.skipped) == 1 and result.skipped[0].line == 11
    assert result.as_dict()["skipped"]["count"] == 1


def test_a_file_of_neither_shape(tmp_path):
    path = tmp_path / "other.csv"
    path.write_text("a,b\n1,2\n")
    with pytest.raises(RecordError, match="not a crease file") as error:
        fit_crease_file(path)
    assert error.value.line == 1


def test_a_falling_force_is_kept_but_warned_about(caplog):
    # Compression recorded as negative turns k negative: not silently "fixed", but said.
    run = exact_run()
    flipped = CreaseRun(**{**run.__dict__, "force": -run.force})
    with caplog.at_level("WARNING", logger="kresling.fits.crease"):
        fit = fit_crease_run(flipped)
    assert fit.k == pytest.approx(-0.047, rel=1e-3)
    assert "check the sign" in caplog.text


@pytest.mark.parametrize("scale, words", [(1e308, "not finite"),
                                          (1e303, "too large to summarize")])
def test_a_record_of_huge_forces_is_refused_naming_its_file(runs_file, scale, words):
    # Forces of ~1e307 N overflow eqn 19 itself (k = inf); 1e303 N give finite stiffnesses of
    # ~1e303 N/rad whose mean over the runs overflows. Either way the message names the
    # record that holds them, not only the list's line.
    record = runs_file.parent / "s2_r1.csv"
    lines = record.read_text().splitlines()
    header = [i for i, line in enumerate(lines) if line.startswith("time_s")][0]
    rows = [line.split(",") for line in lines[header + 1:]]
    record.write_text("\n".join(lines[:header + 1] + [f"{t},{d},{float(f) * scale!r}"
                                                      for t, d, f in rows]) + "\n")
    with pytest.raises(ValueError, match=words) as error:
        fit_crease_file(runs_file)
    assert "s2_r1.csv" in str(error.value)
