"""Reading laboratory records from CSV: configurable column names, units checked, every
problem located by file, line and column, and every skipped row counted.

A record is a text table with one header line, e.g. a testing-machine export::

    # state: contracted            <- optional metadata lines: "# key: value"
    # module_length: 60 mm
    Time (s),Displacement (mm),Force (N)
    0.0,0.000,0.0012
    ...

Headers carry their unit as ``name (unit)``, ``name [unit]`` or ``name_unit``; a column
without one needs ``units={key: unit}``. Blank and comment lines between data rows are
skipped and reported; a bad cell raises :class:`RecordError` unless ``on_invalid="skip"``,
in which case the row is skipped and reported instead.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from kresling._validation import csv_cells
from kresling.fits.units import CANONICAL, conversion_factor, normalize_unit, split_header

__all__ = ["Field", "RecordError", "SkippedRow", "Table", "read_table", "read_header",
           "MACHINE_FIELDS", "read_machine_record"]

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class Field:
    """A column a reader expects.

    Parameters
    ----------
    key : str
        Name used in code and the default header name.
    dimension : str or None
        A dimension of :mod:`kresling.fits.units` (``"length"``, ``"force"``, ...) whose
        unit the header must state; None for a plain number; ``"text"`` for a string.
    aliases : tuple of str
        Other header names accepted (case-insensitive), e.g. ``("load",)`` for force.
    required : bool
        Whether a table without this column is an error.
    positive : bool
        Whether every value must be > 0 (lengths).
    """

    key: str
    dimension: str | None = None
    aliases: tuple = ()
    required: bool = True
    positive: bool = False


@dataclass(frozen=True)
class SkippedRow:
    """A line of a table that holds no data and was passed over, and why."""

    path: str
    line: int
    reason: str

    def __str__(self) -> str:
        return f"{self.path}, line {self.line}: {self.reason}"


class RecordError(ValueError):
    """Bad input in a record; ``path``, ``line`` (1-based) and ``column`` (the header as
    written in the file) say where. ``line`` or ``column`` is None when not applicable."""

    def __init__(self, path, line, column, problem: str):
        self.path, self.line, self.column, self.problem = str(path), line, column, problem
        where = [self.path]
        if line is not None:
            where.append(f"line {line}")
        if column is not None:
            where.append(f"column {column!r}")
        super().__init__(f"{', '.join(where)}: {problem}")


@dataclass
class Table:
    """The columns read from one file, in canonical units (mm, N, s, rad).

    Attributes
    ----------
    path : str
    columns : dict of str to ndarray, shape (n_rows,)
        Values by field key: float64 in canonical units, or ``object`` arrays for text.
    headers : dict of str to str
        The header of each field as written in the file.
    units : dict of str to str or None
        The unit each column was recorded in.
    lines : ndarray of int, shape (n_rows,)
        File line (1-based) of each row.
    header_line : int
    metadata : dict of str to (str, int)
        ``# key: value`` lines above the header: value text and line number.
    skipped : list of SkippedRow
    """

    path: str
    columns: dict
    headers: dict
    units: dict
    lines: np.ndarray
    header_line: int
    metadata: dict = field(default_factory=dict)
    skipped: list = field(default_factory=list)

    def __len__(self) -> int:
        return len(self.lines)

    def error(self, row: int | None, keys, problem: str) -> RecordError:
        """A :class:`RecordError` at data row ``row`` (None: the header) and the columns of
        ``keys`` (a field key, a sequence of them, or None)."""
        line = self.header_line if row is None else int(self.lines[row])
        if keys is None:
            column = None
        elif isinstance(keys, str):
            column = self.headers.get(keys, keys)
        else:
            column = ", ".join(self.headers.get(k, k) for k in keys)
        return RecordError(self.path, line, column, problem)

    def quantity(self, key: str, dimension: str) -> float:
        """A ``# key: value unit`` metadata entry as a number in canonical units."""
        text, line = self.metadata[key]
        parts = text.split()
        try:
            value = float(parts[0])
        except (ValueError, IndexError):
            raise RecordError(self.path, line, None,
                              f"metadata {key!r} = {text!r} is not a number") from None
        if len(parts) != 2:
            raise RecordError(self.path, line, None, f"metadata {key!r} = {text!r} needs a "
                              f"unit, e.g. '{parts[0]} {CANONICAL[dimension]}'")
        try:
            return value * conversion_factor(normalize_unit(parts[1]), dimension)
        except ValueError as error:
            raise RecordError(self.path, line, None, f"metadata {key!r}: {error}") from None


def read_table(path, fields, *, names=None, units=None, on_invalid: str = "raise",
               negate=(), min_rows: int = 1) -> Table:
    """Read the columns ``fields`` of a CSV file.

    Parameters
    ----------
    path : str or Path
    fields : sequence of Field
    names : dict of str to str, optional
        Header name to use for a field key, overriding its default names
        (e.g. ``{"force": "Load"}``).
    units : dict of str to str, optional
        Unit of a field whose header states none (e.g. ``{"force": "lbf"}``).
    on_invalid : {"raise", "skip"}
        What a row with a bad cell (not a number, empty, NaN, a length <= 0) does: raise a
        :class:`RecordError`, or be skipped and reported in ``Table.skipped``.
    negate : sequence of str
        Keys of columns whose sign to flip (machines that record compression as negative).
    min_rows : int
        Fewest data rows accepted.

    Returns
    -------
    Table

    Raises
    ------
    RecordError
        A missing, duplicated or misnamed column, a unit that is not of the column's
        dimension, a bad cell, too few rows; always naming file, line and column.
    FileNotFoundError
        If ``path`` does not exist.
    """
    if on_invalid not in ("raise", "skip"):
        raise ValueError(f"on_invalid = {on_invalid!r} is invalid: must be 'raise' or 'skip'")
    path = Path(path)
    text_lines, header_index, metadata, delimiter, header = _load(path)
    layout = _match_columns(header, fields, names or {}, path, header_index + 1)
    factors = _unit_factors(layout, units or {}, negate, header, path, header_index + 1)
    table = Table(str(path), {}, {k: header[i] for k, (i, _, _) in layout.items()},
                  {k: u for k, (_, _, u) in layout.items()}, np.empty(0, int),
                  header_index + 1, metadata)
    rows, lines = _parse_rows(text_lines, header_index, delimiter, layout, table, on_invalid)
    for key, (index, spec, _) in layout.items():
        values = [row[key] for row in rows]
        table.columns[key] = (np.array(values, dtype=object) if spec.dimension == "text"
                              else np.array(values, dtype=float) * factors[key])
    table.lines = np.array(lines, dtype=int)
    if len(table) < min_rows:
        numeric = [k for k, (_, s, _) in layout.items() if s.dimension != "text"]
        first = next((k for k in numeric if layout[k][1].required), numeric[0])
        row = len(table) - 1 if len(table) else None
        raise table.error(row, first, f"{len(table)} data row(s); at least {min_rows} needed")
    if table.skipped:
        logger.warning("%s: skipped %d line(s): %s", path, len(table.skipped),
                       "; ".join(f"line {s.line} ({s.reason})" for s in table.skipped[:5]))
    return table


def read_header(path) -> tuple[int, list]:
    """Line number (1-based) and cells of a CSV file's header, without parsing its rows."""
    _, index, _, _, header = _load(Path(path))
    return index + 1, header


def _load(path: Path):
    """The file's lines, the header's index, the metadata above it, the delimiter and the
    header's cells. A byte-order mark (Excel's UTF-8 export) is dropped; a file that is not
    UTF-8 is read as Latin-1, as older Windows machine software writes "µm" or "°"."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        logger.info("%s is not UTF-8; reading it as Latin-1", path)
        text = path.read_text(encoding="latin-1")
    text_lines = text.splitlines()
    index, metadata = _preamble(text_lines, path)
    delimiter = _delimiter(text_lines[index])
    return text_lines, index, metadata, delimiter, _cells(text_lines[index], delimiter, path,
                                                          index + 1)


def _cells(text, delimiter, path, line):
    """One line's cells; csv's errors (a field over its 128 KiB limit) as a RecordError."""
    try:
        return csv_cells(text, path, line, delimiter)
    except ValueError as error:
        raise RecordError(path, line, None, str(error).split(": ", 1)[1]) from None


def _preamble(text_lines, path):
    """Index of the header line, and the ``# key: value`` metadata above it."""
    metadata = {}
    for index, raw in enumerate(text_lines):
        line = raw.strip()
        if not line:
            continue
        if not line.startswith("#"):
            return index, metadata
        body = line.lstrip("#").strip()
        for separator in (":", "="):
            key, found, value = body.partition(separator)
            if found and key.strip():
                metadata[key.strip().lower().replace(" ", "_")] = (value.strip(), index + 1)
                break
    raise RecordError(path, None, None, "no header line (the file is empty or all comments)")


def _delimiter(header_text: str) -> str:
    """The delimiter the header uses most: comma, semicolon or tab."""
    return max((",", ";", "\t"), key=header_text.count)


def _match_columns(header, fields, names, path, line):
    """Map each field key to (column index, field, unit as written or None)."""
    layout = {}
    for spec in fields:
        accepted = (names[spec.key],) if spec.key in names else (spec.key, *spec.aliases)
        hits = [(i, split_header(h, accepted)) for i, h in enumerate(header)]
        hits = [(i, match) for i, match in hits if match is not None]
        if len(hits) > 1:
            raise RecordError(path, line, header[hits[1][0]],
                              f"more than one column matches {spec.key!r}: "
                              f"{[header[i] for i, _ in hits]}; pick one with names=")
        if hits:
            layout[spec.key] = (hits[0][0], spec, hits[0][1][1])
        elif spec.required:
            wanted = " or ".join(repr(a) for a in accepted)
            raise RecordError(path, line, spec.key,
                              f"no column named {wanted} (headers: {header}); "
                              f"name the column with names={{{spec.key!r}: ...}}")
    return layout


def _unit_factors(layout, units, negate, header, path, line):
    """Conversion factor of each numeric column to canonical units (sign-flipped if asked)."""
    factors = {}
    for key, (index, spec, unit) in list(layout.items()):
        if spec.dimension in (None, "text"):
            factors[key] = -1.0 if key in negate else 1.0
            continue
        given = normalize_unit(units[key]) if key in units else None
        if unit is not None and given is not None and unit != given:
            raise RecordError(path, line, header[index], f"the header says {unit!r} but "
                              f"units= says {given!r}")
        unit = unit or given
        if unit is None:
            raise RecordError(path, line, header[index], f"no unit: write it in the header, e.g. "
                              f"'{key} ({CANONICAL[spec.dimension]})', or pass "
                              f"units={{{key!r}: ...}}")
        try:
            factor = conversion_factor(unit, spec.dimension)
        except ValueError as error:
            raise RecordError(path, line, header[index], str(error)) from None
        layout[key] = (index, spec, unit)
        factors[key] = -factor if key in negate else factor
    return factors


def _parse_rows(text_lines, header_index, delimiter, layout, table, on_invalid):
    """Data rows as dicts of raw values, and their line numbers; skips are recorded."""
    rows, lines = [], []
    width = max(index for index, _, _ in layout.values()) + 1
    for index in range(header_index + 1, len(text_lines)):
        number, text = index + 1, text_lines[index].strip()
        reason = "blank line" if not text else "comment line" if text.startswith("#") else None
        if reason:
            table.skipped.append(SkippedRow(table.path, number, reason))
            continue
        try:
            cells = _cells(text, delimiter, table.path, number)
            if not any(c.strip() for c in cells):
                table.skipped.append(SkippedRow(table.path, number, "empty row"))
                continue
            rows.append(_parse_cells(cells, width, layout, table.headers, table.path, number))
            lines.append(number)
        except RecordError as error:
            if on_invalid == "raise":
                raise
            where = f"column {error.column!r}: " if error.column else ""
            table.skipped.append(SkippedRow(table.path, number, where + error.problem))
    return rows, lines


def _parse_cells(cells, width, layout, headers, path, line) -> dict:
    if len(cells) < width:
        raise RecordError(path, line, None, f"{len(cells)} cells; the header has {width} "
                          "or more columns")
    row = {}
    for key, (index, spec, _) in layout.items():
        cell = cells[index].strip()
        if spec.dimension == "text":
            if not cell:
                raise RecordError(path, line, headers[key], "empty cell")
            row[key] = cell
            continue
        try:
            value = float(cell)
        except ValueError:
            problem = "empty cell" if not cell else f"{cell!r} is not a number"
            raise RecordError(path, line, headers[key], problem) from None
        if not math.isfinite(value):
            raise RecordError(path, line, headers[key], f"{cell!r} is not a finite number")
        if spec.positive and value <= 0:
            raise RecordError(path, line, headers[key], f"{spec.key} = {cell} must be > 0")
        row[key] = value
    return row


#: Columns of a testing-machine export: time is optional, displacement and force required.
MACHINE_FIELDS = (
    Field("time", "time", ("t",), required=False),
    Field("displacement", "length", ("position", "extension", "disp", "y")),
    Field("force", "force", ("load",)),
)


def read_machine_record(path, *, names=None, units=None, on_invalid="raise",
                        negate=()) -> Table:
    """Read a testing-machine export: ``displacement`` (mm) and ``force`` (N) columns, and
    ``time`` (s) if present, with at least two rows (a line needs two points).

    Headers ``Position`` / ``Extension`` / ``Disp`` / ``y`` are accepted for displacement
    and ``Load`` for force; see :func:`read_table` for the other parameters.
    """
    return read_table(path, MACHINE_FIELDS, names=names, units=units,
                      on_invalid=on_invalid, negate=negate, min_rows=2)
