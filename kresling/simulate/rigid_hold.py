"""Holding a free sheet still: the supports a fold takes when the problem gives none.

A fold is driven from inside (the creases' rest angles), so a sheet needs no support to
fold, as Origami Simulator's free sheet does not; but the equilibrium solver needs its six
rigid-body motions held. Three nodes a, b, c of one triangle are held 3-2-1: a in x, y and
z; b in the two axes most across the line a -> b; c in the axis most along the triangle's
normal. That is six constraints, each removing one rigid-body motion and nothing else (a
statically determinate support), so they carry no force at any equilibrium of internal
loads: the fold's shape is the free sheet's, placed so that a stays where it is, b on its
line from a and c in its plane.
"""

from __future__ import annotations

import numpy as np

__all__ = ["rigid_body_hold"]

_AXES = "xyz"


def rigid_body_hold(vertices, faces):
    """The nodes and axes that hold a free pattern's rigid-body motions (3-2-1).

    The triangle is taken from the panel whose centroid is nearest the pattern's: its
    largest triangle of corners (so that the view's sheet stays centred and the three nodes
    are well apart).

    Parameters
    ----------
    vertices : array_like, shape (N, 3)
        The pattern's vertices [mm].
    faces : sequence of sequence of int
        Its panels.

    Returns
    -------
    list of (int, str)
        Three ``(node, axes)`` pairs: ``(a, "xyz")``, ``(b, two of "xyz")``,
        ``(c, one of "xyz")``.
    """
    x = np.asarray(vertices, dtype=float)
    centroids = np.array([x[list(face)].mean(axis=0) for face in faces])
    face = list(faces[int(np.argmin(np.linalg.norm(centroids - x.mean(axis=0), axis=1)))])
    face = face[::max(1, len(face) // 12)]  # a large panel: a dozen corners spread round it
    best, chosen = -1.0, None
    for i in range(len(face)):
        for j in range(i + 1, len(face)):
            for k in range(j + 1, len(face)):
                a, b, c = face[i], face[j], face[k]
                area = np.linalg.norm(np.cross(x[b] - x[a], x[c] - x[a]))
                if area > best:
                    best, chosen = area, (a, b, c)
    a, b, c = chosen
    along = int(np.argmax(np.abs(x[b] - x[a])))
    normal = int(np.argmax(np.abs(np.cross(x[b] - x[a], x[c] - x[a]))))
    return [(int(a), "xyz"), (int(b), "".join(_AXES[k] for k in range(3) if k != along)),
            (int(c), _AXES[normal])]
