"""Plane geometry the cut files are built from: offsets, clipping, perforations, overlap.

Every function takes and returns ``(k, 2)`` float arrays of points in mm. Polygons are
closed implicitly (the last point joins the first) and need not repeat their first point.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "signed_area", "offset_polygon", "clip_convex", "barycentric", "shorten",
    "dashes", "convex_overlap", "mirror_x",
]


def signed_area(polygon) -> float:
    """Area of a simple polygon [mm^2]: positive when its points run counter-clockwise."""
    x, y = np.asarray(polygon, dtype=float).T
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def offset_polygon(polygon, distance: float) -> np.ndarray:
    """Move every edge of a simple polygon outwards by ``distance`` (inwards if negative).

    Corners are mitred: each new corner is where the two moved edges meet, so a triangle
    offset by ``-d`` is the triangle whose sides lie ``d`` inside the original's (it exists
    while ``d`` is less than the inradius). Meant for offsets small against the edges (kerf,
    insets); the caller checks that the result is still the intended shape.

    Parameters
    ----------
    polygon : array_like, shape (k, 2)
    distance : float
        Offset [mm].

    Returns
    -------
    ndarray, shape (k, 2)
    """
    points = np.asarray(polygon, dtype=float)
    if distance == 0.0:
        return points.copy()
    edges = np.roll(points, -1, axis=0) - points
    unit = edges / np.linalg.norm(edges, axis=1, keepdims=True)
    # The outward normal is on the right of a counter-clockwise boundary.
    orientation = 1.0 if signed_area(points) > 0 else -1.0
    normals = orientation * np.column_stack([unit[:, 1], -unit[:, 0]])
    before, after = np.roll(normals, 1, axis=0), normals
    # The mitre point p + d (n1 + n2) / (1 + n1.n2) lies on both moved edges.
    cosine = np.einsum("ij,ij->i", before, after)
    return points + distance * (before + after) / (1.0 + cosine)[:, None]


def clip_convex(polygon, point, normal) -> np.ndarray:
    """Keep the part of a convex polygon where ``(x - point) . normal >= 0``.

    Returns
    -------
    ndarray, shape (m, 2)
        The clipped polygon (``m = 0`` if nothing is left), same orientation.
    """
    points = np.asarray(polygon, dtype=float)
    side = (points - np.asarray(point, float)) @ np.asarray(normal, float)
    kept = []
    for k in range(len(points)):
        j = (k + 1) % len(points)
        if side[k] >= 0.0:
            kept.append(points[k])
        if (side[k] >= 0.0) != (side[j] >= 0.0):
            s = side[k] / (side[k] - side[j])
            kept.append(points[k] + s * (points[j] - points[k]))
    return np.array(kept).reshape(-1, 2)


def barycentric(point, triangle) -> np.ndarray:
    """Barycentric coordinates, shape (3,), of ``point`` in ``triangle`` (shape (3, 2))."""
    a, b, c = np.asarray(triangle, dtype=float)
    lam = np.linalg.solve(np.column_stack([b - a, c - a]), np.asarray(point, float) - a)
    return np.array([1.0 - lam.sum(), lam[0], lam[1]])


def shorten(start, end, at_start: float, at_end: float) -> np.ndarray:
    """The segment ``start -> end`` with ``at_start`` / ``at_end`` mm removed; shape (2, 2)."""
    start, end = np.asarray(start, float), np.asarray(end, float)
    direction = (end - start) / np.linalg.norm(end - start)
    return np.array([start + at_start * direction, end - at_end * direction])


def dashes(start, end, dash: float, tie: float, kerf: float = 0.0) -> list:
    """Perforation of the segment ``start -> end``: cut dashes separated by uncut ties.

    The line begins and ends with a tie at least ``tie`` long (the crease's end points stay
    joined) and the dashes are centred on it. With a kerf, every dash is shortened by
    ``kerf`` so the material left in each tie is still ``tie``.

    Returns
    -------
    list of ndarray, shape (2, 2)
        The dashes; empty if the segment is shorter than ``dash + 2 tie``.
    """
    start, end = np.asarray(start, float), np.asarray(end, float)
    length = float(np.linalg.norm(end - start))
    count = int(np.floor((length - tie) / (dash + tie)))
    if count < 1:
        return []
    first = 0.5 * (length - count * dash - (count - 1) * tie)
    direction = (end - start) / length
    out = []
    for k in range(count):
        a = first + k * (dash + tie) + 0.5 * kerf
        out.append(np.array([start + a * direction, start + (a + dash - kerf) * direction]))
    return out


def convex_overlap(first, second) -> float:
    """How deep two convex polygons overlap [mm] (separating-axis test).

    Returns
    -------
    float
        The smallest overlap of the two polygons' projections over the edge normals of both:
        positive when their interiors intersect, zero or negative when they only touch or are
        apart (then it is minus the gap along the best separating axis).
    """
    polygons = [np.asarray(first, float), np.asarray(second, float)]
    depth = np.inf
    for polygon in polygons:
        edges = np.roll(polygon, -1, axis=0) - polygon
        normals = np.column_stack([edges[:, 1], -edges[:, 0]])
        normals /= np.linalg.norm(normals, axis=1, keepdims=True)
        for normal in normals:
            a, b = (p @ normal for p in polygons)
            depth = min(depth, min(a.max(), b.max()) - max(a.min(), b.min()))
    return float(depth)


def mirror_x(points, axis_x: float) -> np.ndarray:
    """Reflect points in the vertical line ``x = axis_x``; shape of ``points``."""
    out = np.array(points, dtype=float)
    out[..., 0] = 2.0 * axis_x - out[..., 0]
    return out
