"""The CSV reader: units from headers, configurable names, and bad input located by file,
line and column; skipped lines counted and reported."""

import numpy as np
import pytest

from kresling.fits.records import Field, RecordError, read_machine_record, read_table
from kresling.fits.units import normalize_unit, split_header


def write(tmp_path, text, name="record.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


GOOD = "time_s,displacement_mm,force_N\n0,0.0,0.10\n1,0.1,0.20\n2,0.2,0.30\n"


def test_reads_columns_in_canonical_units_with_line_numbers(tmp_path):
    table = read_machine_record(write(tmp_path, GOOD))
    np.testing.assert_array_equal(table.columns["force"], [0.1, 0.2, 0.3])
    np.testing.assert_array_equal(table.lines, [2, 3, 4])
    assert table.skipped == [] and table.units["force"] == "N"


@pytest.mark.parametrize("header, unit", [
    ("Force (N)", "N"), ("force [lbf]", "lbf"), ("force_kN", "kN"), ("Load (mN)", "mN"),
    ("stiffness_N_per_rad", "N/rad"), ("K (N·m/rad)", "N*m/rad"),
])
def test_header_spellings_of_a_unit(header, unit):
    name = header.split()[0].split("_")[0]
    assert split_header(header, (name,))[1] == unit


def test_unit_conversion_and_aliases(tmp_path):
    # An export in inches and pounds-force with the machine's own column names.
    text = "Time (min),Position (in),Load (lbf)\n0,0,1\n0.5,1,2\n"
    table = read_machine_record(write(tmp_path, text))
    np.testing.assert_allclose(table.columns["displacement"], [0.0, 25.4])
    np.testing.assert_allclose(table.columns["force"], [4.4482216152605, 8.896443230521])
    np.testing.assert_allclose(table.columns["time"], [0.0, 30.0])


def test_configured_names_units_semicolons_bom_and_metadata(tmp_path):
    text = "\ufeff# operator: A. B.\n# module_length: 6 cm\nHub;Kraft\n0;1\n1;2\n"
    table = read_machine_record(write(tmp_path, text),
                                names={"displacement": "Hub", "force": "Kraft"},
                                units={"displacement": "mm", "force": "N"})
    np.testing.assert_array_equal(table.columns["force"], [1.0, 2.0])
    assert table.header_line == 3 and table.metadata["operator"] == ("A. B.", 1)
    assert table.quantity("module_length", "length") == pytest.approx(60.0)


def test_negate_flips_compression_recorded_as_negative(tmp_path):
    text = "displacement_mm,force_N\n0,-0.1\n-1,-0.2\n"
    table = read_machine_record(write(tmp_path, text), negate=("force", "displacement"))
    np.testing.assert_array_equal(table.columns["force"], [0.1, 0.2])
    np.testing.assert_array_equal(table.columns["displacement"], [0.0, 1.0])


def test_blank_and_comment_lines_are_skipped_and_reported(tmp_path):
    text = "displacement_mm,force_N\n0,1\n\n# pause\n1,2\n,\n"
    table = read_machine_record(write(tmp_path, text))
    assert len(table) == 2
    assert [(s.line, s.reason) for s in table.skipped] == [
        (3, "blank line"), (4, "comment line"), (6, "empty row")]


def located(error, path, line, column):
    message = str(error.value)
    assert error.value.path == str(path) and str(path) in message
    assert error.value.line == line and (line is None or f"line {line}" in message)
    assert error.value.column == column and (column is None or repr(column) in message)


@pytest.mark.parametrize("text, line, column, words", [
    ("displacement_mm,Kraft_N\n0,1\n1,2\n", 1, "force", "no column"),          # misnamed
    ("displacement_mm\n0\n1\n", 1, "force", "no column"),                       # missing
    ("displacement_mm,force\n0,1\n1,2\n", 1, "force", "no unit"),
    ("displacement_mm,force_mm\n0,1\n1,2\n", 1, "force_mm", "not a force unit"),
    ("displacement_mm,force_N\n0,1\n1,abc\n", 3, "force_N", "'abc' is not a number"),
    ("displacement_mm,force_N\n0,1\n1,\n", 3, "force_N", "empty cell"),
    ("displacement_mm,force_N\n0,1\nnan,nan\n2,3\n", 3, "displacement_mm", "not a finite"),
    ("displacement_mm,force_N\n0,1\n", 2, "displacement_mm", "at least 2"),    # one point
    ("displacement_mm,force_N\n", 1, "displacement_mm", "at least 2"),         # no points
    ("displacement_mm,force_N,load_N\n0,1,1\n1,2,2\n", 1, "load_N", "more than one"),
    ("displacement_mm,force_N\n0,1\n1\n", 3, None, "1 cells"),
])
def test_bad_input_names_file_line_and_column(tmp_path, text, line, column, words):
    path = write(tmp_path, text)
    with pytest.raises(RecordError, match=words) as error:
        read_machine_record(path)
    located(error, path, line, column)


def test_unit_given_twice_must_agree(tmp_path):
    path = write(tmp_path, GOOD)
    with pytest.raises(RecordError, match="header says 'N'") as error:
        read_machine_record(path, units={"force": "lbf"})
    located(error, path, 1, "force_N")


def test_invalid_rows_skipped_on_request_are_counted_with_their_reason(tmp_path):
    text = "displacement_mm,force_N\n0,1\n1,NaN\n2,x\n3,4\n"
    table = read_machine_record(write(tmp_path, text), on_invalid="skip")
    np.testing.assert_array_equal(table.columns["displacement"], [0.0, 3.0])
    assert [s.line for s in table.skipped] == [3, 4]
    assert "column 'force_N'" in table.skipped[1].reason and "'x'" in table.skipped[1].reason


def test_positive_fields_reject_zero_and_negative_lengths(tmp_path):
    fields = (Field("W", "length", positive=True),)
    for value in ("0", "-3.5"):
        path = write(tmp_path, f"W_mm\n10\n{value}\n")
        with pytest.raises(RecordError, match="must be > 0") as error:
            read_table(path, fields)
        located(error, path, 3, "W_mm")


def test_metadata_without_unit_is_an_error(tmp_path):
    table = read_machine_record(write(tmp_path, "# module_length: 60\n" + GOOD))
    with pytest.raises(RecordError, match="needs a unit") as error:
        table.quantity("module_length", "length")
    assert error.value.line == 1


def test_normalize_unit_keeps_case():
    assert normalize_unit(" N_per_rad ") == "N/rad"
    assert normalize_unit("mN") != normalize_unit("MN")


def test_latin1_exports_with_micro_sign(tmp_path):
    path = tmp_path / "latin1.csv"
    path.write_bytes("Disp (µm),Load (N)\n0,0.1\n500,0.2\n".encode("latin-1"))
    table = read_machine_record(path)
    np.testing.assert_allclose(table.columns["displacement"], [0.0, 0.5])
