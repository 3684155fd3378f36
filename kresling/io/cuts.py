"""Cuts and coincident vertices: FOLD's ``C`` edges separate the faces either side of them,
and two vertices at one point are either the two sides of a cut or a mistake.

FOLD 1.2 says a cut (``C``) edge stands for one boundary edge per face along it, with the
faces separated. :func:`separate_cuts` makes that explicit: around every vertex on a cut,
the faces joined to one another through edges that are not cut form one group, and each
group but the first gets its own copy of the vertex. A slit whose two ends stay joined to
the rest of the sheet (its end vertices' faces still connected round them) duplicates no
vertex: its faces share only the slit's end points, so the model keeps the edge's bar and
drops its hinge. :func:`check_duplicate_vertices` refuses two vertices of a flat pattern at
one point unless both lie on cut edges (the two sides of a cut, as :func:`separate_cuts`
writes them): a pattern written in a problem file, whose node numbers the problem uses. The
file readers merge a vertex written twice instead, and keep cuts drawn as two boundaries
(:mod:`kresling.io.coincident_vertices`).
"""

from __future__ import annotations

import numpy as np

from kresling.io.pattern import Pattern
from kresling.io.planar_graph import merge_points, plane_coordinates

__all__ = ["DUPLICATE_TOLERANCE", "separate_cuts", "coincident_twins", "check_duplicate_vertices"]

#: Two vertices closer than this fraction of the pattern's size (the diagonal of its
#: bounding box) are at one point.
DUPLICATE_TOLERANCE = 1e-7


def _sides(face):
    return list(zip(face, face[1:] + face[:1]))


def _groups_round(vertex: int, faces_here: list, faces, cut: set) -> list:
    """Faces at ``vertex`` grouped by the uncut edges at ``vertex`` they share."""
    group = {f: f for f in faces_here}

    def root(f):
        while group[f] != f:
            group[f] = group[group[f]]
            f = group[f]
        return f

    by_edge = {}
    for f in faces_here:
        for u, v in _sides(faces[f]):
            if vertex in (u, v):
                key = (min(u, v), max(u, v))
                if key not in cut:
                    by_edge.setdefault(key, []).append(f)
    for sharing in by_edge.values():
        for f in sharing[1:]:
            group[root(f)] = root(sharing[0])
    roots = {}
    for f in faces_here:
        roots.setdefault(root(f), []).append(f)
    return list(roots.values())


def separate_cuts(pattern):
    """The pattern with the faces along its cut (``C``) edges separated.

    Parameters
    ----------
    pattern : Pattern

    Returns
    -------
    Pattern
        ``pattern`` itself if nothing is separated. Otherwise the same vertices, then one
        copy of a vertex for each extra group of faces round it (in vertex order), at the
        same place in every frame; faces renumbered; edges: those still sides of faces, in
        their order, then the sides with a copied corner (with the assignment and fold angle
        of the edge they copy), so each side of a cut is a ``C`` edge.
    """
    cut = {(min(u, v), max(u, v)) for (u, v), a in zip(pattern.edges.tolist(),
                                                       pattern.edges_assignment) if a == "C"}
    if not cut:
        return pattern
    faces = [list(face) for face in pattern.faces]
    at = {}
    for f, face in enumerate(faces):
        for v in face:
            at.setdefault(v, []).append(f)
    on_cut = sorted({v for edge in cut for v in edge})
    copies = []                              # (original vertex, faces given the copy)
    for vertex in on_cut:
        for group in _groups_round(vertex, at.get(vertex, []), faces, cut)[1:]:
            copies.append((vertex, group))
    if not copies:
        return pattern
    count = pattern.num_vertices
    for k, (vertex, group) in enumerate(copies):
        for f in group:
            faces[f] = [count + k if v == vertex else v for v in faces[f]]
    originals = np.array([v for v, _ in copies], dtype=np.int64)
    vertices = np.vstack([pattern.vertices, pattern.vertices[originals]])
    frames = tuple(np.vstack([frame, frame[originals]]) for frame in pattern.frames)
    edges, letters, angles = _split_edges(pattern, faces, originals)
    try:
        return Pattern(vertices, tuple(tuple(f) for f in faces), edges, letters, angles, frames,
                       pattern.source)
    except ValueError as error:   # what separating made of the file's faces: name the file
        raise ValueError(f"{pattern.source or 'pattern'}: separating the faces along its cut "
                         f"(C) edges: {error}") from None


def _split_edges(pattern, faces, originals):
    """The pattern's edges, then one per side of a face that has a copied corner (with the
    assignment and fold angle of the edge it copies)."""
    count = pattern.num_vertices
    index = {(min(u, v), max(u, v)): k for k, (u, v) in enumerate(pattern.edges.tolist())}
    edges = [tuple(e) for e in pattern.edges.tolist()]
    letters = list(pattern.edges_assignment)
    angles = list(pattern.edges_fold_angle)
    placed = set(index)
    for face in faces:
        for u, v in _sides(face):
            key = (min(u, v), max(u, v))
            if key in placed:
                continue
            a, b = (w if w < count else int(originals[w - count]) for w in (u, v))
            source = index[(min(a, b), max(a, b))]
            placed.add(key)
            edges.append((u, v))
            letters.append(pattern.edges_assignment[source])
            angles.append(pattern.edges_fold_angle[source])
    # An edge whose faces all moved to copies of its ends is left out.
    sides = {(min(u, v), max(u, v)) for face in faces for u, v in _sides(face)}
    keep = [k for k, (u, v) in enumerate(edges) if (min(u, v), max(u, v)) in sides]
    return (np.asarray([edges[k] for k in keep], dtype=np.int64).reshape(-1, 2),
            tuple(letters[k] for k in keep), np.asarray([angles[k] for k in keep], dtype=float))


def _unfolded(vertices, faces) -> bool:
    """Flat, with every face's signed area of one sign (no face folded over)."""
    flat = plane_coordinates(vertices)
    if flat is None:
        return False
    signs = set()
    by_size = {}
    for face in faces:
        by_size.setdefault(len(face), []).append(face)
    for group in by_size.values():                   # in bulk: one array per face size
        corners = flat[np.array(group)]              # (F, k, 2)
        x, y = corners[..., 0], corners[..., 1]
        twice_area = (x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y).sum(axis=1)
        signs.update(np.sign(twice_area).tolist())
    return len(signs - {0.0}) <= 1


def coincident_twins(vertices, faces, tolerance=DUPLICATE_TOLERANCE) -> list:
    """The vertices of an unfolded pattern's faces that lie at another's point.

    Parameters
    ----------
    vertices : ndarray, shape (N, 3)
        Coordinates [mm].
    faces : sequence of sequence of int
    tolerance : float
        As a fraction of the size (bounding-box diagonal) of the faces' vertices.

    Returns
    -------
    list of (int, int, float)
        ``(one, other, gap)`` for every vertex ``other`` within ``tolerance`` of a
        lower-numbered ``one`` (the lowest of its cluster), with their distance [mm], by
        ``other``; empty for a folded pattern (not flat, or a face turned over): folding,
        and folding flat, bring vertices together.
    """
    # Sorted in Python: numpy's unique imports numpy.ma (about 10 ms of every read).
    used = np.array(sorted({v for face in faces for v in face}), dtype=np.int64)
    if len(used) < 2:
        return []
    points = np.asarray(vertices, dtype=float)[used]
    size = float(np.linalg.norm(np.ptp(points, axis=0)))
    if size == 0.0 or not _unfolded(np.asarray(vertices, dtype=float), faces):
        return []
    representative = merge_points(points, tolerance * size)
    twins = np.flatnonzero(representative != np.arange(len(used)))
    return [(int(used[representative[k]]), int(used[k]),
             float(np.linalg.norm(points[k] - points[representative[k]])))
            for k in twins.tolist()]


def check_duplicate_vertices(vertices, faces, edges, assignments, fail, *,
                             tolerance=DUPLICATE_TOLERANCE, first: int = 0) -> None:
    """Refuse two vertices of a crease pattern's faces at one point, unless both lie on cut
    edges. Only an unfolded pattern is checked (flat, every face turning the same way):
    folding, and folding flat, bring vertices together.

    Parameters
    ----------
    vertices : ndarray, shape (N, 3)
    faces : sequence of sequence of int
    edges : ndarray of int, shape (E, 2)
    assignments : sequence of str, length E
    fail : callable
        ``fail(message)`` returns the exception to raise.
    tolerance : float
        As a fraction of the size (bounding-box diagonal) of the faces' vertices.
    first : int
        The number the file gives its first vertex (1 for OBJ), for the message.

    Raises
    ------
    ValueError
        From ``fail``, naming the first pair (lowest indices) and their distance.
    """
    twins = coincident_twins(vertices, faces, tolerance)
    if not twins:
        return
    on_cut = {v for (u, w), a in zip(np.asarray(edges).tolist(), assignments) if a == "C"
              for v in (u, w)}
    for one, other, gap in twins:
        if one in on_cut and other in on_cut:
            continue
        used = np.unique(np.fromiter((v for face in faces for v in face), dtype=np.int64))
        size = float(np.linalg.norm(np.ptp(np.asarray(vertices, dtype=float)[used], axis=0)))
        raise fail(f"vertices {one + first} and {other + first} coincide ({gap:.3g} mm apart, "
                   f"within {tolerance:g} of the pattern's {size:.3g} mm size): two vertices "
                   "at one point leave a slit between their faces; use one vertex for both "
                   "(or, for a slit, assign the edges along it 'C')")
