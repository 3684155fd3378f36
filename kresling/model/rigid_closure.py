"""Whether fold angles can be reached with rigid panels: loop closure at interior vertices.

Going once round an interior vertex of a flat pattern, the panels turn about its creases in
turn; with rigid panels the last panel comes back onto the first only if the rotations
compose to the identity,

    R(d_1, rho_1) R(d_2, rho_2) ... R(d_k, rho_k) = I,

with ``d_i`` the creases' directions in the flat pattern, in angular order round the vertex,
and ``rho_i`` their fold angles (the composition of rotations about the moving creases,
written with the flat pattern's axes). The angle of the product is the vertex's *closure
error*: 0 where the fold angles are those of a rigidly folded state, and otherwise how far
the panels round the vertex must bend or stretch for the creases to reach those angles. A
pattern folded flat (every crease at +-180 deg) closes where Kawasaki's theorem holds.

Only vertices whose every crease has a fold angle are checked: a crease left free (a facet
edge, a crease not driven) lets the vertex close at any angles of the others.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.io.planar_graph import plane_coordinates

__all__ = ["RigidClosure", "rigid_closure"]


@dataclass(frozen=True)
class RigidClosure:
    """Closure errors of the interior vertices whose creases all have fold angles.

    Attributes
    ----------
    vertices : ndarray of int, shape (C,)
        The vertices checked.
    error_deg : ndarray, shape (C,)
        Each one's closure error [deg], in [0, 180].
    """

    vertices: np.ndarray
    error_deg: np.ndarray

    def incompatible(self, tolerance_deg: float) -> np.ndarray:
        """The vertices whose closure error exceeds ``tolerance_deg`` [deg]."""
        return self.vertices[self.error_deg > tolerance_deg]

    def words(self, tolerance_deg: float, checked: str) -> str:
        """The incompatible vertices in words ("" for none): "not those of any rigidly
        folded state at K of the C interior vertices <checked> (going round vertex V, the
        panels fail to close by E deg)"."""
        r = self.report(tolerance_deg)
        if not r["incompatible"]:
            return ""
        return (f"not those of any rigidly folded state at {r['incompatible']} of the "
                f"{r['vertices_checked']} interior vertices {checked} (going round vertex "
                f"{r['worst_vertex']}, the panels fail to close by {r['worst_deg']:.3g} deg)")

    def report(self, tolerance_deg: float) -> dict:
        """``vertices_checked``, ``incompatible`` (errors above ``tolerance_deg``),
        ``tolerance_deg``, ``worst_deg`` and ``worst_vertex`` (None when none checked)."""
        worst = int(np.argmax(self.error_deg)) if len(self.error_deg) else None
        return {"vertices_checked": int(len(self.vertices)),
                "incompatible": int(np.count_nonzero(self.error_deg > tolerance_deg)),
                "tolerance_deg": float(tolerance_deg),
                "worst_deg": None if worst is None else float(self.error_deg[worst]),
                "worst_vertex": None if worst is None else int(self.vertices[worst])}


def _rotations(axes: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """Rotation matrices about unit ``axes`` (shape (..., 3)) by ``angles`` [rad] (shape
    (...)), by Rodrigues' formula; shape (..., 3, 3)."""
    x, y, z = axes[..., 0], axes[..., 1], axes[..., 2]
    zero = np.zeros_like(x)
    cross = np.stack([np.stack([zero, -z, y], -1), np.stack([z, zero, -x], -1),
                      np.stack([-y, x, zero], -1)], -2)
    s, c = np.sin(angles)[..., None, None], np.cos(angles)[..., None, None]
    return np.eye(3) + s * cross + (1.0 - c) * (cross @ cross)


def rigid_closure(vertices, edges, fold_angle_deg, faces) -> RigidClosure | None:
    """Closure errors of a flat pattern's interior vertices at given fold angles.

    Parameters
    ----------
    vertices : array_like, shape (V, 2) or (V, 3)
        The flat pattern [any length unit].
    edges : array_like of int, shape (E, 2)
    fold_angle_deg : array_like, shape (E,)
        Each edge's fold angle [deg] (FOLD's sign: positive valley); NaN for an edge whose
        angle is free (a boundary, a cut, a facet edge, a crease not driven).
    faces : sequence of sequence of int
        The pattern's faces: a vertex is interior where as many faces as edges meet.

    Returns
    -------
    RigidClosure, or None when the pattern is not flat (its plane's coordinates unknown).
    """
    points = np.asarray(vertices, dtype=float)
    if points.shape[1] == 3:
        points = plane_coordinates(points)
        if points is None:
            return None
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    angles = np.radians(np.asarray(fold_angle_deg, dtype=float))
    count = len(points)
    edge_count = np.bincount(edges.ravel(), minlength=count)
    face_count = np.bincount(np.fromiter((v for f in faces for v in f), dtype=np.int64),
                             minlength=count)
    free = np.zeros(count, dtype=bool)
    np.logical_or.at(free, edges[~np.isfinite(angles)].ravel(), True)
    checked = np.flatnonzero((edge_count > 0) & (edge_count == face_count) & ~free)
    # Each checked vertex's creases, outward, in angular order round it.
    ends = np.concatenate([edges, edges[:, ::-1]])
    crease = np.concatenate([np.arange(len(edges))] * 2)
    keep = np.isin(ends[:, 0], checked)
    ends, crease = ends[keep], crease[keep]
    direction = points[ends[:, 1]] - points[ends[:, 0]]
    turn = np.arctan2(direction[:, 1], direction[:, 0])
    order = np.lexsort((turn, ends[:, 0]))
    ends, crease, direction = ends[order], crease[order], direction[order]
    axes = np.zeros((len(direction), 3))
    with np.errstate(invalid="ignore", divide="ignore"):
        axes[:, :2] = direction / np.linalg.norm(direction, axis=1, keepdims=True)
    rotations = _rotations(axes, angles[crease])
    start = np.searchsorted(ends[:, 0], checked)
    degree = edge_count[checked]
    error = np.zeros(len(checked))
    for k in np.unique(degree):   # one product per degree, over all its vertices at once
        group = np.flatnonzero(degree == k)
        product = np.broadcast_to(np.eye(3), (len(group), 3, 3))
        for i in range(k):
            product = product @ rotations[start[group] + i]
        # The product's angle from its cosine and sine alike (the trace's arccosine alone
        # would lose half the digits near 0).
        cosine = (np.trace(product, axis1=1, axis2=2) - 1.0) / 2.0
        skew = np.stack([product[:, 2, 1] - product[:, 1, 2], product[:, 0, 2] - product[:, 2, 0],
                         product[:, 1, 0] - product[:, 0, 1]], axis=1)
        error[group] = np.degrees(np.arctan2(np.linalg.norm(skew, axis=1) / 2.0, cosine))
    # A vertex with a crease of no length has no direction to turn about: not checked.
    known = np.isfinite(error)
    return RigidClosure(vertices=checked[known], error_deg=error[known])
