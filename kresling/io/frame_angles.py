"""Fold angles of every edge of a mesh in many configurations at once (a path's frames)."""

from __future__ import annotations

import numpy as np

__all__ = ["fold_angle_frames", "newell_normals"]


def newell_normals(frames, faces) -> np.ndarray:
    """Newell's normal of every face in every frame (not normalised: its length is twice the
    face's area; exact for planar faces, robust for any corner order).

    Parameters
    ----------
    frames : array_like, shape (K, V, 3)
        Positions [mm].
    faces : sequence of sequence of int
        F faces, any number of corners each.

    Returns
    -------
    ndarray, shape (K, F, 3)
    """
    frames = np.asarray(frames, dtype=float)
    normals = np.zeros((len(frames), len(faces), 3))
    by_size = {}
    for index, face in enumerate(faces):
        by_size.setdefault(len(face), []).append(index)
    for indices in by_size.values():   # one array operation per corner count
        corners = np.array([faces[i] for i in indices])                  # (F, k)
        x, y, z = (frames[:, corners, axis] for axis in range(3))        # (K, F, k) each
        # The sum over the corners of cross(p_i, p_i+1), written out: the same products,
        # differences and sums in the same order as np.cross(...).sum() (so the same bits,
        # signed zeros included: the sum starts from +0), several times faster.
        total = 0.0
        for i in range(corners.shape[1]):
            j = (i + 1) % corners.shape[1]
            total = total + np.stack([y[..., i] * z[..., j] - z[..., i] * y[..., j],
                                      z[..., i] * x[..., j] - x[..., i] * z[..., j],
                                      x[..., i] * y[..., j] - y[..., i] * x[..., j]], axis=-1)
        normals[:, indices] = total
    return normals


def fold_angle_frames(faces, edges, frames) -> np.ndarray:
    """Signed fold angle [degrees] of every edge in every frame, as FOLD's edges_foldAngle.

    The same angle as :func:`kresling.io.fold_angles` (pi minus the dihedral angle,
    positive for a valley, 0 for an edge of one face), computed for all frames together.

    Parameters
    ----------
    faces : sequence of sequence of int
        Planar faces, counter-clockwise in the flat pattern.
    edges : array_like of int, shape (E, 2)
    frames : array_like, shape (K, V, 3)
        Positions [mm] in each frame.

    Returns
    -------
    ndarray, shape (K, E)
        Degrees in [-180, 180].
    """
    frames = np.asarray(frames, dtype=float).reshape(-1, *np.shape(frames)[-2:])
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    left_of = {}
    for index, face in enumerate(faces):
        for u, v in zip(face, list(face[1:]) + [face[0]]):
            left_of[(int(u), int(v))] = index
    pairs = [(left_of.get((u, v)), left_of.get((v, u))) for u, v in edges.tolist()]
    inner = np.array([a is not None and b is not None for a, b in pairs], dtype=bool)
    left = np.array([a for (a, b), ok in zip(pairs, inner) if ok], dtype=np.int64)
    right = np.array([b for (a, b), ok in zip(pairs, inner) if ok], dtype=np.int64)
    normals = newell_normals(frames, faces)
    normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
    axis = frames[:, edges[inner, 1]] - frames[:, edges[inner, 0]]
    axis /= np.linalg.norm(axis, axis=-1, keepdims=True)
    n_left, n_right = normals[:, left], normals[:, right]
    angles = np.zeros((len(frames), len(edges)))
    angles[:, inner] = np.arctan2(np.einsum("kej,kej->ke", np.cross(n_right, n_left), axis),
                                  np.einsum("kej,kej->ke", n_left, n_right))
    return np.degrees(angles)
