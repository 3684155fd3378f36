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
