"""The results of a sweep: a labelled table of columns, and its CSV form.

One row per design: its parameters (``n, Lc, lam, R``), every metric's columns, ``status``
(``"ok"`` or ``"failed"``), ``reason`` (why it failed, empty when ok), ``iterations``
(Newton iterations over all its runs), ``seconds`` (compute time) and ``index`` (its
position in the sweep's design set).

The table is plain numpy columns, not a pandas DataFrame: the package does not depend on
pandas for one table, the CSV file is the interchange format, and :meth:`SweepTable.to_pandas`
is one call away where pandas is installed. Floats are written with ``repr`` so that reading
the file back gives the same bits.
"""

from __future__ import annotations

import csv
import io

import numpy as np

from kresling._validation import csv_records, show

__all__ = ["SweepTable", "DESIGN_COLUMNS", "STATUS_COLUMNS", "OK", "FAILED"]

#: Leading and trailing columns of every sweep table (metric columns go between them).
DESIGN_COLUMNS = ("n", "Lc", "lam", "R")
STATUS_COLUMNS = ("status", "reason", "iterations", "seconds", "index")
OK, FAILED = "ok", "failed"
_INTEGER = {"n", "iterations", "index"}
_TEXT = {"status", "reason"}


def column_kind(name: str) -> str:
    """``"int"``, ``"str"`` or ``"float"``: how column ``name`` is stored and parsed."""
    return "int" if name in _INTEGER else "str" if name in _TEXT else "float"


def format_row(row) -> str:
    """One CSV line (with its newline) for a row of plain values."""
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerow(
        repr(float(v)) if isinstance(v, float) else v for v in row)
    return buffer.getvalue()


def parse_value(name: str, text: str):
    kind = column_kind(name)
    return int(text) if kind == "int" else text if kind == "str" else float(text)


class SweepTable:
    """Columns of equal length, by name.

    Parameters
    ----------
    columns : dict of str to array_like
        In table order.
    attrs : dict, optional
        About the run that made it: ``metrics``, ``computed`` (designs computed by this
        call), ``loaded`` (read back from disk when resuming), ``seconds``, ``workers``, ``out``.

    Examples
    --------
    >>> t = SweepTable({"n": [8, 8], "Lc": [15.0, 30.0], "lam": [0.9, 0.9], "R": [30.0, 30.0],
    ...                 "kb_ratio": [20.0, 9.0], "status": ["ok", "ok"]})
    >>> t.best("kb_ratio")["Lc"]
    15.0
    """

    def __init__(self, columns: dict, attrs: dict | None = None):
        self._columns = {name: _as_column(name, values) for name, values in columns.items()}
        lengths = {len(v) for v in self._columns.values()}
        if len(lengths) > 1:
            raise ValueError(f"columns have different lengths {sorted(lengths)}")
        self.attrs = dict(attrs or {})

    @property
    def columns(self) -> tuple:
        """Column names, in order."""
        return tuple(self._columns)

    def __len__(self) -> int:
        return len(next(iter(self._columns.values()))) if self._columns else 0

    def __getitem__(self, name: str) -> np.ndarray:
        try:
            return self._columns[name]
        except KeyError:
            raise KeyError(f"no column {name!r}; the columns are "
                           f"{', '.join(self.columns)}") from None

    def __contains__(self, name) -> bool:
        return name in self._columns

    def __repr__(self) -> str:
        failed = int((self["status"] != OK).sum()) if "status" in self else 0
        return (f"SweepTable({len(self)} rows, {failed} failed; columns: "
                f"{', '.join(self.columns)})")

    @property
    def ok(self) -> np.ndarray:
        """Mask of the rows whose status is ``"ok"``, shape (N,)."""
        return self["status"] == OK

    def take(self, rows) -> "SweepTable":
        """The rows selected by a boolean mask or an index array, as a new table."""
        return SweepTable({k: v[rows] for k, v in self._columns.items()}, self.attrs)

    def where(self, **equal) -> "SweepTable":
        """Rows whose columns equal the given values, e.g. ``table.where(n=10)``."""
        mask = np.ones(len(self), bool)
        for name, value in equal.items():
            mask &= self[name] == value
        return self.take(mask)

    def row(self, i: int) -> dict:
        """Row ``i`` as a dict of plain Python values."""
        return {k: v[i].item() if hasattr(v[i], "item") else v[i] for k, v in self._columns.items()}

    def best(self, metric: str, **equal) -> dict:
        """The row with the largest ``metric`` among the ok rows (optionally ``where``).

        Raises
        ------
        ValueError
            If no ok row has a finite value.
        """
        table = self.where(**equal)
        values = np.where(table.ok & np.isfinite(table[metric]), table[metric], -np.inf)
        if not np.isfinite(values).any():
            raise ValueError(f"no successful design with a finite {metric}")
        return table.row(int(np.argmax(values)))

    def grid(self, metric: str, n: int):
        """``metric`` over the Lc x lambda grid of one n, for heat maps.

        Returns
        -------
        Lc : ndarray, shape (A,)
        lam : ndarray, shape (B,)
        values : ndarray, shape (B, A)
            ``values[j, i]`` at ``lam[j], Lc[i]``; NaN for failed or missing designs.
        """
        part = self.where(n=n)
        Lc, i = np.unique(part["Lc"], return_inverse=True)
        lam, j = np.unique(part["lam"], return_inverse=True)
        values = np.full((len(lam), len(Lc)), np.nan)
        values[j, i] = np.where(part.ok, part[metric], np.nan)
        return Lc, lam, values

    def to_pandas(self):
        """A pandas DataFrame of the table (needs pandas)."""
        try:
            import pandas as pd  # here, not at the top: pandas is not a dependency
        except ImportError:
            raise ImportError("SweepTable.to_pandas needs pandas: pip install pandas") from None
        return pd.DataFrame(self._columns)

    def to_csv(self, path) -> None:
        """Write the table (header line, then one line per row)."""
        with open(path, "w", newline="") as f:
            f.write(format_row(self.columns))
            for i in range(len(self)):
                f.write(format_row(_plain(v[i]) for v in self._columns.values()))

    @classmethod
    def read_csv(cls, path) -> "SweepTable":
        """Read a table written by :meth:`to_csv` or by a sweep."""
        with open(path, newline="", encoding="utf-8", errors="replace") as f:
            records = list(csv_records(f, path))
        if not records:
            raise ValueError(f"{path} is empty: a sweep table starts with its header line")
        header = records[0][1]
        columns = {name: [] for name in header}
        for line, row in records[1:]:
            if len(row) != len(header):
                raise ValueError(f"{path}, line {line}: {len(row)} fields, expected "
                                 f"{len(header)}")
            for name, text in zip(header, row):
                try:
                    columns[name].append(parse_value(name, text))
                except ValueError:
                    raise ValueError(f"{path}, line {line}: column {name!r} = {show(text)} is "
                                     f"not a {column_kind(name)}") from None
        return cls(columns)


def _plain(value):
    return value.item() if isinstance(value, np.generic) else value


def _as_column(name: str, values) -> np.ndarray:
    kind = column_kind(name)
    if kind == "str":
        return np.asarray(values, dtype=object)
    return np.asarray(values, dtype=np.int64 if kind == "int" else float)
