"""Pairs of points closer than a tolerance, and the clusters they chain into, in numpy alone.

A pattern's vertices are checked for near-duplicates on every read: a sweep along a generic
direction finds the close pairs of the few hundred or thousand vertices of a pattern in
well under a millisecond, where importing scipy's k-d tree for them costs about 0.3 s of a
command's start-up. The k-d tree takes over when the points crowd the sweep (thousands of
points within the tolerance of one another along the sweep's direction).
"""

from __future__ import annotations

import numpy as np

__all__ = ["close_pairs", "lowest_in_cluster"]

#: The sweep's direction (normalised to the points' dimension): generic, so that the points
#: of a grid or a line in the coordinate axes still spread out along it.
_DIRECTION = np.array([1.0, 2.0 ** 0.5, 3.0 ** 0.5])

#: Neighbours along the sweep compared with each point before the k-d tree takes over.
MAX_SWEEP_NEIGHBOURS = 64


def close_pairs(points: np.ndarray, tolerance: float) -> np.ndarray:
    """Every pair of points at most ``tolerance`` apart (Euclidean).

    Parameters
    ----------
    points : ndarray, shape (P, D)
        D = 1, 2 or 3.
    tolerance : float
        >= 0, in the points' unit.

    Returns
    -------
    ndarray of int, shape (K, 2)
        Each pair ``(i, j)`` with ``i < j`` once, in no particular order: the pairs scipy's
        ``cKDTree(points).query_pairs(tolerance)`` finds.
    """
    points = np.asarray(points, dtype=float)
    count, dimension = points.shape
    direction = _DIRECTION[:dimension] / np.linalg.norm(_DIRECTION[:dimension])
    position = points @ direction
    order = np.argsort(position, kind="stable")
    position, ordered = position[order], points[order]
    # |direction . (a - b)| <= |a - b|: a pair apart by more than the tolerance along the
    # direction is farther apart than that. The margin keeps pairs at exactly the tolerance
    # whose projection rounds above it; the distances decide.
    reach = tolerance * (1.0 + 1e-9)
    found = []
    for offset in range(1, count):
        near = np.flatnonzero(position[offset:] - position[:-offset] <= reach)
        if not len(near):
            break   # the gaps only grow with the offset
        if offset > MAX_SWEEP_NEIGHBOURS:
            return _kd_tree_pairs(points, tolerance)
        gap = ordered[near + offset] - ordered[near]
        hit = near[np.einsum("ij,ij->i", gap, gap) <= tolerance * tolerance]
        found.append(np.sort(np.stack([order[hit], order[hit + offset]], axis=1), axis=1))
    if not found:
        return np.zeros((0, 2), dtype=np.intp)
    return np.concatenate(found)


def _kd_tree_pairs(points, tolerance):
    from scipy.spatial import cKDTree   # only for crowded points: it costs ~0.3 s to import

    return cKDTree(points).query_pairs(tolerance, output_type="ndarray").astype(np.intp)


def lowest_in_cluster(count: int, pairs: np.ndarray) -> np.ndarray:
    """The lowest index of each point's cluster, the points chained by ``pairs``.

    Parameters
    ----------
    count : int
        Number of points P.
    pairs : ndarray of int, shape (K, 2)

    Returns
    -------
    ndarray of int, shape (P,)
    """
    label = np.arange(count)
    if not len(pairs):
        return label
    first, second = np.asarray(pairs).T
    while True:
        # Each point takes the lowest label among itself and its partners, then the label of
        # the point its label names (which is in its cluster and no higher): the labels fall
        # to each cluster's lowest index in about log2 of its diameter rounds.
        lowest = label.copy()
        smaller = np.minimum(label[first], label[second])
        np.minimum.at(lowest, first, smaller)
        np.minimum.at(lowest, second, smaller)
        lowest = lowest[lowest]
        if np.array_equal(lowest, label):
            return label
        label = lowest
