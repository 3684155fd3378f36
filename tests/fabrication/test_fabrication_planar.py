"""Plane-geometry helpers of the cut files, on shapes whose answers are known by hand."""

import math

import numpy as np
import pytest

from kresling.fabrication.planar import (barycentric, clip_convex, convex_overlap, dashes,
                                         mirror_x, offset_polygon, shorten, signed_area)

SQUARE = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])


def test_signed_area_and_orientation():
    assert signed_area(SQUARE) == pytest.approx(4.0)
    assert signed_area(SQUARE[::-1]) == pytest.approx(-4.0)


@pytest.mark.parametrize("polygon", [SQUARE, SQUARE[::-1]])
def test_offset_is_outwards_for_either_orientation(polygon):
    grown = offset_polygon(polygon, 0.5)
    assert abs(signed_area(grown)) == pytest.approx(9.0, abs=1e-12)
    np.testing.assert_allclose(np.sort(grown[:, 0]), [-0.5, -0.5, 2.5, 2.5], atol=1e-12)


def test_inset_triangle_sides_move_by_the_inset():
    triangle = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 3.0]])    # inradius 1
    inset = offset_polygon(triangle, -0.25)
    # The inset of a triangle is similar about the incentre, scaled by (r - d) / r.
    incentre = np.array([1.0, 1.0])
    np.testing.assert_allclose(inset, incentre + 0.75 * (triangle - incentre), atol=1e-12)


def test_clip_convex_keeps_one_side():
    half = clip_convex(SQUARE, [1.0, 0.0], [1.0, 0.0])
    assert signed_area(half) == pytest.approx(2.0) and half[:, 0].min() == pytest.approx(1.0)
    assert clip_convex(SQUARE, [3.0, 0.0], [1.0, 0.0]).shape == (0, 2)


def test_barycentric_round_trip():
    triangle = np.array([[0.0, 0.0], [3.0, 1.0], [1.0, 4.0]])
    weights = barycentric([1.5, 1.5], triangle)
    assert weights.sum() == pytest.approx(1.0)
    np.testing.assert_allclose(weights @ triangle, [1.5, 1.5], atol=1e-12)


def test_dashes_are_centred_with_ties_at_both_ends():
    cuts = dashes([0.0, 0.0], [10.0, 0.0], dash=2.0, tie=1.0)
    starts = [c[0, 0] for c in cuts]
    assert len(cuts) == 3                         # 3 dashes + 2 inner ties = 8 mm, ends 1 mm
    np.testing.assert_allclose(starts, [1.0, 4.0, 7.0])
    kerfed = dashes([0.0, 0.0], [10.0, 0.0], dash=2.0, tie=1.0, kerf=0.2)
    np.testing.assert_allclose([c[1, 0] - c[0, 0] for c in kerfed], 1.8)
    assert dashes([0.0, 0.0], [3.0, 0.0], dash=2.0, tie=1.0) == []


def test_convex_overlap_depth():
    assert convex_overlap(SQUARE, SQUARE + [1.5, 0.0]) == pytest.approx(0.5)
    assert convex_overlap(SQUARE, SQUARE + [2.0, 0.0]) == pytest.approx(0.0)   # touching
    assert convex_overlap(SQUARE, SQUARE + [3.0, 3.0]) == pytest.approx(-1.0)


def test_shorten_and_mirror():
    np.testing.assert_allclose(shorten([0, 0], [0, 10], 1.0, 2.0), [[0, 1], [0, 8]])
    np.testing.assert_allclose(mirror_x([[1.0, 5.0]], 3.0), [[5.0, 5.0]])
    assert math.isclose(signed_area(mirror_x(SQUARE, 1.0)), -4.0)
