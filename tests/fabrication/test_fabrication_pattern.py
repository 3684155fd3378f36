"""The flat crease pattern against the 3D cell: lengths, facet angle, closure, isometry of
every face on folding, fold directions, and the tabs on the base polygon.

Tolerances: the pattern is built from closed forms in double precision, so lengths agree to a
few ulps of the cell's size (~1e-14 mm at R = 30 mm); 1e-9 mm is the required accuracy.
"""

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import kresling
from kresling.fabrication import crease_pattern, fold_angles
from kresling.fabrication.planar import convex_overlap, signed_area

LENGTH_TOL = 1e-9  # mm
THESIS_DESIGNS = [(n, lam, Lc) for n in (4, 6, 8, 10) for lam in (0.7, 0.9) for Lc in (15.0, 60.0)]


def _pattern(n, lam, Lc, chirality=1, **options):
    return crease_pattern(kresling.Design(n, lam, Lc, 30.0, chirality), **options)


def _lengths(points, edges):
    return np.linalg.norm(points[edges[:, 0]] - points[edges[:, 1]], axis=1)


@pytest.mark.parametrize("chirality", [1, -1])
@pytest.mark.parametrize("n, lam, Lc", THESIS_DESIGNS)
def test_every_crease_has_its_3d_length(n, lam, Lc, chirality):
    p = _pattern(n, lam, Lc, chirality)
    d = p.design
    expected = {"valley": d.Vg, "mountain": d.Mg, "seam": d.Mg, "tab": d.P}
    counts = {"valley": n, "mountain": n - 1, "seam": 1, "tab": n}
    for kind, length in expected.items():
        edges = p.edges_of_kind(kind)
        assert len(edges) == counts[kind]
        np.testing.assert_allclose(_lengths(p.points, edges), length, rtol=0, atol=LENGTH_TOL)
    # The strip's top edges are the top polygon's sides: P as well.
    top = np.column_stack([p.top[:-1], p.top[1:]])
    np.testing.assert_allclose(_lengths(p.points, top), d.P, rtol=0, atol=LENGTH_TOL)


@pytest.mark.parametrize("chirality", [1, -1])
def test_facet_angle_is_theta_g(chirality):
    p = _pattern(10, 0.9, 15.0, chirality)
    b, t = p.points[p.bottom], p.points[p.top]
    for i in range(10):
        u, v = b[i + 1] - b[i], t[i + 1] - b[i]
        angle = math.acos(np.dot(u, v) / np.linalg.norm(u) / np.linalg.norm(v))
        assert angle == pytest.approx(p.design.theta_g, abs=1e-12)


@pytest.mark.parametrize("state", ["contracted", "extended"])
@pytest.mark.parametrize("chirality", [1, -1])
@pytest.mark.parametrize("n, lam, Lc", THESIS_DESIGNS)
def test_folding_is_an_isometry_and_the_strip_closes(n, lam, Lc, chirality, state):
    p = _pattern(n, lam, Lc, chirality)
    folded = p.folded(state)
    for face in p.faces:
        for a, b in itertools.combinations(face, 2):
            flat = np.linalg.norm(p.points[a] - p.points[b])
            assert np.linalg.norm(folded[a] - folded[b]) == pytest.approx(flat, abs=LENGTH_TOL)
    # B_n, T_n land on B_0, T_0; B_i, T_i on the design's polygon vertices.
    assert np.linalg.norm(folded[p.bottom[-1]] - folded[p.bottom[0]]) < LENGTH_TOL
    assert np.linalg.norm(folded[p.top[-1]] - folded[p.top[0]]) < LENGTH_TOL
    bottom, top = p.design.vertices(state)
    assert {tuple(np.round(x, 9)) for x in folded[p.bottom]} == {tuple(np.round(x, 9)) for x in bottom}
    assert {tuple(np.round(x, 9)) for x in folded[p.top]} == {tuple(np.round(x, 9)) for x in top}


@pytest.mark.parametrize("chirality", [1, -1])
def test_fold_directions_and_tab_angle(chirality):
    """Seen from outside, valleys fold positive, mountains negative; a tab folds in onto the
    base polygon, so its crease turns by pi - Psi (the facet-to-polygon angle)."""
    p = _pattern(10, 0.9, 15.0, chirality)
    d = p.design
    for state, psi in (("contracted", d.psi_con), ("extended", d.psi_ext)):
        angles = fold_angles(p.faces, p.edges, p.folded(state))
        by_kind = {kind: angles[[k for k, e in enumerate(p.edge_kinds) if e == kind]]
                   for kind in set(p.edge_kinds)}
        assert np.all(by_kind["valley"] > 0.1) and np.all(by_kind["mountain"] < -0.1)
        np.testing.assert_allclose(by_kind["tab"], -(math.pi - psi), atol=1e-9)
        # The seam folds like the other mountains (the closing tab lies on facet 0).
        np.testing.assert_allclose(by_kind["seam"], by_kind["mountain"][0], atol=1e-9)
        assert np.all(by_kind["boundary"] == 0.0)


def test_facet_normals_point_out_of_the_cell():
    p = _pattern(8, 0.8, 30.0)
    folded = p.folded("extended")
    for face, kind in zip(p.faces, p.face_kinds):
        if kind != "facet":
            continue
        a, b, c = folded[list(face)]
        centre = (a + b + c) / 3
        radial = centre - [0.0, 0.0, centre[2]]
        assert np.dot(np.cross(b - a, c - a), radial) > 0


@pytest.mark.parametrize("n", [3, 4, 6, 8, 10])
def test_tabs_lie_on_the_base_polygon_without_overlap(n):
    p = _pattern(n, 0.8, 15.0, tab_height=0.95 * 30.0 * math.cos(math.pi / n))
    folded = p.folded("extended")
    tabs = [folded[list(f)][:, :2] for f, k in zip(p.faces, p.face_kinds) if k == "tab"]
    assert all(np.all(np.abs(folded[list(f)][:, 2]) < 1e-12)
               for f, k in zip(p.faces, p.face_kinds) if k == "tab")
    polygon = p.design.vertices("extended")[0][:, :2]
    for a, b in itertools.combinations(range(n), 2):
        assert convex_overlap(tabs[a], tabs[b]) < 1e-9
    for tab in tabs:  # inside the polygon: every tip within the apothem
        assert np.all(np.linalg.norm(tab, axis=1) <= 30.0 + 1e-9)
        assert convex_overlap(tab, polygon) > 0


def test_chiralities_are_mirror_images():
    right, left = _pattern(6, 0.8, 15.0, 1), _pattern(6, 0.8, 15.0, -1)
    mirrored = right.points * [-1.0, 1.0]
    shift = left.points[:, 0].min() - mirrored[:, 0].min()
    np.testing.assert_allclose(left.points, mirrored + [shift, 0.0], atol=1e-12)
    assert left.edge_kinds == right.edge_kinds
    assert all(signed_area(left.points[list(f)]) > 0 for f in left.faces)


def test_outline_encloses_strip_tabs_and_closing_tab():
    p = _pattern(10, 0.9, 15.0)
    pieces = [f for f, k in zip(p.faces, p.face_kinds) if k != "base polygon"]
    area = sum(signed_area(p.points[list(f)]) for f in pieces)
    assert signed_area(p.outline()) == pytest.approx(area, rel=1e-12)


@pytest.mark.parametrize(
    "options, message",
    [
        ({"tab_height": 22.0}, "tab_height = 22.0 mm is invalid for n = 4"),
        ({"tab_height": 0.0}, "tab_height = 0.0 is invalid"),
        ({"tab_height": float("nan")}, "tab_height = nan is invalid"),
        ({"closing_tab_width": 40.0}, "closing_tab_width = 40.0 mm is invalid"),
        ({"tab_clearance": -1.0}, "tab_clearance = -1.0 is invalid"),
    ],
)
def test_bad_pattern_parameters(options, message):
    with pytest.raises(ValueError, match=message):
        _pattern(4, 0.7, 30.0, **options)


def test_overlapping_faces_are_named():
    from dataclasses import replace

    from kresling.fabrication.pattern import _check_no_overlap

    p = _pattern(6, 0.8, 15.0)
    points = p.points.copy()
    tip = 2 * 6 + 2  # tab 0's tip, pushed up into facet 0
    points[tip] = [points[tip, 0], 5.0]
    with pytest.raises(ValueError, match=r"cannot be laid flat: .*tab 0"):
        _check_no_overlap(replace(p, points=points))


designs = st.builds(
    kresling.Design,
    n=st.integers(min_value=3, max_value=24),
    lam=st.floats(min_value=0.55, max_value=0.99),
    Lc=st.floats(min_value=0.0, max_value=120.0),
    R=st.floats(min_value=10.0, max_value=200.0),
    chirality=st.sampled_from([1, -1]),
)


@settings(max_examples=60, deadline=None)
@given(designs)
def test_any_design_is_exact_or_refused_by_name(d):
    """Over a wide design space the pattern is exact, or a tab does not fit and the error says
    which parameter; it never comes out wrong."""
    try:
        p = crease_pattern(d)
    except ValueError as error:
        assert str(error).startswith(("tab_height", "closing_tab_width"))
        return
    tol = 1e-12 * max(d.R, d.Lc)
    for kind, length in (("valley", d.Vg), ("mountain", d.Mg), ("tab", d.P)):
        np.testing.assert_allclose(_lengths(p.points, p.edges_of_kind(kind)), length, atol=tol)
    for state in ("contracted", "extended"):
        folded = p.folded(state)
        flat, bent = _lengths(p.points, p.edges), _lengths(folded, p.edges)
        np.testing.assert_allclose(bent, flat, atol=tol)


def test_the_titles_of_a_sheet_beside_its_folded_states_do_not_overlap():
    # The fabrication notebook's figure: the sheet's one-line title ran into its neighbour's.
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from kresling.fabrication import cut_sheet
    from kresling.fabrication.plot import plot_folded, plot_sheet

    design = kresling.Design(10, 0.9, 15.0, 30.0)
    fig = plt.figure(figsize=(11, 4.2))
    axes = [plot_sheet(cut_sheet(design, "paper"), fig.add_subplot(131)),
            plot_folded(crease_pattern(design), "extended", fig.add_subplot(132, projection="3d")),
            plot_folded(crease_pattern(design), "contracted",
                        fig.add_subplot(133, projection="3d"))]
    fig.tight_layout()
    renderer = fig.canvas.get_renderer()
    boxes = [ax.title.get_window_extent(renderer) for ax in axes]
    for left, right in zip(boxes, boxes[1:]):
        assert left.x1 < right.x0, (left, right)
    assert boxes[0].x0 >= 0 and boxes[-1].x1 <= fig.bbox.x1  # inside the figure
    assert "R=30\u00a0mm" in axes[0].get_title()  # wrapped between words, not in a quantity
    plt.close(fig)
