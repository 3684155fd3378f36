"""Measured marker positions and their comparison with the model (figures 4.13-4.15).

A marker file is a CSV with the columns ``config, step, marker, x, y``: the configuration
(``101``: one digit per module, base first), the protocol step k (0 = rest), the marker
(1 = base, j + 1 = end of module j) and its position [mm] relative to the base marker in the
thesis's plot coordinates ``(x, y) = (-x_model, -z_model)`` (the arm hangs down from its base
plate; the plane is that of tendon 1). Other columns are ignored.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kresling._validation import as_integer, csv_records
from kresling.manipulator.forward import marker_distances
from kresling.manipulator.model import Manipulator, configuration_name, parse_configuration
from kresling.manipulator.protocol import pseudo_linkage

__all__ = ["MarkerData", "MarkerComparison", "read_markers", "write_markers", "compare_markers",
           "COLUMNS"]

#: Required columns of a marker file, in the order :func:`write_markers` writes them.
COLUMNS = ("config", "step", "marker", "x", "y")


@dataclass(frozen=True)
class MarkerData:
    """Marker positions, one row per (configuration, step, marker).

    Attributes
    ----------
    config : ndarray of str, shape (n,)
        Configuration names, e.g. ``"101"``.
    step : ndarray of int, shape (n,)
    marker : ndarray of int, shape (n,)
        1 = base, j + 1 = end of module j.
    xy : ndarray, shape (n, 2)
        Positions in the thesis's plot coordinates [mm].
    """

    config: np.ndarray
    step: np.ndarray
    marker: np.ndarray
    xy: np.ndarray

    @property
    def configurations(self) -> list:
        """Configuration names present, sorted."""
        return sorted(set(self.config.tolist()))

    def select(self, config: str) -> "MarkerData":
        """Rows of one configuration, sorted by step and marker."""
        rows = np.flatnonzero(self.config == config)
        rows = rows[np.lexsort((self.marker[rows], self.step[rows]))]
        return MarkerData(self.config[rows], self.step[rows], self.marker[rows], self.xy[rows])

    def module_lengths(self, config: str) -> tuple[np.ndarray, np.ndarray]:
        """Marker-to-marker distances of one configuration per step.

        Returns
        -------
        steps : ndarray, shape (k,)
            Steps at which every marker was measured.
        lengths : ndarray, shape (k, m)
            [mm]
        """
        part = self.select(config)
        modules = len(config)
        steps, lengths = [], []
        for step in np.unique(part.step):
            rows = part.step == step
            if sorted(part.marker[rows].tolist()) == list(range(1, modules + 2)):
                xy = part.xy[rows][np.argsort(part.marker[rows])]
                steps.append(step)
                lengths.append(marker_distances(xy))
        return np.array(steps, dtype=int), np.array(lengths).reshape(len(steps), modules)


def _fail(source: str, line: int, column: str, message: str):
    raise ValueError(f"{source}, line {line}, column {column!r}: {message}")


def _number(text: str, source: str, line: int, column: str) -> float:
    try:
        value = float(text)
    except ValueError:
        _fail(source, line, column, f"{text!r} is not a number")
    if not math.isfinite(value):
        _fail(source, line, column, f"{text!r} is not a finite number")
    return value


def _integer(text: str, source: str, line: int, column: str, minimum: int, maximum=None) -> int:
    value = _number(text, source, line, column)
    if value != int(value) or value < minimum or (maximum is not None and value > maximum):
        upper = f" and <= {maximum}" if maximum is not None else ""
        _fail(source, line, column, f"{text!r} is invalid: must be an integer >= {minimum}{upper}")
    return int(value)


def read_markers(path, modules: int = 3) -> MarkerData:
    """Read a marker CSV (see the module docstring).

    Parameters
    ----------
    path : str or Path
    modules : int, default 3
        m; configurations must have m digits and markers run 1..m + 1.

    Returns
    -------
    MarkerData

    Raises
    ------
    ValueError
        For missing columns, and for cells that are not numbers, unknown configurations,
        markers or steps out of range, or repeated (config, step, marker) rows; the message
        gives the file, line and column.
    """
    modules = as_integer("modules", modules, minimum=1)
    path = Path(path)
    source = path.name
    with open(path, newline="", encoding="utf-8", errors="replace") as handle:
        records = csv_records(handle, source)
        first = next(records, None)
        header = [h.strip() for h in (first[1] if first else [])]
        missing = [c for c in COLUMNS if c not in header]
        if missing:
            raise ValueError(f"{source}: missing column(s) {', '.join(repr(c) for c in missing)}; "
                             f"the header must name {', '.join(COLUMNS)} (found {header})")
        position = {name: header.index(name) for name in COLUMNS}
        config, step, marker, xy, seen = [], [], [], [], {}
        for line, row in records:
            if not row:
                continue  # a blank line, as csv.DictReader skips it
            cells = {c: (row[k] if k < len(row) else "").strip() for c, k in position.items()}
            try:
                name = configuration_name(parse_configuration(cells["config"], modules))
            except ValueError:
                _fail(source, line, "config", f"{cells['config']!r} is not a configuration of "
                      f"{modules} modules (one 0/1 digit per module, base first, e.g. '101')")
            key = (name, _integer(cells["step"], source, line, "step", 0),
                   _integer(cells["marker"], source, line, "marker", 1, modules + 1))
            if key in seen:
                _fail(source, line, "marker", f"repeats config {key[0]}, step {key[1]}, marker "
                      f"{key[2]} of line {seen[key]}")
            seen[key] = line
            config.append(key[0]), step.append(key[1]), marker.append(key[2])
            xy.append([_number(cells["x"], source, line, "x"), _number(cells["y"], source, line, "y")])
    return MarkerData(np.array(config, dtype=str), np.array(step, dtype=int),
                      np.array(marker, dtype=int), np.array(xy, dtype=float).reshape(-1, 2))


def write_markers(path, data: MarkerData, decimals: int = 4) -> Path:
    """Write ``data`` as a marker CSV (positions rounded to ``decimals`` places of a mm)."""
    path = Path(path)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(COLUMNS)
        for c, s, m, (x, y) in zip(data.config, data.step, data.marker, data.xy):
            writer.writerow([c, int(s), int(m), f"{x:.{decimals}f}", f"{y:.{decimals}f}"])
    return path


@dataclass(frozen=True)
class MarkerComparison:
    """Measured against predicted markers, one row per measurement.

    Attributes
    ----------
    config, step, marker : ndarray, shape (n,)
    measured, predicted : ndarray, shape (n, 2)
        Thesis plot coordinates [mm].
    error : ndarray, shape (n,)
        Euclidean distance [mm] (figure 4.14).
    length_from_base : ndarray, shape (n,)
        Predicted length of the arm from the base to the marker, the sum of the predicted
        marker-to-marker module lengths before it [mm].
    normalized_error : ndarray, shape (n,)
        ``error / length_from_base`` (figure 4.15); NaN for the base marker (length 0).
    """

    config: np.ndarray
    step: np.ndarray
    marker: np.ndarray
    measured: np.ndarray
    predicted: np.ndarray
    error: np.ndarray
    length_from_base: np.ndarray
    normalized_error: np.ndarray

    def grid(self, config: str, normalized: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """Errors of one configuration as (steps, markers) for plotting.

        Returns
        -------
        steps : ndarray, shape (k,)
        errors : ndarray, shape (k, m + 1)
            [mm] or dimensionless; NaN where a marker was not measured.
        """
        rows = self.config == config
        steps = np.unique(self.step[rows])
        values = (self.normalized_error if normalized else self.error)[rows]
        out = np.full((steps.size, len(config) + 1), np.nan)
        out[np.searchsorted(steps, self.step[rows]), self.marker[rows] - 1] = values
        return steps, out

    def summary(self) -> dict:
        """Per configuration: mean and max error [mm] and max normalised error (non-base)."""
        out = {}
        for config in sorted(set(self.config.tolist())):
            rows = self.config == config
            tip = rows & (self.marker > 1)
            out[config] = {"mean_error_mm": float(self.error[rows].mean()),
                           "max_error_mm": float(self.error[rows].max()),
                           "max_normalized_error": float(np.max(self.normalized_error[tip]))
                           if tip.any() else 0.0}
        return out


def compare_markers(model: Manipulator, measured: MarkerData) -> MarkerComparison:
    """Compare measured markers with the protocol's predictions (section 4.3).

    Parameters
    ----------
    model : Manipulator
    measured : MarkerData

    Returns
    -------
    MarkerComparison
    """
    n = measured.step.size
    predicted = np.empty((n, 2))
    length = np.empty(n)
    for config in measured.configurations:
        rows = np.flatnonzero(measured.config == config)
        steps = np.unique(measured.step[rows])
        run = pseudo_linkage(model, config, steps)
        at = np.searchsorted(steps, measured.step[rows])
        predicted[rows] = run.plot_markers[at, measured.marker[rows] - 1]
        length[rows] = run.path_lengths[at, measured.marker[rows] - 1]
    error = np.linalg.norm(measured.xy - predicted, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        normalized = np.where(length > 0, error / np.where(length > 0, length, 1.0), np.nan)
    return MarkerComparison(measured.config, measured.step, measured.marker, measured.xy,
                            predicted, error, length, normalized)
