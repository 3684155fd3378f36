"""FOLD's ``vertices_vertices`` and ``vertices_edges``: each vertex's neighbours in order
round it.

The FOLD specification lists a vertex's neighbours counter-clockwise round it (for an
orientable sheet), and its edges in the same order. Readers that separate faces along cuts
walk round each vertex in this order (Origami Simulator needs both keys in a file with
``C`` edges), so :func:`~kresling.io.write_fold` writes them for such files. The order comes
from the faces, not from coordinates, so it holds for folded (3D) key frames too: in a
counter-clockwise face ``[..., a, v, b, ...]`` the sheet turns counter-clockwise round
``v`` from ``b`` to ``a``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["vertices_neighbours"]


def _turns(faces, count: int) -> list:
    """For each vertex, the face corners round it: ``{b: a}`` for each face ``[.., a, v, b,
    ..]`` (one step counter-clockwise round ``v`` goes from ``b`` to ``a``)."""
    turns = [dict() for _ in range(count)]
    for face in faces:
        n = len(face)
        for k, v in enumerate(face):
            turns[v][face[(k + 1) % n]] = face[k - 1]
    return turns


def _walk(turn: dict) -> list:
    """The neighbours in the order the faces chain them: each fan of faces from its first
    side (a neighbour no face turns to, on a boundary or a cut; any one of a closed ring)
    to its last, the fans one after another."""
    order, seen = [], set()
    targets = set(turn.values())
    starts = [b for b in turn if b not in targets] + list(turn)
    for start in starts:
        if start in seen:
            continue
        b = start
        while b not in seen:
            seen.add(b)
            order.append(b)
            if b not in turn:
                break
            b = turn[b]
    return order


def vertices_neighbours(faces, edges, count: int) -> tuple:
    """Each vertex's neighbours and edges, counter-clockwise round it.

    Parameters
    ----------
    faces : sequence of sequence of int
        Counter-clockwise faces (0-based vertex indices).
    edges : array_like of int, shape (E, 2)
    count : int
        Number of vertices.

    Returns
    -------
    vertices_vertices : list of list of int
        Per vertex, its neighbours through edges: counter-clockwise round it where faces
        chain them (a fan from a boundary side, or a closed ring), fans one after another,
        then neighbours through edges of no face, in edge order.
    vertices_edges : list of list of int
        Per vertex, the index of the edge to each neighbour, in the same order.
    """
    edges = np.asarray(edges, dtype=int).reshape(-1, 2)
    edge_of = [dict() for _ in range(count)]
    for index, (u, v) in enumerate(edges.tolist()):
        edge_of[u].setdefault(v, index)
        edge_of[v].setdefault(u, index)
    vertices_vertices, vertices_edges = [], []
    for v, turn in enumerate(_turns(faces, count)):
        ring = [w for w in _walk(turn) if w in edge_of[v]]
        ring += [w for w in edge_of[v] if w not in set(ring)]
        vertices_vertices.append(ring)
        vertices_edges.append([edge_of[v][w] for w in ring])
    return vertices_vertices, vertices_edges
