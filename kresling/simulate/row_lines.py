"""CSV lines of rows of floats, each formatted once in a run: the lines a run writes as its
path goes (:mod:`kresling.simulate.path_stream`) are kept, by the row's bytes, for the file
written whole at its end, which would otherwise format the same floats again (a double's
shortest ``repr`` is most of a CSV file's cost).

A line is kept for the row's exact bytes, so a row taken from here is the line
:func:`float_row` gives it: the files' bytes are the same either way.
"""

from __future__ import annotations

import numpy as np

__all__ = ["float_row", "remembered_row", "row_lines", "forget_rows"]

#: Characters kept at most (a long run's rows beyond them are formatted again at its end).
_LIMIT = 64_000_000

_kept: dict = {}
_size = [0]


def float_row(values) -> str:
    """One CSV line of floats, as ``csv.writer`` writes it (each float's ``repr``, no quotes,
    ``\\r\\n``), at about half its cost: a path's files hold thousands of rows.

    Parameters
    ----------
    values : array_like, shape (C,)
    """
    return ",".join(map(repr, np.asarray(values, dtype=float).tolist())) + "\r\n"


def remembered_row(values) -> str:
    """:func:`float_row` of ``values``, kept for :func:`row_lines` (within the limit)."""
    row = np.asarray(values, dtype=float)
    line = float_row(row)
    if _size[0] + len(line) <= _LIMIT:
        _kept[row.tobytes()] = line
        _size[0] += len(line)
    return line


def row_lines(array) -> list:
    """:func:`float_row` of every row of ``array`` (shape (R, C)), each kept line taken
    (and let go) instead of formatting its row again."""
    lines = []
    for row in np.asarray(array, dtype=float):
        line = _kept.pop(row.tobytes(), None)
        if line is None:
            line = float_row(row)
        else:
            _size[0] -= len(line)
        lines.append(line)
    return lines


def forget_rows() -> None:
    """Let every kept line go (a new run starts)."""
    _kept.clear()
    _size[0] = 0
