"""Lumped masses: the sheet's total exactly, the N5B8 centre node's share, explicit masses."""

import numpy as np
import pytest

from kresling import Design
from kresling.io import miura_sheet
from kresling.model import ManualProperties, build_pattern_model, kresling_specimen
from kresling.model.masses import lumped_masses, specimen_triangles

RHO, T = 1.38e-9, 0.3
MANUAL = ManualProperties(bar_modulus=1e3, bar_area=1.0, fold_stiffness=0.1,
                          bend_stiffness=1.0)


def test_n5b8_square_centre_takes_a_third():
    square = np.array([[0, 0, 0], [3, 0, 0], [3, 2, 0], [0, 2, 0]], float)
    pm = build_pattern_model_of(square, [[0, 1, 2, 3]])
    m = lumped_masses(pm, T, RHO)
    total = RHO * T * 6.0
    assert m.shape == (5,)
    # Four triangles (corner, corner, centre): the centre is in all four, each corner in two.
    centre = pm.elements.panel_centre[0]
    assert m[centre] == pytest.approx(total / 3, rel=1e-14)
    assert m.sum() == pytest.approx(total, rel=1e-14)


def build_pattern_model_of(vertices, panels):
    from kresling.io import pattern_from_arrays

    pattern = pattern_from_arrays(vertices, panels)
    return build_pattern_model(pattern, material=MANUAL,
                               split="N5B8", centre="mean")


def test_miura_sheet_total_is_sheet_mass():
    pattern = miura_sheet(4, 3)
    pm = build_pattern_model(pattern, material=MANUAL)
    nodes = np.asarray(pattern.vertices)
    area = sum(_area(nodes[list(face)]) for face in pattern.faces)   # panels, not triangles
    m = lumped_masses(pm, T, RHO, extra={0: 1e-6})
    assert m.sum() == pytest.approx(RHO * T * area + 1e-6, rel=1e-12)
    assert (m[pm.num_vertices:] > 0).all()      # every centre node has its share


def _area(points):
    # Planar polygon area by the shoelace formula on its best-fit plane (the vector area).
    return 0.5 * np.linalg.norm(sum(np.cross(points[i], points[(i + 1) % len(points)])
                                    for i in range(len(points))))


def test_polygon_panel_shared_equally_and_explicit_masses():
    square = np.array([[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0], [5, 5, 5]], float)
    m = lumped_masses((square, [[0, 1, 2, 3]]), 1.0, 1.0, extra=np.array([0, 0, 0, 0, 2.0]))
    assert m.tolist() == [1.0, 1.0, 1.0, 1.0, 2.0]


def test_specimen_mass_is_its_surface():
    design = Design(n=10, lam=0.9, Lc=15, R=30)
    s = kresling_specimen(design, ["extended", "contracted"])
    tri = specimen_triangles(s)
    assert tri.shape == (2 * 10 * 2 + 10 * 3, 3)
    m = lumped_masses(s, T, RHO)
    x = s.model.nodes
    polygon = 0.5 * 10 * 30.0 ** 2 * np.sin(2 * np.pi / 10)   # a regular n-gon of radius R
    sides = sum(_area(x[list(t)]) for t in tri[:40])
    assert m.sum() == pytest.approx(RHO * T * (sides + 3 * polygon), rel=1e-12)


@pytest.mark.parametrize("bad, match", [
    ({"thickness": 0.0}, "thickness = 0.0"),
    ({"density": -1.0}, "density = -1.0"),
    ({"extra": {9: 1.0}}, "extra has node 9"),
    ({"extra": {1: -1.0}}, r"extra\[1\] = -1.0"),
])
def test_bad_input(bad, match):
    square = np.array([[0, 0, 0], [2, 0, 0], [2, 2, 0]], float)
    args = {"thickness": 1.0, "density": 1.0} | bad
    with pytest.raises(ValueError, match=match):
        lumped_masses((square, [[0, 1, 2]]), **args)
