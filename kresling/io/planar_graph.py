"""Planar graphs of creases: the faces a flat crease pattern's edges enclose, and line
drawings (an SVG's strokes) snapped into a planar pattern.

Both work in the plane of a flat pattern (2D coordinates). Faces are the bounded regions of
the edge graph, found by walking round each vertex in angular order; they come out
counter-clockwise, so their normals point towards +z of that plane.
"""

from __future__ import annotations

import numpy as np

from kresling.io.close_pairs import close_pairs, lowest_in_cluster

__all__ = ["faces_from_edges", "simple_faces", "plane_coordinates", "planarize", "merge_points"]


def plane_coordinates(vertices: np.ndarray, tolerance: float = 1e-6):
    """2D coordinates of a flat pattern in its own plane, or None if it is not flat.

    Parameters
    ----------
    vertices : ndarray, shape (N, 3)
    tolerance : float
        Largest distance from the best-fit plane, as a fraction of the pattern's size.

    Returns
    -------
    ndarray, shape (N, 2) or None
        ``(x, y)`` itself when every z is equal (so faces are counter-clockwise about +z);
        otherwise the coordinates along two axes of the best-fit plane.
    """
    vertices = np.asarray(vertices, dtype=float)
    if np.ptp(vertices[:, 2]) == 0.0:
        return vertices[:, :2].copy()
    centred = vertices - vertices.mean(axis=0)
    size = float(np.linalg.norm(np.ptp(vertices, axis=0)))
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    if np.abs(centred @ vt[2]).max() > tolerance * size:
        return None
    return centred @ vt[:2].T


def faces_from_edges(points: np.ndarray, edges: np.ndarray) -> list:
    """The bounded faces of a planar straight-line graph.

    Parameters
    ----------
    points : ndarray, shape (N, 2)
    edges : ndarray of int, shape (E, 2)
        Distinct vertex pairs that cross only at shared vertices.

    Returns
    -------
    list of list of int
        Each bounded face's vertices, counter-clockwise, in order of its lowest half-edge.
        Dangling edges (to a vertex of degree 1, repeatedly) bound no face and are left out;
        the outer boundary of each connected component (clockwise) is left out.
    """
    points = np.asarray(points, dtype=float)
    neighbours = [set() for _ in range(len(points))]
    for u, v in np.asarray(edges, dtype=np.int64).reshape(-1, 2).tolist():
        neighbours[u].add(v)
        neighbours[v].add(u)
    leaves = [v for v, n in enumerate(neighbours) if len(n) == 1]
    while leaves:                     # prune dangling edges: they enclose nothing
        v = leaves.pop()
        for u in neighbours[v]:
            neighbours[u].discard(v)
            if len(neighbours[u]) == 1:
                leaves.append(u)
        neighbours[v] = set()
    order = []
    for v, near in enumerate(neighbours):
        near = np.fromiter(near, dtype=np.int64, count=len(near))
        angles = np.arctan2(points[near, 1] - points[v, 1], points[near, 0] - points[v, 0])
        order.append(near[np.argsort(angles, kind="stable")].tolist())
    position = [{w: k for k, w in enumerate(ring)} for ring in order]
    seen, faces = set(), []
    for u in range(len(points)):
        for v in order[u]:
            if (u, v) in seen:
                continue
            face, a, b = [], u, v
            while (a, b) not in seen:
                seen.add((a, b))
                face.append(a)
                ring = order[b]
                # The face lies left of a -> b: at b turn to the neighbour just clockwise of a.
                a, b = b, ring[(position[b][a] - 1) % len(ring)]
            if _signed_area(points[face]) > 0.0:
                faces.append(face)
    return faces


def simple_faces(points: np.ndarray, edges: np.ndarray):
    """The bounded faces of a planar graph, with the edges that bound none dropped.

    A drawing's face walk can meet a vertex twice: along an edge with the same face on both
    sides (a crease that links an island of strokes to the rest, or ends inside a panel
    past a vertex), or where the face's outline touches itself at a corner. The first kind
    of edge bounds nothing: it is dropped and the faces found again. The second kind of
    face is no simple polygon (it wraps round what it touches); it is returned as it is, for
    the caller to refuse.

    Parameters
    ----------
    points : ndarray, shape (N, 2)
    edges : ndarray of int, shape (E, 2)

    Returns
    -------
    faces : list of list of int
        Counter-clockwise.
    dropped : list of int
        The indices (into ``edges``) of the edges dropped, each inside one face.
    """
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    keep = np.ones(len(edges), dtype=bool)
    index = {(min(u, v), max(u, v)): k for k, (u, v) in enumerate(edges.tolist())}
    while True:
        faces = faces_from_edges(points, edges[keep])
        inside = set()
        for face in faces:
            if len(set(face)) == len(face):
                continue
            sides = set(zip(face, face[1:] + face[:1]))
            inside.update(index[(min(u, v), max(u, v))] for u, v in sides if (v, u) in sides)
        if not inside:
            return faces, np.flatnonzero(~keep).tolist()
        keep[sorted(inside)] = False


def _signed_area(corners: np.ndarray) -> float:
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))


def merge_points(points: np.ndarray, tolerance: float):
    """Cluster points closer than ``tolerance``.

    Parameters
    ----------
    points : ndarray, shape (P, D)
    tolerance : float
        > 0, in the points' unit.

    Returns
    -------
    representative : ndarray of int, shape (P,)
        The lowest index of each point's cluster: points chained by distances up to
        ``tolerance`` form one cluster.
    """
    points = np.asarray(points, dtype=float)
    if not len(points):
        return np.zeros(0, dtype=np.intp)
    # Exact repeats first (a segment's end is every segment's end at that vertex): the
    # distinct points alone are searched for close pairs, where repeats would crowd the
    # search. Clusters are the same, repeats being 0 apart.
    distinct, inverse = np.unique(points, axis=0, return_inverse=True)
    inverse = inverse.reshape(-1)
    cluster = lowest_in_cluster(len(distinct), close_pairs(distinct, tolerance))[inverse]
    lowest = np.full(len(distinct), len(points), dtype=np.intp)
    np.minimum.at(lowest, cluster, np.arange(len(points)))
    return lowest[cluster]


def _expanded(first: np.ndarray, stop: np.ndarray):
    """Every (row, column) with column in [first[row], stop[row]), rows in order."""
    counts = np.maximum(stop - first, 0)
    rows = np.repeat(np.arange(len(first)), counts)
    columns = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    return rows, first[rows] + columns


def _overlapping_boxes(low: np.ndarray, high: np.ndarray, margin: float):
    """The pairs (i, j), i < j, of boxes (corners ``low``, ``high``, shape (S, 2)) that
    overlap once widened by ``margin``: a sweep along x, then y checked."""
    order = np.argsort(low[:, 0], kind="stable")
    left = low[order, 0]
    stop = np.searchsorted(left, high[order, 0] + 2 * margin, side="right")
    a, b = _expanded(np.arange(1, len(order) + 1), stop)
    a, b = order[a], order[b]
    keep = (low[b, 1] <= high[a, 1] + 2 * margin) & (low[a, 1] <= high[b, 1] + 2 * margin)
    a, b = a[keep], b[keep]
    return np.minimum(a, b), np.maximum(a, b)


def _ends_in_boxes(points: np.ndarray, low: np.ndarray, high: np.ndarray):
    """The pairs (box, point) with the point in the box (corners ``low``, ``high``)."""
    order = np.argsort(points[:, 0], kind="stable")
    x = points[order, 0]
    box, at = _expanded(np.searchsorted(x, low[:, 0], side="left"),
                        np.searchsorted(x, high[:, 0], side="right"))
    point = order[at]
    inside = (points[point, 1] >= low[box, 1]) & (points[point, 1] <= high[box, 1])
    return box[inside], point[inside]


def planarize(segments: np.ndarray, tolerance: float):
    """Snap line segments into a planar straight-line graph.

    Endpoints closer than ``tolerance`` are merged, segments are split where they cross or
    where a vertex lies on them (within ``tolerance``), and edges that end up between the
    same two vertices are kept once (the first in input order).

    Parameters
    ----------
    segments : ndarray, shape (S, 2, 2)
        Start and end point of each segment.
    tolerance : float
        Snapping distance (> 0), in the segments' unit.

    Returns
    -------
    points : ndarray, shape (N, 2)
    edges : ndarray of int, shape (E, 2)
    origin : ndarray of int, shape (E,)
        The input segment each edge is a piece of.
    """
    segments = np.asarray(segments, dtype=float).reshape(-1, 2, 2)
    ends = segments.reshape(-1, 2)
    starts, directions = segments[:, 0], segments[:, 1] - segments[:, 0]
    lengths2 = np.maximum((directions ** 2).sum(axis=1), 1e-300)
    low, high = segments.min(axis=1), segments.max(axis=1)
    # Proper crossings, of the pairs i < j whose boxes overlap.
    i, j = _overlapping_boxes(low, high, tolerance)
    p, d, q, e = starts[i], directions[i], starts[j], directions[j]
    denominator = d[:, 0] * e[:, 1] - d[:, 1] * e[:, 0]
    offset = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (offset[:, 0] * e[:, 1] - offset[:, 1] * e[:, 0]) / denominator
        s = (offset[:, 0] * d[:, 1] - offset[:, 1] * d[:, 0]) / denominator
    crossing = (np.abs(denominator) > 1e-12 * np.sqrt(lengths2[i] * lengths2[j])) & \
        (t > 0) & (t < 1) & (s > 0) & (s < 1)
    # Endpoints of any other segment lying on segment k (T-junctions, overlaps), of those in
    # its box widened by the tolerance.
    k, end = _ends_in_boxes(ends, low - tolerance, high + tolerance)
    other = end // 2 != k
    k, end = k[other], end[other]
    relative = ends[end] - starts[k]
    along = (relative[:, 0] * directions[k, 0] + relative[:, 1] * directions[k, 1]) / lengths2[k]
    gap = ends[end] - (starts[k] + along[:, None] * directions[k])
    near = (np.sqrt(gap[:, 0] ** 2 + gap[:, 1] ** 2) <= tolerance) & (along > 0) & (along < 1)
    count = len(segments)
    cut_segment = np.concatenate([np.arange(count), np.arange(count), i[crossing], j[crossing],
                                  k[near]])
    cut_at = np.concatenate([np.zeros(count), np.ones(count), t[crossing], s[crossing],
                             along[near]])
    order = np.lexsort((cut_at, cut_segment))
    cut_segment, cut_at = cut_segment[order], cut_at[order]
    repeated = np.zeros(len(order), dtype=bool)
    repeated[1:] = (cut_segment[1:] == cut_segment[:-1]) & (cut_at[1:] == cut_at[:-1])
    cut_segment, cut_at = cut_segment[~repeated], cut_at[~repeated]
    cut_points = starts[cut_segment] + cut_at[:, None] * directions[cut_segment]
    piece = np.flatnonzero(cut_segment[1:] == cut_segment[:-1])   # from cut piece to piece + 1
    pieces = np.stack([cut_points[piece], cut_points[piece + 1]], axis=1)
    origin = cut_segment[piece].tolist()
    pieces = np.asarray(pieces, dtype=float).reshape(-1, 2, 2)
    flat = pieces.reshape(-1, 2)
    representative = merge_points(flat, tolerance)
    kept, number = np.unique(representative, return_inverse=True)
    points = flat[kept]
    pairs = number.reshape(-1, 2)
    edges, edge_origin, seen = [], [], set()
    for (u, v), source in zip(pairs.tolist(), origin):
        key = (min(u, v), max(u, v))
        if u == v or key in seen:
            continue
        seen.add(key)
        edges.append((u, v))
        edge_origin.append(source)
    return (points, np.asarray(edges, dtype=np.int64).reshape(-1, 2),
            np.asarray(edge_origin, dtype=np.int64))
