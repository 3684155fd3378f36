"""Element kernels of the bar-and-hinge model, one element at a time (C++ core).

These are the functions the assembly calls for every element, exposed for checking and
teaching: each returns the value and its exact first and second derivatives. Node order
for hinges is ``(a, b, c, d)``: axis ``a -> b``, wings ``c`` and ``d``. Units: mm, N, rad.
"""

from __future__ import annotations

import numpy as np

from kresling import _core
from kresling.laws import BAR_LAWS, FOLD_LIMITS, SPRING_LAWS

__all__ = ["dihedral_angle", "dihedral_angle_derivatives", "bar_response", "hinge_response",
           "spring_law"]


def _point(name, x):
    x = np.asarray(x, dtype=float)
    if x.shape != (3,) or not np.isfinite(x).all():
        raise ValueError(f"{name} = {x.tolist()} is invalid: must be 3 finite coordinates")
    return x


def dihedral_angle(a, b, c, d) -> float:
    """Dihedral angle in [0, 2 pi): pi when flat (docs/model.md, 'Hinges') [rad]."""
    return _core.elements.dihedral_angle(*(_point(n, x) for n, x in zip("abcd", (a, b, c, d))))


def dihedral_angle_derivatives(a, b, c, d):
    """Angle, gradient (12,) and Hessian (12, 12) with respect to ``(a, b, c, d)``."""
    angle, gradient, hessian = _core.elements.dihedral_angle_derivatives(
        *(_point(n, x) for n, x in zip("abcd", (a, b, c, d))))
    return angle, np.asarray(gradient), np.asarray(hessian)


def bar_response(x1, x2, *, rest_length, modulus, area=1.0, law="ogden"):
    """Energy [N*mm], internal force (6,) [N] and tangent (6, 6) [N/mm] of one bar."""
    if law not in BAR_LAWS:
        raise ValueError(f"law = {law!r} is invalid: must be one of {sorted(BAR_LAWS)}")
    energy, force, stiffness = _core.elements.bar_response(
        _point("x1", x1), _point("x2", x2), float(area), float(rest_length), BAR_LAWS[law],
        float(modulus))
    return energy, np.asarray(force), np.asarray(stiffness)


def hinge_response(a, b, c, d, *, stiffness, rest_angle, length, law="enhanced_linear",
                   limits=FOLD_LIMITS):
    """Energy, internal force (12,), tangent (12, 12), angle and moment of one hinge.

    ``stiffness`` is per unit length [N/rad]; the moment is ``length * M(angle)`` [N*mm].
    """
    if law not in SPRING_LAWS:
        raise ValueError(f"law = {law!r} is invalid: must be one of {sorted(SPRING_LAWS)}")
    energy, force, tangent, angle, moment = _core.elements.hinge_response(
        *(_point(n, x) for n, x in zip("abcd", (a, b, c, d))), float(stiffness),
        float(rest_angle), float(length), SPRING_LAWS[law], float(limits[0]), float(limits[1]))
    return energy, np.asarray(force), np.asarray(tangent), angle, moment


def spring_law(theta, *, rest_angle, stiffness, law="enhanced_linear",
               limits=FOLD_LIMITS):
    """Moment, dM/dtheta and energy per unit hinge length at angle(s) ``theta`` [rad].

    Returns three arrays shaped like ``theta``.
    """
    if law not in SPRING_LAWS:
        raise ValueError(f"law = {law!r} is invalid: must be one of {sorted(SPRING_LAWS)}")
    theta = np.asarray(theta, dtype=float)
    out = np.array([_core.elements.spring_law(SPRING_LAWS[law], t, float(rest_angle),
                                              float(stiffness), float(limits[0]), float(limits[1]))
                    for t in theta.ravel()]).reshape(theta.shape + (3,))
    return out[..., 0], out[..., 1], out[..., 2]
