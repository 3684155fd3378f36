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
    return lowest_in_cluster(len(points), close_pairs(points, tolerance))


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
    cuts = [[0.0, 1.0] for _ in range(len(segments))]
    starts, directions = segments[:, 0], segments[:, 1] - segments[:, 0]
    lengths2 = np.maximum((directions ** 2).sum(axis=1), 1e-300)
    for i in range(len(segments)):
        p, d = starts[i], directions[i]
        # Proper crossings of segment i with the later ones.
        q, e = starts[i + 1:], directions[i + 1:]
        denominator = d[0] * e[:, 1] - d[1] * e[:, 0]
        offset = q - p
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (offset[:, 0] * e[:, 1] - offset[:, 1] * e[:, 0]) / denominator
            s = (offset[:, 0] * d[1] - offset[:, 1] * d[0]) / denominator
        crossing = (np.abs(denominator) > 1e-12 * np.sqrt(lengths2[i] * lengths2[i + 1:])) & \
            (t > 0) & (t < 1) & (s > 0) & (s < 1)
        for j, ti, sj in zip(np.flatnonzero(crossing) + i + 1, t[crossing], s[crossing]):
            cuts[i].append(float(ti))
            cuts[j].append(float(sj))
        # Endpoints of any segment lying on segment i (T-junctions, overlaps).
        along = ((ends - p) @ d) / lengths2[i]
        foot = p + along[:, None] * d
        near = (np.linalg.norm(ends - foot, axis=1) <= tolerance) & (along > 0) & (along < 1)
        near[2 * i:2 * i + 2] = False
        cuts[i].extend(along[near].tolist())
    pieces, origin = [], []
    for i, ts in enumerate(cuts):
        ts = np.unique(ts)
        points = starts[i] + ts[:, None] * directions[i]
        pieces.extend(zip(points[:-1], points[1:]))
        origin.extend([i] * (len(ts) - 1))
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
