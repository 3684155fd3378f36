"""Output helpers shared by the subcommands: JSON that never contains NaN, aligned text
tables, and a library logger shown on stderr while a command runs."""

from __future__ import annotations

import json
import logging
import math
import sys
from contextlib import contextmanager

import numpy as np


def _plain(value):
    if isinstance(value, dict):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, (np.bool_, bool)):
        return bool(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, (np.floating, float)):
        value = float(value)
        if not math.isfinite(value):
            # JSON has no NaN; a non-finite number here is a bug upstream, so say so.
            raise ValueError(f"non-finite number {value} cannot be written as JSON")
        return value
    return value


def print_json(obj) -> None:
    """Print ``obj`` as one JSON object (numpy scalars and arrays converted)."""
    print(json.dumps(_plain(obj), indent=2, allow_nan=False))


def print_table(rows, headers) -> None:
    """Print ``rows`` (sequences of cells) under ``headers``, columns aligned (no rows: the
    headers alone)."""
    cells = [[_format(c) for c in row] for row in rows]
    widths = [max([len(h)] + [len(r[i]) for r in cells]) for i, h in enumerate(headers)]
    print("  ".join(h.ljust(w) for h, w in zip(headers, widths)).rstrip())
    print("  ".join("-" * w for w in widths))
    for row in cells:
        print("  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip())


def _format(cell) -> str:
    if isinstance(cell, (float, np.floating)):
        return f"{float(cell):.10g}"
    return str(cell)


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
