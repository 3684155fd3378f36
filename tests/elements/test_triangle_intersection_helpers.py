"""The independent triangle-triangle intersection test of the contact checks
(tests/triangle_intersection_helpers.py), on cases whose answer is known by construction."""

from __future__ import annotations

import numpy as np

from triangle_intersection_helpers import intersecting_pairs, triangles_intersect

#: A triangle in the plane z = 0 (nodes 0, 1, 2), 500 mm across: the scale of a sheet.
FLOOR = [[0.0, 0.0, 0.0], [500.0, 0.0, 0.0], [0.0, 500.0, 0.0]]


def test_a_triangle_through_another_intersects_it_and_one_beside_it_does_not():
    through = FLOOR + [[100.0, 100.0, -50.0], [100.0, 100.0, 50.0], [300.0, 400.0, 50.0]]
    assert triangles_intersect(np.array(through), (0, 1, 2), (3, 4, 5))
    beside = FLOOR + [[600.0, 600.0, -50.0], [600.0, 600.0, 50.0], [700.0, 800.0, 50.0]]
    assert not triangles_intersect(np.array(beside), (0, 1, 2), (3, 4, 5))


def test_of_two_triangles_sharing_a_node_the_edge_opposite_it_decides():
    # Node 0 shared; the other triangle's far edge (3, 4) passes through the floor's inside.
    crossing = FLOOR + [[100.0, 100.0, -50.0], [100.0, 100.0, 50.0]]
    assert triangles_intersect(np.array(crossing), (0, 1, 2), (0, 3, 4))
    # Its far edge over the floor, its edges from node 0 at 1e-6 rad above the floor's
    # plane over 400 mm: apart, whatever the rounding at node 0.
    lifted = FLOOR + [[400.0, 100.0, 400e-6], [100.0, 400.0, 400e-6]]
    assert not triangles_intersect(np.array(lifted), (0, 1, 2), (0, 3, 4))
    # The same edge pushed below the floor: through it.
    lowered = FLOOR + [[400.0, 100.0, 1.0], [100.0, 300.0, -1.0]]
    assert triangles_intersect(np.array(lowered), (0, 1, 2), (0, 3, 4))


def test_triangles_sharing_an_edge_never_count_and_pairs_are_listed_once():
    hinge = FLOOR + [[-300.0, 300.0, 200.0]]
    assert intersecting_pairs(hinge, [[0, 1, 2], [0, 2, 3]]) == []
    through = FLOOR + [[100.0, 100.0, -50.0], [100.0, 100.0, 50.0], [300.0, 400.0, 50.0]]
    assert intersecting_pairs(through, [[0, 1, 2], [3, 4, 5]]) == [(0, 1)]


def _every_pair(x, triangles) -> list:
    """triangles_intersect on every pair, with no prefilter: the answer to match."""
    return [(i, j) for i in range(len(triangles)) for j in range(i + 1, len(triangles))
            if triangles_intersect(x, tuple(triangles[i]), tuple(triangles[j]))]


def _random_mesh(rng, nodes, triangles, flatness):
    """``triangles`` triangles of distinct nodes out of ``nodes`` random ones in a 500 mm
    box squashed to ``flatness`` of its height: many share a node or an edge."""
    x = rng.uniform(0.0, 500.0, (nodes, 3)) * [1.0, 1.0, flatness]
    tri = np.array([rng.choice(nodes, 3, replace=False) for _ in range(triangles)])
    return x, tri


def test_the_prefilter_leaves_out_no_intersecting_pair():
    # intersecting_pairs clears most pairs with a vectorised test before the scalar one:
    # the same pairs as the scalar test on every pair, in a box (many crossings) and on a
    # sheet nearly flat (1e-9 of its width: edges almost in each other's plane, where
    # rounding decides).
    rng = np.random.default_rng(7)
    for flatness, crossings in ((1.0, 100), (1e-9, 100)):
        x, tri = _random_mesh(rng, 30, 60, flatness)
        expected = _every_pair(x, tri)
        assert len(expected) >= crossings   # a discriminating case: many pairs meet
        assert intersecting_pairs(x, tri) == expected
    # Edges that end exactly on another triangle (parameters at 0 and 1, no rounding): on
    # the floor's inside (node 5), on its edge (node 1) and on its long edge (node 21).
    grid = np.array([[i, j, 0.0] for i in range(4) for j in range(4)]) * 100.0
    x = np.vstack([grid, [[100.0, 100.0, 100.0], [200.0, 100.0, 100.0], [-100.0, 100.0, 100.0],
                          [-100.0, 200.0, 100.0], [100.0, 100.0, -100.0], [150.0, 150.0, 0.0]]])
    tri = np.array([[0, 3, 12], [5, 16, 17], [1, 18, 19], [21, 16, 20], [5, 6, 9]])
    pairs = intersecting_pairs(x, tri)
    assert pairs == _every_pair(x, tri)
    assert {(0, 1), (0, 2), (0, 3)} <= set(pairs)


def test_the_prefilter_keeps_every_segment_that_touches_a_triangle_at_its_border():
    # Segments that start or end exactly on a triangle, on its inside, its edges and its
    # corners (u, v, u + v and t at 0 or 1 exactly, in integers): the scalar test finds them
    # all, and the prefilter must keep every one it finds.
    from triangle_intersection_helpers import _may_cross, segment_crosses_triangle
    rng = np.random.default_rng(3)
    rows = []
    for _ in range(40):
        a, b, c = rng.integers(-400, 400, (3, 3)).astype(float)
        away = rng.integers(-400, 400, 3).astype(float)
        for u, v in ((0, 0), (1, 0), (0, 1), (0.5, 0), (0, 0.5), (0.5, 0.5), (0.25, 0.25)):
            on = a + u * (b - a) + v * (c - a)
            rows += [(on, away, a, b, c), (away, on, a, b, c), (2 * on - away, away, a, b, c)]
    p, q, a, b, c = (np.array(column) for column in zip(*rows))
    found = np.array([segment_crosses_triangle(*row) for row in rows])
    assert found.sum() >= 0.9 * len(rows)
    assert np.all(_may_cross(p, q, a, b, c)[found])
