"""Crease-test files: a table of per-run stiffnesses shaped like the thesis's Table 1, or a
list of runs pointing at raw testing-machine records with the video markers beside them.

Table of stiffnesses (``sample, run, stiffness`` with a unit; ``length`` optional)::

    sample,run,length_mm,stiffness_N_per_rad
    1,1,32.60,0.045

List of runs: one row per run, the machine record's file (relative to the list), the
measured ``Lp`` and crease length ``W``, and the (x, y) of the vertex, upper and lower
markers in the first (1) and last (2) video frame, in pixels or any one length unit::

    sample,run,record,Lp_mm,W_mm,vertex_x1_px,vertex_y1_px,upper_x1_px,...,lower_y2_px
    1,1,s1_r1.csv,32.6,152.4,400.0,700.0,...
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from kresling.fits.crease import (MARKERS, CreaseRun, CreaseStiffness, fit_crease_runs,
                                  panel_angles, summarize_crease)
from kresling.fits.records import (Field, RecordError, read_header, read_machine_record,
                                   read_table)
from kresling.fits.units import split_header

__all__ = ["STIFFNESS_FIELDS", "RUN_FIELDS", "MARKER_KEYS", "read_stiffness_table",
           "read_crease_runs", "fit_crease_file"]

STIFFNESS_FIELDS = (
    Field("sample", "text"),
    Field("run", "text"),
    Field("stiffness", "crease stiffness", ("k", "kf")),
    Field("length", "length", ("Lp",), required=False, positive=True),
)

#: Marker columns of the first frame, then the last: vertex_x1, vertex_y1, upper_x1, ...
MARKER_KEYS = tuple(f"{marker}_{axis}{frame}" for frame in (1, 2) for marker in MARKERS
                    for axis in "xy")

RUN_FIELDS = (
    Field("sample", "text"),
    Field("run", "text"),
    Field("record", "text", ("file",)),
    Field("Lp", "length", positive=True),
    Field("W", "length", ("crease_length",), positive=True),
    *(Field(key, "image") for key in MARKER_KEYS),
)


def read_stiffness_table(path, *, names=None, units=None, on_invalid="raise",
                         confidence: float = 0.95) -> CreaseStiffness:
    """Summarize a table of per-run stiffnesses (the shape of the thesis's Table 1).

    Parameters are those of :func:`~kresling.fits.records.read_table`; ``confidence`` is
    the level of the confidence intervals.
    """
    table = read_table(path, STIFFNESS_FIELDS, names=names, units=units,
                       on_invalid=on_invalid, min_rows=2)
    return summarize_crease(table.columns["sample"], table.columns["run"],
                            table.columns["stiffness"], confidence=confidence,
                            skipped=table.skipped, source=table.path)


def _record_path(listing: Path, name: str, table, row) -> Path:
    """The record ``name`` of a list of runs, in the list's folder or below it: an absolute
    path or one leaving that folder (``../``) is refused, so a list can only point at the
    records shipped beside it."""
    relative = Path(name)
    folder = listing.resolve().parent
    try:
        resolved = (folder / relative).resolve()
    except (ValueError, OSError) as error:  # a NUL byte, a symlink loop
        raise table.error(row, "record", f"{name!r} is not a file name ({error})") from None
    if relative.is_absolute() or (resolved != folder and folder not in resolved.parents):
        raise table.error(row, "record", f"{name!r} is invalid: must be a file in the list's "
                          f"folder {str(folder)!r} or below it (a relative path without '..')")
    return listing.parent / relative


def read_crease_runs(path, *, names=None, units=None, on_invalid="raise", record_names=None,
                     record_units=None, negate=()):
    """Read a list of runs and the machine record of each.

    Parameters
    ----------
    path : str or Path
        The list of runs (columns :data:`RUN_FIELDS`).
    names, units, on_invalid
        For the list, as in :func:`~kresling.fits.records.read_table`; ``on_invalid`` also
        applies to the records.
    record_names, record_units, negate
        For the machine records (:func:`~kresling.fits.records.read_machine_record`).

    Returns
    -------
    runs : list of CreaseRun
    skipped : list of SkippedRow
        Lines passed over in the list and in every record.
    """
    table = read_table(path, RUN_FIELDS, names=names, units=units, on_invalid=on_invalid)
    marker_units = {table.units[key] for key in MARKER_KEYS}
    if len(marker_units) > 1:
        raise table.error(None, MARKER_KEYS, f"marker columns mix units {sorted(marker_units)}: "
                          "use one unit for all")
    runs, skipped = [], list(table.skipped)
    for row in range(len(table)):
        record_path = _record_path(Path(path), table.columns["record"][row], table, row)
        if not record_path.is_file():
            raise table.error(row, "record", f"no record file {str(record_path)!r}")
        record = read_machine_record(record_path, names=record_names, units=record_units,
                                     on_invalid=on_invalid, negate=negate)
        skipped += record.skipped
        markers = np.array([table.columns[key][row] for key in MARKER_KEYS]).reshape(2, 3, 2)
        try:
            panel_angles(markers[0], markers[1])
        except ValueError as error:
            raise table.error(row, MARKER_KEYS, str(error)) from None
        runs.append(CreaseRun(table.columns["sample"][row], table.columns["run"][row],
                              record.columns["displacement"], record.columns["force"],
                              markers[0], markers[1], float(table.columns["Lp"][row]),
                              float(table.columns["W"][row]),
                              source=f"{table.path}, line {table.lines[row]} "
                                     f"(record {record_path.name})"))
    return runs, skipped


def fit_crease_file(path, *, confidence: float = 0.95, **options) -> CreaseStiffness:
    """Crease stiffness from a file of either shape (see the module docstring).

    A file with a ``record`` column is a list of runs (:func:`read_crease_runs`, then
    :func:`~kresling.fits.crease.fit_crease_runs`); one with a ``stiffness`` column is a
    table of per-run stiffnesses (:func:`read_stiffness_table`). ``options`` go to the
    reader.
    """
    line, header = read_header(path)
    names = options.get("names") or {}
    if any(split_header(cell, (names.get("record", "record"), "file")) for cell in header):
        runs, skipped = read_crease_runs(path, **options)
        return fit_crease_runs(runs, confidence=confidence, skipped=skipped, source=str(path))
    if "stiffness" in names or any(split_header(cell, ("stiffness", "k", "kf"))
                                   for cell in header):
        for_records = sorted(k for k in ("record_names", "record_units", "negate")
                             if options.pop(k, None))
        if for_records:
            raise ValueError(f"{path}: {', '.join(for_records)} apply to the records of a "
                             "list of runs, and this is a table of stiffnesses")
        return read_stiffness_table(path, confidence=confidence, **options)
    raise RecordError(path, line, None, f"not a crease file: expected a 'stiffness' column "
                      f"(table of per-run stiffnesses) or a 'record' column (list of runs); "
                      f"headers: {header}")
