"""The shipped reference tables as plain numbers: the thesis's Table 3 and the MERLIN2
reference runs of its four paper designs.

These are data, read the same way by every part of the package that compares with the
thesis (the bending analyses, the experimental fits, the report), so they live here, below
all of them. Nothing is computed beyond turning text into numbers.

Examples
--------
>>> from kresling.data import tables
>>> row = tables.thesis_table3()[0]
>>> row["n"], row["Lc"], row["lam"], row["material"], row["K1_exp_mean"]
(8, 30.0, 0.8, 'paper', 3.5)
>>> tables.merlin2_table3_reference()[(8, 30.0, 0.8)]["ratio"]
5.846924
"""

from __future__ import annotations

import csv

import numpy as np

from kresling.data import path

__all__ = ["TABLE3_DESIGNS", "TABLE1_HALF_UNIT", "TABLE3_HALF_UNIT", "thesis_table3",
           "merlin2_table3_reference", "merlin2_model_curves"]

#: The designs of Table 3 as (n, Lc [mm], lambda): the three paper samples and the optimum
#: (the designs of the MERLIN2 reference runs).
TABLE3_DESIGNS = ((8, 30.0, 0.8), (8, 15.0, 0.8), (4, 30.0, 0.7), (10, 15.0, 0.9))

#: Half a unit of the last digit Tables 1 and 3 print (three and two decimals): how far an
#: unrounded value can be from the printed one.
TABLE1_HALF_UNIT = 0.0005
TABLE3_HALF_UNIT = 0.005

_KEYS = ("extended", "contracted", "ratio")

# Column of thesis_table3_bending_stiffness.csv -> key of the rows returned.
_TABLE3_COLUMNS = {"K1_exp_mean_Nm_per_rad": "K1_exp_mean", "K1_exp_sd": "K1_exp_sd",
                   "K0_exp_mean_Nm_per_rad": "K0_exp_mean", "K0_exp_sd": "K0_exp_sd",
                   "ratio_exp": "ratio_exp", "K1_model_Nm_per_rad": "K1_model",
                   "K0_model_Nm_per_rad": "K0_model", "ratio_model": "ratio_model"}


def _number(text: str) -> float:
    return float(text) if text.strip() else float("nan")


def thesis_table3() -> list:
    """The rows of the thesis's Table 3, as printed (K_B in N*m/rad; NaN where it prints
    nothing).

    Returns
    -------
    list of dict
        Per row: ``n`` (int), ``Lc`` [mm], ``lam``, ``R`` [mm], ``material`` (``"paper"`` or
        ``"PET"``); the experiment's ``K1_exp_mean``, ``K1_exp_sd`` (extended, state 1),
        ``K0_exp_mean``, ``K0_exp_sd`` (contracted, state 0) and its printed ratio
        ``ratio_exp``; the model's ``K1_model``, ``K0_model`` and ``ratio_model``.
    """
    rows = []
    with open(path("thesis_table3_bending_stiffness.csv"), newline="") as handle:
        for raw in csv.DictReader(handle):
            row = {"n": int(_number(raw["n"])), "Lc": _number(raw["Lc_mm"]),
                   "lam": _number(raw["lambda"]), "R": _number(raw["R_mm"]),
                   "material": raw["material"]}
            row.update({key: _number(raw[column]) for column, key in _TABLE3_COLUMNS.items()})
            rows.append(row)
    return rows


def merlin2_table3_reference() -> dict:
    """K_B of the MERLIN2 reference runs (5 mm protocol).

    Returns
    -------
    dict
        ``(n, Lc, lam)`` to ``{"extended", "contracted", "ratio"}`` [N*m/rad].
    """
    table = np.genfromtxt(path("merlin2/table3_reference.csv"), delimiter=",", names=True)
    return {(int(r["n"]), float(r["Lc_mm"]), float(r["lambda"])):
            dict(zip(_KEYS, (float(r["Kb_ext_Nm_per_rad"]), float(r["Kb_con_Nm_per_rad"]),
                             float(r["ratio"])))) for r in table}


def merlin2_model_curves() -> dict:
    """Moment-angle curves of the MERLIN2 reference runs shipped with the package.

    Returns
    -------
    dict
        ``(n, Lc, lam)`` to ``{"extended": (angle, moment), "contracted": (...)}``, arrays
        of shape (350,) in rad and N*m, for the four paper designs of Table 3.
    """
    curves = {}
    for (n, Lc, lam) in TABLE3_DESIGNS:
        for state in ("extended", "contracted"):
            name = f"merlin2/fd_n{n}_Lc{Lc:g}_lam{lam:g}_{state}.csv"
            table = np.genfromtxt(path(name), delimiter=",", names=True)
            curves.setdefault((n, float(Lc), lam), {})[state] = (table["angle_rad"],
                                                                 table["moment_Nm"])
    return curves
