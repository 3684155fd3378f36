"""The thesis's conclusions about its parametric study, as functions of a sweep's table.

Sections 3.4-3.5 conclude: for every n the K_B ratio (and the facet-angle ratio, and the
snap-through force) is largest at the highest lambda and the lowest Lc of the grid; they
rise with lambda and fall with Lc; the maximum K_B ratio rises with n and levels off at
n = 8-10; the optimum is n = 10, Lc = 15 mm, lambda = 0.9. These functions measure each of
those on a table, so the report and the tests judge them the same way.
"""

from __future__ import annotations

import numpy as np
from scipy import stats

from kresling.sweeps.table import SweepTable

__all__ = ["corner", "maxima_by_n", "rising_steps", "leveling", "monotone_fraction",
           "rank_correlation"]


def corner(table: SweepTable, n: int) -> tuple:
    """The grid corner of highest lambda and lowest Lc for ``n``: ``(Lc, lam)``."""
    part = table.where(n=n)
    return float(part["Lc"].min()), float(part["lam"].max())


def maxima_by_n(table: SweepTable, metric: str) -> dict:
    """``{n: row}`` of the largest ``metric`` (ok rows) for each n, in increasing n."""
    return {n: table.best(metric, n=n) for n in sorted({int(k) for k in table["n"]})}


def rising_steps(values) -> int:
    """How many consecutive pairs of ``values`` increase."""
    values = np.asarray(values, float)
    return int((np.diff(values) > 0).sum())


def leveling(values) -> float:
    """The last step's gain as a fraction of the first step's: small when a sequence levels
    off (NaN with fewer than three values or no first gain)."""
    values = np.asarray(values, float)
    if len(values) < 3 or values[1] == values[0]:
        return float("nan")
    return float((values[-1] - values[-2]) / (values[1] - values[0]))


def monotone_fraction(table: SweepTable, metric: str, axis: str, sign: int) -> float:
    """Fraction of neighbouring grid pairs along ``axis`` ("Lc" or "lam") where ``metric``
    moves with ``sign`` (+1 rises, -1 falls) as ``axis`` increases, over every n.

    Pairs with a failed design are left out; NaN if there are none.
    """
    moves = []
    for n in sorted({int(k) for k in table["n"]}):
        _, _, values = table.grid(metric, n)  # values[lam, Lc]
        step = np.diff(values, axis=1 if axis == "Lc" else 0)
        moves.append(np.sign(step[np.isfinite(step)]))
    moves = np.concatenate(moves) if moves else np.array([])
    return float((moves == sign).mean()) if moves.size else float("nan")


def rank_correlation(table: SweepTable, a: str, b: str, n: int) -> float:
    """Spearman rank correlation of columns ``a`` and ``b`` over the ok designs of ``n``."""
    part = table.where(n=n)
    keep = part.ok & np.isfinite(part[a]) & np.isfinite(part[b])
    return float(stats.spearmanr(part[a][keep], part[b][keep]).statistic)
