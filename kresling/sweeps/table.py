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
import operator
import re

import numpy as np

from kresling._validation import csv_records, show

__all__ = ["SweepTable", "DESIGN_COLUMNS", "STATUS_COLUMNS", "OK", "FAILED"]

#: Leading and trailing columns of every sweep table (metric columns go between them).
DESIGN_COLUMNS = ("n", "Lc", "lam", "R")
STATUS_COLUMNS = ("status", "reason", "iterations", "seconds", "index")
OK, FAILED = "ok", "failed"
_INTEGER = {"n", "iterations", "index"}
_TEXT = {"status", "reason"}
# where()'s comparison strings: an operator, then a number (spaces allowed around both).
_COMPARISON = re.compile(r"\s*(<=|>=|==|!=|<|>)\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*")
_OPERATORS = {"<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge,
              "==": operator.eq, "!=": operator.ne}


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
    """A cell of column ``name`` from its text; a ValueError where it is not one (an
    integer beyond the 64 bits a column holds included)."""
    kind = column_kind(name)
    if kind == "int":
        value = int(text)
        if not -2**63 <= value < 2**63:
            raise ValueError(f"{name} = {text!r} is beyond a 64-bit integer")
        return value
    return text if kind == "str" else float(text)


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

    def where(self, **conditions) -> "SweepTable":
        """The rows that meet every condition, as a new table.

        Parameters
        ----------
        **conditions
            ``column=condition``, one per column, all of which must hold:

            - a value: equal to it, e.g. ``n=10``;
            - a comparison string, one of ``"<x"``, ``"<=x"``, ``">x"``, ``">=x"``, ``"==x"``,
              ``"!=x"`` with a number x, e.g. ``lam=">=0.8"``;
            - a tuple ``(low, high)``: within the closed range, either end ``None`` for no
              bound, e.g. ``Lc=(15, 30)`` for 15 <= Lc <= 30;
            - a list or set: equal to one of its values, e.g. ``n=[8, 10]``.

            A NaN value meets no condition but ``"!=x"``. On a text column (``status``,
            ``reason``) only equality applies: a string is the value itself
            (``status="ok"``), or ``"==text"`` / ``"!=text"`` (spaces around the text are
            ignored), e.g. ``status="!=ok"`` for the failed designs; a value that itself
            starts with ``==`` or ``!=`` is written after ``==``.

        Raises
        ------
        ValueError
            For a column the table does not have, a condition of none of these forms, or
            ``<``, ``<=``, ``>``, ``>=`` on a text column.

        Examples
        --------
        >>> t = SweepTable({"n": [8, 8, 10], "Lc": [15.0, 30.0, 15.0]})
        >>> len(t.where(n=8)), len(t.where(Lc=">20")), len(t.where(n=8, Lc=(None, 20)))
        (2, 1, 1)
        >>> s = SweepTable({"n": [8, 8, 10], "status": ["ok", "failed", "ok"]})
        >>> s.where(status="!=ok")["n"].tolist(), s.where(status="== ok")["n"].tolist()
        ([8], [8, 10])
        """
        mask = np.ones(len(self), bool)
        for name, condition in conditions.items():
            mask &= self._meets(name, condition)
        return self.take(mask)

    def _meets(self, name: str, condition) -> np.ndarray:
        """Mask of the rows whose column ``name`` meets ``condition`` (see :meth:`where`)."""
        if name not in self._columns:
            raise ValueError(f"where: no column {name!r}; the columns are "
                             f"{', '.join(self.columns)}")
        column = self._columns[name]
        numeric = column.dtype != object
        if isinstance(condition, str) and not numeric:
            return self._meets_text(name, column, condition)
        if isinstance(condition, str) and numeric:
            match = _COMPARISON.fullmatch(condition)
            if match is None:
                raise ValueError(f"where: {name} = {condition!r} is not a condition: a "
                                 f"comparison is one of <, <=, >, >=, ==, != followed by a "
                                 f"number, e.g. {name}='>=0.8'")
            operator, bound = match.group(1), float(match.group(2))
            with np.errstate(invalid="ignore"):
                return _OPERATORS[operator](column, bound)
        if isinstance(condition, tuple):
            if len(condition) != 2 or not numeric or not all(
                    b is None or _is_number(b) for b in condition):
                raise ValueError(f"where: {name} = {condition!r} is not a range: a range is "
                                 f"a tuple (low, high) of two numbers or None, on a numeric "
                                 f"column")
            low, high = condition
            mask = np.isfinite(column) if column.dtype.kind == "f" else np.ones(len(self), bool)
            if low is not None:
                mask &= column >= low
            if high is not None:
                mask &= column <= high
            return mask
        if isinstance(condition, (list, set, frozenset, np.ndarray)):
            return np.isin(column, list(condition))
        return column == condition

    @staticmethod
    def _meets_text(name: str, column: np.ndarray, condition: str) -> np.ndarray:
        """Mask of the rows of the text column ``name`` that meet the string ``condition``:
        ``"==text"``, ``"!=text"`` or the text itself (see :meth:`where`)."""
        stripped = condition.lstrip()
        operator_ = next((op for op in ("==", "!=") if stripped.startswith(op)), None)
        if operator_ is not None:
            value = stripped[2:].strip()
            return _OPERATORS[operator_](column, value).astype(bool)
        # An ordering of text is almost never what was meant (and "<ok" is no status):
        # say so instead of matching nothing.
        ordering = next((op for op in ("<=", ">=", "<", ">") if stripped.startswith(op)),
                        None)
        if ordering is not None:
            raise ValueError(f"where: {name} = {condition!r} is not a condition on the text "
                             f"column {name}: only equality applies to text, written "
                             f"{name}='ok', {name}='==ok' or {name}='!=ok' (no {ordering})")
        return (column == condition).astype(bool)

    def row(self, i: int) -> dict:
        """Row ``i`` as a dict of plain Python values."""
        return {k: v[i].item() if hasattr(v[i], "item") else v[i] for k, v in self._columns.items()}

    def best(self, metric: str, where: dict | None = None, **equal) -> dict:
        """The row with the largest ``metric`` among the ok rows that meet the conditions.

        Parameters
        ----------
        metric : str
            A numeric column.
        where : dict, optional
            ``{column: condition}`` in any form :meth:`where` takes, e.g.
            ``{"lam": "<=0.85", "Lc": (20, None)}``.
        **equal
            More conditions, e.g. ``n=10`` (the same forms).

        Returns
        -------
        dict
            The row (plain values), plus ``"boundary"``: a tuple naming each searched design
            parameter at whose edge the optimum lies, e.g. ``("Lc min", "lam max")``; empty
            when it is inside the searched domain. A parameter is searched when the rows
            meeting the conditions (ok or failed) take more than one value of it; its edges
            are their smallest and largest values. An optimum on the boundary may be beaten
            just outside the domain: widen it, or use
            :func:`~kresling.sweeps.optimize_design` with wider bounds.

        Raises
        ------
        ValueError
            If ``metric`` is not a numeric column, a condition is invalid (see
            :meth:`where`), or no ok row has a finite value.

        Examples
        --------
        >>> t = SweepTable({"n": [8, 8, 8], "Lc": [15.0, 30.0, 45.0], "lam": [0.9] * 3,
        ...                 "kb_ratio": [20.0, 9.0, 5.0], "status": ["ok"] * 3})
        >>> t.best("kb_ratio")["boundary"]
        ('Lc min',)
        >>> t.best("kb_ratio", where={"Lc": ">20"})["Lc"]
        30.0
        """
        if where is not None and not isinstance(where, dict):
            raise ValueError(f"where = {where!r} is invalid: must be a dict of column "
                             f"conditions, e.g. {{'lam': '>=0.8'}}")
        conditions = {**(where or {}), **equal}
        if metric not in self._columns or self._columns[metric].dtype == object:
            numeric = [c for c, v in self._columns.items() if v.dtype != object]
            raise ValueError(f"metric = {metric!r} is invalid: must be a numeric column, one "
                             f"of {', '.join(numeric)}")
        table = self.where(**conditions)
        ok = table.ok if "status" in table else np.ones(len(table), bool)
        values = np.where(ok & np.isfinite(table[metric]), table[metric], -np.inf)
        if not np.isfinite(values).any():
            shown = f" where {conditions}" if conditions else ""
            raise ValueError(f"no successful design with a finite {metric}{shown}")
        i = int(np.argmax(values))
        return {**table.row(i), "boundary": table._boundary(i)}

    def _boundary(self, i: int) -> tuple:
        """The searched design parameters at whose edge row ``i`` lies (see :meth:`best`)."""
        edges = []
        for name in DESIGN_COLUMNS:
            if name not in self._columns:
                continue
            column = self._columns[name]
            low, high = np.nanmin(column), np.nanmax(column)
            if low == high:
                continue  # one value: not searched
            edges += [f"{name} {end}" for end, edge in (("min", low), ("max", high))
                      if column[i] == edge]
        return tuple(edges)

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
        header_line, header = records[0]
        repeated = sorted({name for name in header if header.count(name) > 1})
        if repeated:
            raise ValueError(f"{path}, line {header_line}: the header names column(s) "
                             f"{repeated} more than once: each column once")
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


def _is_number(value) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)


def _plain(value):
    return value.item() if isinstance(value, np.generic) else value


def _as_column(name: str, values) -> np.ndarray:
    kind = column_kind(name)
    if kind == "str":
        return np.asarray(values, dtype=object)
    return np.asarray(values, dtype=np.int64 if kind == "int" else float)
