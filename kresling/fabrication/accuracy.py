"""How exactly a flat crease pattern folds onto the 3D cell: the lengths of its lines against
the 3D creases, the rigidity of its faces when folded, and the closure of its strip.

Each function returns the worst deviation [mm], 0 up to floating-point rounding for an exact
pattern.

Examples
--------
>>> from kresling import Design
>>> from kresling.fabrication import crease_pattern
>>> pattern = crease_pattern(Design(10, 0.9, 15.0))
>>> closure_error(pattern, 1) < 1e-9 and isometry_error(pattern, 0) < 1e-9
True
"""

from __future__ import annotations

import itertools

import numpy as np

from kresling.fabrication.pattern import CreasePattern

__all__ = ["edge_length_errors", "isometry_error", "closure_error"]


def edge_length_errors(pattern: CreasePattern) -> dict:
    """Worst flat length of each crease family against the 3D model's value.

    Returns
    -------
    dict of str to (float, float)
        ``kind -> (flat length farthest from the reference, reference)`` [mm] for valleys
        (Vg, eqn 6), mountains and the seam (Mg, eqn 7) and tab creases (P, eqn 1).
    """
    d = pattern.design
    out = {}
    for kind, reference in (("valley", d.Vg), ("mountain", d.Mg), ("seam", d.Mg), ("tab", d.P)):
        lengths = np.linalg.norm(np.diff(pattern.points[pattern.edges_of_kind(kind)], axis=1)[:, 0],
                                 axis=1)
        out[kind] = (float(lengths[np.argmax(np.abs(lengths - reference))]), reference)
    return out


def isometry_error(pattern: CreasePattern, state) -> float:
    """Largest change of any distance between two corners of one face on folding [mm]."""
    folded = pattern.folded(state)
    worst = 0.0
    for face in pattern.faces:
        for a, b in itertools.combinations(face, 2):
            flat = np.linalg.norm(pattern.points[a] - pattern.points[b])
            worst = max(worst, abs(np.linalg.norm(folded[a] - folded[b]) - flat))
    return float(worst)


def closure_error(pattern: CreasePattern, state) -> float:
    """Distance between the strip's last edge ``B_n T_n`` and its first ``B_0 T_0`` once
    folded [mm] (0 when the strip closes)."""
    folded = pattern.folded(state)
    (b0, bn), (t0, tn) = folded[pattern.bottom[[0, -1]]], folded[pattern.top[[0, -1]]]
    return float(max(np.linalg.norm(bn - b0), np.linalg.norm(tn - t0)))
