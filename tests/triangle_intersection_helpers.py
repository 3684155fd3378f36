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
    (N, 3): O(T^2) with a box prefilter, for the small meshes of the tests."""
    x = np.asarray(x, dtype=float)
    tri = np.asarray(triangles)
    lo, hi = x[tri].min(axis=1), x[tri].max(axis=1)
    pairs = []
    for i in range(len(tri)):
        overlap = np.all((lo[i + 1:] <= hi[i]) & (lo[i] <= hi[i + 1:]), axis=1)
        for j in np.nonzero(overlap)[0] + i + 1:
            if triangles_intersect(x, tuple(tri[i]), tuple(tri[j])):
                pairs.append((i, int(j)))
    return pairs
