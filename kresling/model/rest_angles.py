"""Hinges a model cannot start from: rest angles where the hinge is folded flat.

A hinge's angle runs over (0, 360) degrees; at 0 or 360 its two panels lie on each other
(a folded-flat key frame). There the enhanced-linear law's moment is infinite and every
law's angle jumps by 360 degrees as the panels pass through each other, so the first
increment fails. :func:`check_rest_angles` names such hinges before a solve starts.
"""

from __future__ import annotations

import numpy as np

__all__ = ["FLAT_MARGIN_DEG", "check_rest_angles"]

#: A rest angle within this many degrees of 0 or 360 is folded flat.
FLAT_MARGIN_DEG = 1.0


def check_rest_angles(rest, hinges, family, *, source: str = "pattern", listed: int = 5):
    """Refuse hinges whose rest angle is within :data:`FLAT_MARGIN_DEG` of 0 or 360 deg.

    Parameters
    ----------
    rest : ndarray, shape (H,)
        Rest angles [rad].
    hinges : ndarray of int, shape (H, 4)
        Each hinge's nodes; the first two are its axis.
    family : sequence of str, length H
    source : str
        The pattern, for the message.
    listed : int
        How many hinges the message names.

    Raises
    ------
    ValueError
        Naming the hinges (index, axis, family, angle) and the ways out.
    """
    degrees = np.degrees(np.asarray(rest, dtype=float))
    flat = np.flatnonzero((degrees < FLAT_MARGIN_DEG) | (degrees > 360.0 - FLAT_MARGIN_DEG)
                          | ~np.isfinite(degrees))
    if not flat.size:
        return
    names = ", ".join(f"hinge {h} (axis {hinges[h][0]}-{hinges[h][1]}, {family[h]}) at "
                      f"{degrees[h]:.3g} deg" for h in flat[:listed].tolist())
    more = f" and {flat.size - listed} more" if flat.size > listed else ""
    raise ValueError(
        f"{source}: {flat.size} {'hinge is' if flat.size == 1 else 'hinges are'} folded flat "
        f"at rest (within {FLAT_MARGIN_DEG:g} deg of 0 or 360, outside the range (0, 360) "
        f"deg of the spring laws): {names}{more}. The model is stress-free as given, so it "
        "cannot start folded flat: start from a frame where these hinges are open ([pattern] "
        "frame = K, e.g. the flat crease pattern), or unfold the pattern's key frame")
