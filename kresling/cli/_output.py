"""Output helpers shared by the subcommands: JSON that never contains NaN, aligned text
tables with degrees beside radians, a library logger shown on stderr while a command runs,
library errors reworded with the command's option names, and checks that output files and
folders can be written before any work starts."""

from __future__ import annotations

import json
import logging
import math
import re
import sys
from contextlib import contextmanager

import numpy as np


def _plain(value, infinite_as_text=False):
    if isinstance(value, dict):
        return {str(k): _plain(v, infinite_as_text) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v, infinite_as_text) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist(), infinite_as_text)
    if isinstance(value, (np.bool_, bool)):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, (np.floating, float)):
        value = float(value)
        if math.isinf(value) and infinite_as_text:
            return "inf" if value > 0 else "-inf"
        if not math.isfinite(value):
            # JSON has no NaN; a non-finite number here is a bug upstream, so say so.
            raise ValueError(f"non-finite number {value} cannot be written as JSON")
        return value
    return value


def print_json(obj, infinite_as_text=False) -> None:
    """Print ``obj`` as one JSON object (numpy scalars and arrays converted).

    JSON has no infinity: with ``infinite_as_text`` an infinite number is written as the
    string ``"inf"`` (or ``"-inf"``), for quantities that are infinite by definition;
    otherwise it is an error, as NaN always is (callers write None for a missing value).
    """
    print(json.dumps(_plain(obj, infinite_as_text), indent=2, allow_nan=False))


#: A number below this fraction of the largest one in its row or its column prints as 0:
#: the table shows 10 significant digits, so it is rounding noise there (a coordinate of
#: -5.7e-16 mm beside ones of 100 mm).
NOISE = 1e-12


def _is_number(cell) -> bool:
    return isinstance(cell, (float, np.floating)) and math.isfinite(cell)


def _cleaned(rows) -> list:
    """``rows`` with the numbers below :data:`NOISE` of their row's or column's largest
    magnitude set to 0.0."""
    rows = [list(row) for row in rows]
    columns = max((len(r) for r in rows), default=0)
    column_scale = [max((abs(float(r[i])) for r in rows if i < len(r) and _is_number(r[i])),
                        default=0.0) for i in range(columns)]
    for row in rows:
        row_scale = max((abs(float(c)) for c in row if _is_number(c)), default=0.0)
        for i, cell in enumerate(row):
            if _is_number(cell) and abs(float(cell)) < NOISE * max(row_scale, column_scale[i]):
                row[i] = 0.0
    return rows


def print_table(rows, headers) -> None:
    """Print ``rows`` (sequences of cells) under ``headers``, columns aligned (no rows: the
    headers alone). Floats get 10 significant digits; one below 1e-12 of the largest float
    in its row or column prints as 0 (rounding noise at that precision)."""
    cells = [[_format(c) for c in row] for row in _cleaned(rows)]
    widths = [max([len(h)] + [len(r[i]) for r in cells]) for i, h in enumerate(headers)]
    print("  ".join(h.ljust(w) for h, w in zip(headers, widths)).rstrip())
    print("  ".join("-" * w for w in widths))
    for row in cells:
        print("  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip())


def degrees(radians) -> str:
    """An angle in rad as degrees for a table column beside it (4 significant digits)."""
    if radians is None:
        return ""
    return f"{math.degrees(float(radians)):.4g}"


def _format(cell) -> str:
    if isinstance(cell, (float, np.floating)):
        return f"{float(cell):.10g}"
    return str(cell)


@contextmanager
def cli_names(names: dict):
    """Within the block, a ``ValueError`` from the library names the command's options, not
    the library's keywords: ``names`` maps keyword to option (``{"deflection_angle":
    "--deflection-rad"}``)."""
    try:
        yield
    except ValueError as error:
        message = str(error)
        for keyword, option in names.items():
            message = re.sub(rf"(?<![\w-]){re.escape(keyword)}\b", option, message)
        if message == str(error):
            raise
        raise ValueError(message) from None


@contextmanager
def log_to_stderr(name: str, prefix: str, level=logging.INFO):
    """Show the records of logger ``name`` (``level`` and above) on stderr, each line
    starting with ``[prefix]``, for the duration of the block."""
    logger = logging.getLogger(name)
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter(f"[{prefix}] %(message)s"))
    previous_level = logger.level
    logger.addHandler(handler)
    logger.setLevel(level)
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.setLevel(previous_level)


def check_output_file(option: str, path) -> None:
    """Check, before any computation, that the file ``path`` given to ``option`` can be
    written: its folder exists and is writable, and ``path`` is not a folder.

    Raises
    ------
    ValueError
        Naming the option, the path and why it cannot be written.
    """
    import os
    from pathlib import Path

    path = Path(path)
    if path.is_dir():
        raise ValueError(f"{option} {str(path)!r}: cannot write there, it is a folder")
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.exists():
        raise ValueError(f"{option} {str(path)!r}: cannot write there, the folder "
                         f"{str(folder)!r} does not exist")
    if not folder.is_dir():
        raise ValueError(f"{option} {str(path)!r}: cannot write there, {str(folder)!r} is "
                         f"not a folder")
    if not os.access(folder, os.W_OK | os.X_OK) or (path.exists()
                                                     and not os.access(path, os.W_OK)):
        raise ValueError(f"{option} {str(path)!r}: cannot write there, no permission")


def check_output_folder(option: str, path) -> None:
    """Check, before any computation, that the folder ``path`` given to ``option`` exists
    or can be made (its nearest existing ancestor is a writable folder).

    Raises
    ------
    ValueError
        Naming the option, the path and why it cannot be used.
    """
    import os
    from pathlib import Path

    path = Path(path)
    if path.exists() and not path.is_dir():
        raise ValueError(f"{option} {str(path)!r}: not a folder (a file of that name exists)")
    ancestor = path
    while not ancestor.exists() and ancestor != ancestor.parent:
        ancestor = ancestor.parent
    if not ancestor.is_dir():
        raise ValueError(f"{option} {str(path)!r}: cannot make it, {str(ancestor)!r} is not a "
                         f"folder")
    if not os.access(ancestor, os.W_OK | os.X_OK):
        raise ValueError(f"{option} {str(path)!r}: no permission to write in {str(ancestor)!r}")
