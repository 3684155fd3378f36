"""The thesis's experimental tables as shipped data, recomputed.

Table 1 (crease stiffness per run) is read with the same reader a user's table goes
through. Table 3 lists, per design, the experimental K_B (mean ± SD of three trials) in
both states, their ratio, and the model's values; its ratios are recomputed here from its
means, and each listed ratio is checked against the range that rounding of the printed
means allows. The printed numbers themselves come from :mod:`kresling.data.tables`.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from scipy import stats

from kresling import data
from kresling.data.tables import (TABLE1_HALF_UNIT, TABLE3_HALF_UNIT, merlin2_model_curves,
                                  thesis_table3)
from kresling.fits.bending import model_stiffness
from kresling.fits.crease import CreaseStiffness
from kresling.fits.crease_files import read_stiffness_table
from kresling.fits.statistics import Ratio, Summary, ratio_of_means

__all__ = ["table1", "largest_sd_under_rounding", "Table3Row", "table3", "experiment_vs_model",
           "merlin2_model_curves", "TABLE1_HALF_UNIT", "TABLE3_HALF_UNIT"]


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


def _state(mean: float, sd: float) -> Summary:
    """Table 3's "mean ± SD of three trials" as a Summary (SE and CI follow from n = 3)."""
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
    for value in thesis_table3():
        extended = _state(value["K1_exp_mean"], value["K1_exp_sd"])
        contracted = _state(value["K0_exp_mean"], value["K0_exp_sd"])
        h = TABLE3_HALF_UNIT
        rounding = ((extended.mean - h) / (contracted.mean + h),
                    (extended.mean + h) / (contracted.mean - h))
        model = {"extended": value["K1_model"], "contracted": value["K0_model"],
                 "ratio": value["ratio_model"]}
        rows.append(Table3Row(value["n"], value["Lc"], value["lam"], value["material"],
                              extended, contracted, value["ratio_exp"],
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
