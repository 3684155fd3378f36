"""The close pairs and clusters of points found in numpy agree with scipy's k-d tree and
connected components (the independent reference), on grids, random clouds with
near-duplicates, exact duplicates and points crowded enough for the k-d tree to take over."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from kresling.io import close_pairs as module
from kresling.io.close_pairs import close_pairs, lowest_in_cluster
from kresling.io.planar_graph import merge_points


def reference_pairs(points, tolerance):
    return {tuple(p) for p in cKDTree(points).query_pairs(tolerance, output_type="ndarray")}


def reference_clusters(points, tolerance):
    pairs = cKDTree(points).query_pairs(tolerance, output_type="ndarray")
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])),
                       shape=(len(points), len(points)))
    _, label = connected_components(graph, directed=False)
    lowest = np.full(label.max() + 1, len(points))
    np.minimum.at(lowest, label, np.arange(len(points)))
    return lowest[label]


def clouds():
    rng = np.random.default_rng(7)
    grid = np.stack(np.meshgrid(np.arange(12.0), np.arange(9.0), [0.0, 2.5]), -1).reshape(-1, 3)
    # Near-duplicates: copies moved by up to twice the tolerance (about half within it), and
    # chains of them (a cluster several tolerances long).
    copies = grid[rng.integers(0, len(grid), 150)] + rng.uniform(-2e-3, 2e-3, (150, 3))
    chain = np.array([[5.0, 5.0, 5.0]]) + np.arange(8)[:, None] * [9e-4, 0.0, 0.0]
    yield "grid 3D", rng.permutation(np.vstack([grid, copies, chain, grid[:20]])), 1e-3
    flat = grid[:, :2]
    yield "grid 2D", np.vstack([flat, flat[::3] + rng.uniform(-1e-3, 1e-3, (len(flat[::3]), 2))]), 1e-3
    # About 350 pairs, some chained; about 20 points within the tolerance along the sweep.
    yield "random", rng.uniform(0, 1, (3000, 2)), 0.005
    # 400 points on a line 2.5e-5 apart, each within the tolerance of 40 others: the k-d
    # tree takes over.
    yield "crowded", np.c_[np.linspace(0, 1e-2, 400), np.zeros(400), np.zeros(400)], 1e-3


@pytest.mark.parametrize("name, points, tolerance", list(clouds()), ids=lambda v: v
                         if isinstance(v, str) else "")
def test_the_pairs_and_clusters_are_the_k_d_trees(name, points, tolerance):
    pairs = close_pairs(points, tolerance)
    assert (pairs[:, 0] < pairs[:, 1]).all()
    assert len(pairs) == len({tuple(p) for p in pairs})      # each pair once
    assert {tuple(p) for p in pairs} == reference_pairs(points, tolerance)
    np.testing.assert_array_equal(merge_points(points, tolerance),
                                  reference_clusters(points, tolerance))


def test_the_k_d_tree_takes_over_only_for_crowded_points(monkeypatch):
    used = []
    real = module._kd_tree_pairs
    monkeypatch.setattr(module, "_kd_tree_pairs", lambda p, t: used.append(len(p)) or real(p, t))
    for name, points, tolerance in clouds():
        close_pairs(points, tolerance)
    assert used == [400]


def test_no_pairs_and_single_points():
    assert close_pairs(np.eye(3), 0.5).shape == (0, 2)
    assert close_pairs(np.zeros((1, 3)), 1.0).shape == (0, 2)
    np.testing.assert_array_equal(lowest_in_cluster(4, np.zeros((0, 2), int)), np.arange(4))
    # A chain given from its far end: 4-3, 3-2, 2-1, 1-0 all fall to 0; 5 stays alone.
    np.testing.assert_array_equal(lowest_in_cluster(6, np.array([[3, 4], [2, 3], [1, 2],
                                                                 [0, 1]])), [0, 0, 0, 0, 0, 5])
