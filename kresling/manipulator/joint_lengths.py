"""Module ("joint") lengths against the thesis's Table 5.

If the contracted modules act as revolute joints, each module's marker-to-marker length
stays constant while the arm bends. The model predicts exactly that under the protocol (the
chord of a flexible module is the mean tendon length, 30 mm; an extended module is
``2 Le`` = 111.64 mm); Table 5 lists the measured [min, max] of each module per
configuration.
"""

from __future__ import annotations

import csv

import numpy as np

from kresling import data
from kresling.manipulator.markers import MarkerData
from kresling.manipulator.model import Manipulator
from kresling.manipulator.protocol import THESIS_STEPS, pseudo_linkage

__all__ = ["read_table5", "joint_length_table"]


def read_table5() -> list:
    """Table 5 as a list of dicts: ``config`` (str), ``joint`` (1-based), ``state`` (0/1),
    ``min_mm``, ``max_mm`` (the extended rows of (111) give one value: min = max)."""
    with open(data.path("thesis_table5_joint_lengths.csv"), newline="", encoding="utf-8") as f:
        return [{"config": row["config"], "joint": int(row["joint"]), "state": int(row["state"]),
                 "min_mm": float(row["min_mm"]), "max_mm": float(row["max_mm"])}
                for row in csv.DictReader(f)]


def joint_length_table(model: Manipulator, measured: MarkerData | None = None,
                       steps=THESIS_STEPS) -> list:
    """Predicted module lengths beside Table 5's measured ranges (and optionally others).

    Parameters
    ----------
    model : Manipulator
        Must have 3 modules (Table 5's arm).
    measured : MarkerData, optional
        Marker measurements whose module-length ranges are added as ``measured_min_mm`` /
        ``measured_max_mm``.
    steps : array_like
        Protocol steps over which the predicted range is taken.

    Returns
    -------
    list of dict
        One per Table 5 row, with ``predicted_min_mm``, ``predicted_max_mm``,
        ``inside`` (the predicted range lies within Table 5's) and ``outside_by_mm`` (how far
        the predicted range lies outside Table 5's, 0 when inside).
    """
    if model.modules != 3:
        raise ValueError(f"model.modules = {model.modules} is invalid: Table 5 is for 3 modules")
    rows = []
    for row in read_table5():
        lengths = pseudo_linkage(model, row["config"], steps).module_lengths[:, row["joint"] - 1]
        lo, hi = float(lengths.min()), float(lengths.max())
        outside = max(row["min_mm"] - lo, hi - row["max_mm"], 0.0)
        entry = dict(row, predicted_min_mm=lo, predicted_max_mm=hi, inside=outside == 0.0,
                     outside_by_mm=outside)
        if measured is not None and row["config"] in measured.configurations:
            _, measured_lengths = measured.module_lengths(row["config"])
            column = measured_lengths[:, row["joint"] - 1]
            entry.update(measured_min_mm=float(np.min(column)), measured_max_mm=float(np.max(column)))
        rows.append(entry)
    return rows
