"""The sheet calibration against hand calculations, and MERLIN2 v1.1's pairing switch.

Hand calculations follow the published formulas (docs/model.md, 'Material calibration')
for a triangle, a rectangle and a regular hexagon, each a single panel; they evaluate the
same closed forms as the code, so they agree to rounding (rtol 1e-13).
"""

from __future__ import annotations

import numpy as np
import pytest

from kresling.model import SheetMaterial, build_panel_elements, calibrate_sheet

E, NU, T = 1000.0, 0.3, 0.25
MATERIAL = SheetMaterial(E, NU, T)
D = E * T ** 3 / (12 * (1 - NU ** 2))


def bar_area_of(elements, stiffness, a, b):
    bars = [tuple(sorted(bar)) for bar in elements.bars.tolist()]
    return stiffness.bar_area[bars.index(tuple(sorted((a, b))))]


def test_plate_rigidity():
    assert MATERIAL.bending_rigidity == pytest.approx(D, rel=1e-15)


def test_triangle():
    # Right triangle 3-4-5: S = 6, P = 12, every side t 2 S / (P (1 - nu)).
    vertices = np.array([[0, 0, 0], [3, 0, 0], [0, 4, 0]], float)
    elements = build_panel_elements(vertices, [[0, 1, 2]], split="N5B8")
    s = calibrate_sheet(elements, MATERIAL)
    np.testing.assert_allclose(s.bar_area, T * 2 * 6 / (12 * (1 - NU)), rtol=1e-13)
    assert len(s.fold_stiffness) == 0 and len(s.bend_stiffness) == 0


def test_rectangle():
    a, b = 8.0, 5.0  # W = a (sides 0-1, 2-3), H = b
    vertices = np.array([[0, 0, 0], [a, 0, 0], [a, b, 0], [0, b, 0]], float)
    elements = build_panel_elements(vertices, [[0, 1, 2, 3]], split="N5B8")
    s = calibrate_sheet(elements, MATERIAL)
    W, H, c = a, b, 1 - NU ** 2
    assert bar_area_of(elements, s, 0, 1) == pytest.approx(T * abs(H**2 - NU * W**2) / (2 * H * c), rel=1e-13)
    assert bar_area_of(elements, s, 2, 3) == pytest.approx(T * abs(H**2 - NU * W**2) / (2 * H * c), rel=1e-13)
    assert bar_area_of(elements, s, 1, 2) == pytest.approx(T * abs(W**2 - NU * H**2) / (2 * W * c), rel=1e-13)
    assert bar_area_of(elements, s, 0, 3) == pytest.approx(T * abs(W**2 - NU * H**2) / (2 * W * c), rel=1e-13)
    spoke = T * NU * (H**2 + W**2) ** 1.5 / (2 * H * W * c)
    for k in range(4):
        assert bar_area_of(elements, s, 4, k) == pytest.approx(spoke, rel=1e-13)
    diagonal = np.hypot(a, b)  # each spoke and the one opposite make a whole diagonal
    np.testing.assert_allclose(s.bend_stiffness, D * (diagonal / T) ** (1 / 3) / diagonal,
                               rtol=1e-13)


def test_regular_hexagon():
    side = 10.0
    angles = np.arange(6) * np.pi / 3
    vertices = np.column_stack([side * np.cos(angles), side * np.sin(angles), np.zeros(6)])
    elements = build_panel_elements(vertices, [list(range(6))], split="N5B8")
    np.testing.assert_allclose(elements.nodes[6], 0.0, atol=1e-12)
    s = calibrate_sheet(elements, MATERIAL)
    area = 6 * np.sqrt(3) / 4 * side ** 2
    share = T * 2 * area / ((6 * side + 6 * side) * (1 - NU))
    np.testing.assert_allclose(s.bar_area, share, rtol=1e-13)
    # Opposite spokes make a whole diagonal of 2 * side.
    np.testing.assert_allclose(s.bend_stiffness, D * (2 * side / T) ** (1 / 3) / (2 * side),
                               rtol=1e-13)


def test_fold_between_two_triangles():
    vertices = np.array([[0, 0, 0], [6, 0, 0], [0, 6, 0], [6, 6, 0.5]], float)
    elements = build_panel_elements(vertices, [[0, 1, 2], [1, 3, 2]], split="N5B8")
    assert elements.folds[:, :2].tolist() == [[1, 2]]
    lf = np.linalg.norm(vertices[2] - vertices[1])
    for ls in (None, 3.0):
        s = calibrate_sheet(elements, SheetMaterial(E, NU, T, ls))
        scale = 2 * lf if ls is None else ls  # default: twice the mean fold length
        expected = 1 / (scale / D + 1 / (0.55 * D * (lf / T) ** (1 / 3))) / lf
        assert s.fold_stiffness[0] == pytest.approx(expected, rel=1e-13)
        assert s.length_scale == pytest.approx(scale, rel=1e-15)


def rhombus(order):
    """A rhombus with unequal diagonals, its corners listed in ``order``."""
    vertices = np.array([[6, 0, 0], [0, 3, 0], [-6, 0, 0], [0, -3, 0]], float)
    return build_panel_elements(vertices, [order], split="N5B8")


def test_compat_is_the_published_rule_for_ascending_panels():
    elements = rhombus([0, 1, 2, 3])
    published = calibrate_sheet(elements, MATERIAL)
    compat = calibrate_sheet(elements, MATERIAL, merlin2_compat=True)
    np.testing.assert_array_equal(published.bend_stiffness, compat.bend_stiffness)
    np.testing.assert_array_equal(published.bar_area, compat.bar_area)


def test_compat_gives_spoke_values_by_vertex_rank():
    order = [1, 2, 3, 0]  # not ascending: MERLIN2 v1.1 pairs values with sorted spokes
    elements = rhombus(order)
    published = calibrate_sheet(elements, MATERIAL)
    compat = calibrate_sheet(elements, MATERIAL, merlin2_compat=True)
    spoke_of = {int(b[1]): k for k, b in enumerate(elements.bends.tolist())}  # vertex -> bend
    # Published: each spoke's value is its own diagonal's; the long diagonal (12) for
    # vertices 0 and 2, the short one (6) for 1 and 3.
    for vertex, diagonal in ((0, 12.0), (1, 6.0), (2, 12.0), (3, 6.0)):
        assert published.bend_stiffness[spoke_of[vertex]] == pytest.approx(
            D * (diagonal / T) ** (1 / 3) / diagonal, rel=1e-13)
    # Compatibility: the r-th smallest vertex's spoke gets the value of the r-th listed corner.
    for rank, vertex in enumerate(sorted(order)):
        assert compat.bend_stiffness[spoke_of[vertex]] == \
            published.bend_stiffness[spoke_of[order[rank]]]
    assert not np.array_equal(published.bend_stiffness, compat.bend_stiffness)
    # Spoke areas of a quad are all equal: the pairing cannot move them.
    np.testing.assert_array_equal(published.bar_area, compat.bar_area)


def grid(widths, heights):
    xs, ys = np.concatenate([[0], np.cumsum(widths)]), np.concatenate([[0], np.cumsum(heights)])
    vertices = np.array([[x, y, 0.0] for y in ys for x in xs])
    n = len(xs)
    panels = [[j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i]
              for j in range(len(heights)) for i in range(len(widths))]
    return vertices, panels


def test_compat_moves_side_areas_only_of_an_all_fold_quad():
    # 3 x 3 rectangles; the middle one (vertices 5, 6, 10, 9) has four fold sides.
    vertices, panels = grid([4.0, 7.0, 4.0], [4.0, 3.0, 4.0])
    elements = build_panel_elements(vertices, panels, split="N5B8")
    published = calibrate_sheet(elements, MATERIAL)
    compat = calibrate_sheet(elements, MATERIAL, merlin2_compat=True)
    middle = panels[4]
    sides = [tuple(sorted((middle[k], middle[(k + 1) % 4]))) for k in range(4)]
    # The middle panel's own shares, in corner order (W = 7 along sides 0 and 2).
    W, H, c = 7.0, 3.0, 1 - NU ** 2
    own = [T * abs(H**2 - NU * W**2) / (2 * H * c), T * abs(W**2 - NU * H**2) / (2 * W * c)] * 2
    ranked = sorted(range(4), key=lambda k: sides[k])
    expected_shift = {sides[ranked[r]]: own[r] - own[ranked[r]] for r in range(4)}
    bars = [tuple(sorted(b)) for b in elements.bars.tolist()]
    for index, bar in enumerate(bars):
        shift = expected_shift.get(bar, 0.0)
        assert compat.bar_area[index] - published.bar_area[index] == pytest.approx(
            shift, rel=1e-12, abs=1e-15), bar
    assert sum(abs(v) > 0 for v in expected_shift.values()) == 2  # two sides move


def test_calibration_needs_the_n5b8_split():
    vertices, panels = grid([4.0], [3.0])
    elements = build_panel_elements(vertices, panels, split="N4B5")
    with pytest.raises(ValueError, match="panel 0.*N5B8"):
        calibrate_sheet(elements, MATERIAL)


@pytest.mark.parametrize("kwargs, match", [
    ({"youngs_modulus": -1.0}, "youngs_modulus"),
    ({"poisson_ratio": 0.6}, "poisson_ratio"),
    ({"thickness": 0.0}, "thickness"),
    ({"length_scale": float("nan")}, "length_scale"),
])
def test_bad_material(kwargs, match):
    values = {"youngs_modulus": E, "poisson_ratio": NU, "thickness": T} | kwargs
    with pytest.raises(ValueError, match=match):
        SheetMaterial(**values)
