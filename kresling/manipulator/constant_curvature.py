"""Jones's constant-curvature map for three tendons (thesis eqns 27-29) and its inverse.

Tendon i sits at radius d and angle ``2 pi (i - 1) / 3`` in a module's base frame (tendon 1
on +x, counter-clockwise seen from +z). An arc is ``(s, kappa, phi)``: arc length [mm],
curvature [1/mm] and the angle of eqn 26, the bend pointing towards ``phi - pi/2``, i.e. to
the shortest tendon. The computations run in the C++ core.
"""

from __future__ import annotations

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, as_integer, as_real

__all__ = ["arc_from_tendons", "tendons_from_arc", "tendon_angles"]


def tendon_angles() -> np.ndarray:
    """Angles of tendons 1, 2, 3 in a module's base frame [rad], shape (3,)."""
    return np.array([_core.kinematics.tendon_angle(i) for i in range(3)])


def _rows(values, name: str) -> tuple[np.ndarray, bool]:
    array = as_float_array(name, values)
    if array.shape == (3,):
        return array[None, :], True
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"{name} has shape {array.shape}: must be (3,) or (n, 3)")
    return array, False


def arc_from_tendons(lengths, d: float = 32.0, N: int = 1) -> np.ndarray:
    """Eqns 27-29: tendon lengths -> arc ``(s, kappa, phi)``.

    Parameters
    ----------
    lengths : array_like, shape (3,) or (n, 3)
        Tendon lengths (l1, l2, l3) of one flexible module [mm], each ``>= 0``.
    d : float, default 32.0
        Tendon radius [mm].
    N : int, default 1
        Straight tendon segments per module.

    Returns
    -------
    ndarray, shape of ``lengths``
        ``s`` [mm], ``kappa`` [1/mm] (>= 0) and ``phi`` [rad] in (-pi, pi] (atan2, so the
        bend points the right way when l2 < l3; ``phi = 0`` for equal tendons).

    Raises
    ------
    ValueError
        For negative or non-finite lengths, and lengths no arc can realise for this ``d``
        (``sqrt(Q) > 3 N d``); batch messages name the row.

    Examples
    --------
    >>> s, kappa, phi = arc_from_tendons([10.0, 40.0, 40.0])   # Appendix E, k = 10
    >>> bool(np.isclose(s * kappa, 2 * np.arcsin(10 / 32))), bool(np.isclose(phi, np.pi / 2))
    (True, True)
    """
    rows, single = _rows(lengths, "lengths")
    out = _core.kinematics.arc_from_tendons(rows, as_real("d", d), as_integer("N", N))
    return out[0] if single else out


def tendons_from_arc(arcs, d: float = 32.0, N: int = 1) -> np.ndarray:
    """Inverse of :func:`arc_from_tendons`: ``(s, kappa, phi)`` -> tendon lengths [mm].

    For N segments, ``l_i = 2 N sin(s kappa / 2N) (1/kappa - d sin(phi - sigma_i))``.

    Parameters
    ----------
    arcs : array_like, shape (3,) or (n, 3)
        ``s >= 0`` [mm], ``kappa >= 0`` [1/mm], ``phi`` [rad], with ``s kappa <= N pi``.
    d, N : see :func:`arc_from_tendons`

    Returns
    -------
    ndarray, shape of ``arcs``
    """
    rows, single = _rows(arcs, "arcs")
    out = _core.kinematics.tendons_from_arc(rows, as_real("d", d), as_integer("N", N))
    return out[0] if single else out
