"""What a run formats once and reuses (the CSV lines and FOLD frames its stream wrote, the
element states its history rows took) leaves its files byte for byte as a run that
formats everything afresh writes them."""

from __future__ import annotations

import csv
import io
from pathlib import Path

import numpy as np

from kresling.io.fold_format import forget_frame_texts
from kresling.simulate import simulate
from kresling.simulate.row_lines import float_row, forget_rows, remembered_row, row_lines

POLYGON = (Path(__file__).parents[1] / "data" / "merlin2_examples" / "polygon_N5B8_auto"
           / "problem.toml")
FILES = ("history.csv", "displacements.csv", "path.fold", "summary.json", "view.html")


def test_a_streamed_run_writes_the_bytes_of_a_run_written_afresh(tmp_path):
    # The streamed run keeps its rows' lines, frames' texts and element states for its final
    # files; the other run is written after every kept text is let go and is not streamed.
    streamed = simulate(POLYGON, progress=False, stream=tmp_path / "streamed")
    streamed.write(tmp_path / "streamed")
    forget_rows()
    forget_frame_texts()
    simulate(POLYGON, progress=False).write(tmp_path / "afresh")
    for name in FILES:
        assert (tmp_path / "streamed" / name).read_bytes() == \
            (tmp_path / "afresh" / name).read_bytes(), name


def test_float_rows_are_csv_writer_lines_and_kept_lines_match_their_rows():
    rows = np.array([[0.0, -0.0, 1e-7, -2.5e300, 1 / 3], [12345678901234567.0, 5e-324, -1.0,
                                                          0.1, 1e16]])
    for row in rows:
        written = io.StringIO(newline="")
        csv.writer(written).writerow(row.tolist())
        assert float_row(row) == written.getvalue()
    forget_rows()
    remembered_row(rows[0])
    changed = rows.copy()
    changed[1, 3] = np.nextafter(changed[1, 3], 1.0)   # one bit: a line of its own
    assert row_lines(rows) == [float_row(r) for r in rows]
    assert row_lines(changed) == [float_row(r) for r in changed] != row_lines(rows)
