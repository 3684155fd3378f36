"""How far a displacement-driven test got: the fraction of its travel reached, for the
results and the paths of the bending and snap-through tests (a run that stopped early is
*partial*, its values fitted to the part that converged)."""

from __future__ import annotations

import math

__all__ = ["travel_fraction"]


def travel_fraction(completed: bool, reached, travel: float) -> float:
    """Fraction of a drive's full ``travel`` reached.

    Parameters
    ----------
    completed : bool
        The run reached the end of its travel (the fraction is then 1).
    reached : float or None
        How far the drive got at its last converged increment (same unit as ``travel``);
        None if no increment converged.
    travel : float
        The drive's full travel; not finite or not positive means unknown.

    Returns
    -------
    float
        1 when completed; 0 when nothing converged or the travel is unknown; otherwise
        ``reached / travel``, at most 1.
    """
    if completed:
        return 1.0
    if reached is None or not (math.isfinite(travel) and travel > 0):
        return 0.0
    return float(min(1.0, reached / travel))
