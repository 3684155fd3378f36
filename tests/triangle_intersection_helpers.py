"""An independent triangle-triangle intersection test for the contact checks: two
triangles that are not coplanar intersect exactly when an edge of one crosses the other
(each end of their common segment lies on an edge of one of them), and a segment crosses a
triangle when Moller and Trumbore's ray-triangle parameters are all in range. Written
apart from the solver's kernels (no distance, no CCD) so that it can catch their faults."""

from __future__ import annotations

import numpy as np


def segment_crosses_triangle(p, q, a, b, c) -> bool:
    """Whether the segment p q meets the triangle (a, b, c) (Moller-Trumbore)."""
    d = q - p
    e1, e2 = b - a, c - a
    h = np.cross(d, e2)
    det = e1 @ h
    if abs(det) < 1e-14 * np.linalg.norm(d) * np.linalg.norm(e1) * np.linalg.norm(e2):
        return False  # parallel to the plane: measure zero for a moving mesh
    s = p - a
    u = (s @ h) / det
    qv = np.cross(s, e1)
    v = (d @ qv) / det
    t = (e2 @ qv) / det
    return u >= 0.0 and v >= 0.0 and u + v <= 1.0 and 0.0 <= t <= 1.0


def triangles_intersect(x, s, t) -> bool:
    """Whether triangles ``s`` and ``t`` (node triples) at positions ``x`` meet anywhere
    but at the nodes they share. Two triangles that share an edge meet only on it unless
    they are coplanar (folded exactly flat onto each other), which a barrier never lets
    happen; they are reported as not intersecting. Of two triangles that share one node,
    an edge from that node lies off the other's plane but at the node itself (the node is
    a corner of the other), so it meets the other only there: only the edges opposite the
    shared node are tested. (Testing those edges from the node would ask whether a
    crossing sits at parameter 0, which rounding decides for edges nearly in the other's
    plane.)"""
    shared = set(s) & set(t)
    if len(shared) >= 2:
        return False
    for one, other in ((s, t), (t, s)):
        for i in range(3):
            p, q = one[i], one[(i + 1) % 3]
            if p in shared or q in shared:
                continue
            if segment_crosses_triangle(x[p], x[q], *x[list(other)]):
                return True
    return False


def intersecting_pairs(x, triangles) -> list:
    """Every pair (i, j), i < j, of ``triangles`` (T, 3) that intersects at positions ``x``
    (N, 3): O(T^2) with a box prefilter, for the small meshes of the tests. The answer is
    :func:`triangles_intersect`'s for every pair; a vectorised form of the same test, with a
    margin far above its rounding, only leaves out the pairs it clears with certainty."""
    x = np.asarray(x, dtype=float)
    tri = np.asarray(triangles)
    lo, hi = x[tri].min(axis=1), x[tri].max(axis=1)
    distinct = len(tri) == 0 or bool(np.all((tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2])
                                            & (tri[:, 0] != tri[:, 2])))
    first, second = [], []
    for i in range(len(tri)):
        overlap = np.all((lo[i + 1:] <= hi[i]) & (lo[i] <= hi[i + 1:]), axis=1)
        second.append(np.nonzero(overlap)[0] + i + 1)
        first.append(np.full(len(second[-1]), i))
    first = np.concatenate(first) if first else np.zeros(0, dtype=int)
    second = np.concatenate(second) if second else np.zeros(0, dtype=int)
    if distinct:   # all the boxes' pairs at once
        kept = _may_intersect(x, tri[first], tri[second])
        first, second = first[kept], second[kept]
    return [(int(i), int(j)) for i, j in zip(first, second)
            if triangles_intersect(x, tuple(tri[i]), tuple(tri[j]))]


#: The prefilter's margin, relative to the size of each quantity's rounding error (a few
#: machine epsilons of the products of the lengths involved): it never clears a pair the
#: exact test would find.
_MARGIN = 1e-9


def _may_intersect(x, s, t) -> np.ndarray:
    """For the pairs of triangles ``s`` and ``t`` (P, 3), each of distinct nodes: False
    where :func:`triangles_intersect` certainly answers False, True where it may not."""
    meets = s[:, :, None] == t[:, None, :]               # (P, 3, 3): s[a] is t[b]
    s_shared, t_shared = meets.any(axis=2), meets.any(axis=1)
    maybe = np.zeros(len(t), dtype=bool)
    for k in range(3):
        k1 = (k + 1) % 3
        # An edge of each s against its t, then an edge of each t against its s.
        tested = ~(s_shared[:, k] | s_shared[:, k1])
        crosses = _may_cross(x[s[:, k]], x[s[:, k1]], x[t[:, 0]], x[t[:, 1]], x[t[:, 2]])
        maybe |= tested & crosses
        tested = ~(t_shared[:, k] | t_shared[:, k1])
        crosses = _may_cross(x[t[:, k]], x[t[:, k1]], x[s[:, 0]], x[s[:, 1]], x[s[:, 2]])
        maybe |= tested & crosses
    return maybe & (s_shared.sum(axis=1) < 2)


def _may_cross(p, q, a, b, c) -> np.ndarray:
    """segment_crosses_triangle over rows (broadcast), False only where it is certainly
    False: each parameter clears its range by more than _MARGIN times its rounding bound,
    or det is below half the parallel threshold."""
    d, e1, e2, s = q - p, b - a, c - a, p - a
    h, qv = np.cross(d, e2), np.cross(s, e1)
    det = np.sum(e1 * h, axis=-1)
    nd, n1, n2, ns = (np.sqrt(np.sum(w * w, axis=-1)) for w in (d, e1, e2, s))
    parallel = np.abs(det) < 0.5e-14 * nd * n1 * n2
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.sum(s * h, axis=-1) / det
        v = np.sum(d * qv, axis=-1) / det
        t = np.sum(e2 * qv, axis=-1) / det
        bound = (ns * nd * n2 + nd * ns * n1 + n2 * ns * n1 + n1 * nd * n2) / np.abs(det)
        m = _MARGIN * bound * (1.0 + np.abs(u) + np.abs(v) + np.abs(t))
        clear = (u < -m) | (v < -m) | (u + v > 1.0 + 2 * m) | (t < -m) | (t > 1.0 + m)
    return ~(parallel | clear)
