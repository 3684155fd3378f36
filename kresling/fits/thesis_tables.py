"""The thesis's experimental tables as shipped data, recomputed.

Table 1 (crease stiffness per run) is read with the same reader a user's table goes
through. Table 3 lists, per design, the experimental K_B (mean ± SD of three trials) in
both states, their ratio, and the model's values; its ratios are recomputed here from its
means, and each listed ratio is checked against the range that rounding of the printed
means allows.
"""

from __future__ import annotations

import csv
import itertools
from dataclasses import dataclass

import numpy as np

from kresling import data
from kresling.fits.bending import model_stiffness
from kresling.fits.crease import CreaseStiffness
from kresling.fits.crease_files import read_stiffness_table
from kresling.fits.statistics import Ratio, Summary, ratio_of_means

__all__ = ["table1", "largest_sd_under_rounding", "Table3Row", "table3", "experiment_vs_model",
           "merlin2_model_curves"]

#: Half a unit of the last digit Tables 1 and 3 print (three and two decimals).
TABLE1_HALF_UNIT = 0.0005
TABLE3_HALF_UNIT = 0.005


def table1(confidence: float = 0.95) -> CreaseStiffness:
    """The thesis's Table 1 (15 runs, five samples) summarized, N/rad."""
    return read_stiffness_table(data.path("thesis_table1_crease_stiffness.csv"),
                                confidence=confidence)


def largest_sd_under_rounding(values, half_unit: float) -> float:
    """Largest sample SD the unrounded values could have had, given the printed ones.

    Each true value lies within ``± half_unit`` of its printed value. The SD is convex in
    the values, so its maximum over that box is at a corner; all ``2^n`` corners are tried
    (n <= 20).

    Parameters
    ----------
    values : array_like, shape (n,)
    half_unit : float

    Returns
    -------
    float
    """
    x = np.asarray(values, dtype=float)
    if x.size > 20:
        raise ValueError(f"{x.size} values: at most 20 (2^n corners are enumerated)")
    corners = np.array(list(itertools.product((-half_unit, half_unit), repeat=x.size)))
    return float((x + corners).std(axis=1, ddof=1).max())


@dataclass(frozen=True)
class Table3Row:
    """One design of Table 3 (K_B in N*m/rad).

    Attributes
    ----------
    n, Lc, lam, material
        The design (Lc in mm) and what it was built from.
    extended, contracted : Summary
        Experimental K_B, mean ± SD of three trials (SD NaN where the thesis gives none).
    ratio_listed : float
        The experimental K_B ratio the thesis prints.
    ratio_of_means : Ratio
        Recomputed: mean(extended) / mean(contracted), with first-order uncertainty.
    ratio_rounding_range : (float, float)
        The ratios the printed (two-decimal) means allow.
    model : dict
        The thesis's model K_B (``"extended"``, ``"contracted"``, ``"ratio"``); NaN where
        it prints none.
    """

    n: int
    Lc: float
    lam: float
    material: str
    extended: Summary
    contracted: Summary
    ratio_listed: float
    ratio_of_means: Ratio
    ratio_rounding_range: tuple
    model: dict

    @property
    def listed_ratio_consistent(self) -> bool:
        """Whether the printed ratio can come from the printed means (rounding allowed)."""
        low, high = self.ratio_rounding_range
        return low - TABLE3_HALF_UNIT <= self.ratio_listed <= high + TABLE3_HALF_UNIT

    @property
    def label(self) -> str:
        return f"n={self.n}, Lc={self.Lc:g} mm, lambda={self.lam:g} ({self.material})"


def _number(text: str) -> float:
    return float(text) if text.strip() else float("nan")


def _state(mean: float, sd: float) -> Summary:
    """Table 3's "mean ± SD of three trials" as a Summary (SE and CI follow from n = 3)."""
    from scipy import stats

    se = sd / np.sqrt(3.0)
    half = float(stats.t.ppf(0.975, 2)) * se
    return Summary(3, mean, sd, se, (mean - half, mean + half), 0.95)


def table3() -> list:
    """The rows of the thesis's Table 3, with their ratios recomputed.

    Returns
    -------
    list of Table3Row
    """
    rows = []
    with open(data.path("thesis_table3_bending_stiffness.csv"), newline="") as handle:
        for raw in csv.DictReader(handle):
            value = {key: _number(text) for key, text in raw.items() if key != "material"}
            extended = _state(value["K1_exp_mean_Nm_per_rad"], value["K1_exp_sd"])
            contracted = _state(value["K0_exp_mean_Nm_per_rad"], value["K0_exp_sd"])
            h = TABLE3_HALF_UNIT
            rounding = ((extended.mean - h) / (contracted.mean + h),
                        (extended.mean + h) / (contracted.mean - h))
            model = {"extended": value["K1_model_Nm_per_rad"],
                     "contracted": value["K0_model_Nm_per_rad"], "ratio": value["ratio_model"]}
            rows.append(Table3Row(int(value["n"]), value["Lc_mm"], value["lambda"],
                                  raw["material"], extended, contracted, value["ratio_exp"],
                                  ratio_of_means(extended, contracted), rounding, model))
    return rows


def experiment_vs_model(model_curves=None) -> list:
    """Table 3's experiment beside the model, one dict per row (K_B in N*m/rad).

    Keys: the design; the experimental means and SDs; ``ratio_exp_listed`` (printed) and
    ``ratio_exp_of_means`` (recomputed, with first-order ``_sd`` and ``_se``), and whether the
    printed one follows from the means; the thesis's model values; and K_B through the
    origin of ``model_curves`` (NaN for designs it lacks).

    Parameters
    ----------
    model_curves : dict, optional
        ``(n, Lc, lam)`` to ``{"extended": (angle, moment), "contracted": ...}`` (rad, N*m),
        paper specimens only. Default: :func:`merlin2_model_curves`.
    """
    model_curves = merlin2_model_curves() if model_curves is None else model_curves
    lines = []
    for row in table3():
        curve = model_curves.get((row.n, row.Lc, row.lam)) if row.material == "paper" else None
        K1, K0 = ((model_stiffness(*curve["extended"]), model_stiffness(*curve["contracted"]))
                  if curve else (float("nan"), float("nan")))
        ratio = row.ratio_of_means
        lines.append({
            "n": row.n, "Lc_mm": row.Lc, "lambda": row.lam, "material": row.material,
            "K1_exp": row.extended.mean, "K1_exp_sd": row.extended.sd,
            "K0_exp": row.contracted.mean, "K0_exp_sd": row.contracted.sd,
            "ratio_exp_listed": row.ratio_listed, "ratio_exp_of_means": ratio.value,
            "ratio_exp_sd": ratio.sd, "ratio_exp_se": ratio.se,
            "listed_ratio_consistent": row.listed_ratio_consistent,
            "K1_model_thesis": row.model["extended"], "K0_model_thesis": row.model["contracted"],
            "ratio_model_thesis": row.model["ratio"], "K1_model_curve": K1,
            "K0_model_curve": K0, "ratio_model_curve": K1 / K0,
        })
    return lines


def merlin2_model_curves() -> dict:
    """Moment-angle curves of the MERLIN2 reference runs shipped with the package.

    Returns
    -------
    dict
        ``(n, Lc, lam)`` to ``{"extended": (angle, moment), "contracted": (...)}``, arrays
        of shape (350,) in rad and N*m: the model curve of the four paper designs of
        Table 3 until the package's own bending analysis supplies one.
    """
    curves = {}
    for (n, Lc, lam) in ((8, 30, 0.8), (8, 15, 0.8), (4, 30, 0.7), (10, 15, 0.9)):
        for state in ("extended", "contracted"):
            name = f"merlin2/fd_n{n}_Lc{Lc}_lam{lam}_{state}.csv"
            table = np.genfromtxt(data.path(name), delimiter=",", names=True)
            curves.setdefault((n, float(Lc), lam), {})[state] = (table["angle_rad"],
                                                                 table["moment_Nm"])
    return curves
