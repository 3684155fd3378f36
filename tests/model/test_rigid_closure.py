"""Loop closure of fold angles at a pattern's interior vertices (kresling.model.rigid_closure),
against rigidly folded Miura-ori sheets built in closed form."""

import numpy as np
import pytest

from kresling.io import miura_sheet
from kresling.model.rigid_closure import rigid_closure


def _closure(pattern, angles):
    return rigid_closure(pattern.vertices, pattern.edges, angles, pattern.faces)


def _crease_angles(pattern):
    """The pattern's fold angles, NaN on the rim."""
    angles = np.asarray(pattern.edges_fold_angle, dtype=float).copy()
    angles[np.asarray(pattern.edges_assignment) == "B"] = np.nan
    return angles


@pytest.mark.parametrize("fold_angle", [10.0, 45.0, 80.0])
def test_the_angles_of_a_rigidly_folded_miura_sheet_close_at_every_interior_vertex(fold_angle):
    flat = miura_sheet(4, 3, sector_angle=55.0, fold_angle=0.0)
    folded = miura_sheet(4, 3, sector_angle=55.0, fold_angle=fold_angle)
    closure = _closure(flat, _crease_angles(folded))
    # (4 - 1) x (3 - 1) interior vertices, each of degree 4 with every crease folded.
    assert len(closure.vertices) == 6
    # The closed form's angles are exact to rounding: the product of four rotations is the
    # identity to ~1e-15, its angle (from its sine and cosine) ~1e-13 deg.
    assert closure.error_deg.max() < 1e-9
    assert closure.report(1.0)["incompatible"] == 0


def test_one_crease_moved_off_its_folded_angle_opens_its_two_vertices():
    flat = miura_sheet(4, 3, fold_angle=0.0)
    folded = miura_sheet(4, 3, fold_angle=40.0)
    angles = _crease_angles(folded)
    interior = set(_closure(flat, angles).vertices.tolist())
    # An interior crease between two interior vertices, moved by 3 deg.
    edge = next(e for e, (u, v) in enumerate(flat.edges.tolist())
                if u in interior and v in interior)
    angles[edge] += 3.0
    closure = _closure(flat, angles)
    opened = set(closure.incompatible(1.0).tolist())
    assert opened == set(flat.edges[edge].tolist())
    # One rotation of the loop off by 3 deg: the loop fails to close by about that much
    # (exactly 3 deg if it were the loop's only rotation; the others turn its axis).
    assert closure.error_deg.max() == pytest.approx(3.0, rel=0.2)


def test_a_flat_folded_vertex_closes_where_kawasakis_theorem_holds():
    # The Miura-ori folded flat: every crease at +-180 deg, its sector angles alternating
    # gamma, 180 - gamma round each vertex (Kawasaki's sums of 180 deg).
    flat = miura_sheet(3, 3, sector_angle=60.0, fold_angle=0.0)
    folded = miura_sheet(3, 3, sector_angle=60.0, fold_angle=45.0)
    angles = 180.0 * np.sign(_crease_angles(folded))
    assert _closure(flat, angles).error_deg.max() < 1e-9
    # A degree-3 vertex cannot fold flat: three half-turns about lines in the plane leave
    # a half-turn.
    vertices = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [-0.5, 0.8, 0.0],
                         [-0.5, -0.8, 0.0]])
    edges = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [2, 3], [3, 1]])
    faces = [(0, 1, 2), (0, 2, 3), (0, 3, 1)]
    star = rigid_closure(vertices, edges, [180.0, -180.0, 180.0] + [np.nan] * 3, faces)
    assert star.vertices.tolist() == [0]
    assert star.error_deg[0] == pytest.approx(180.0)


def test_a_vertex_with_a_free_crease_is_not_checked():
    flat = miura_sheet(3, 3, fold_angle=0.0)
    angles = _crease_angles(miura_sheet(3, 3, fold_angle=30.0))
    checked = _closure(flat, angles).vertices
    u, v = next((u, v) for u, v in flat.edges.tolist() if u in checked and v in checked)
    edge = flat.edges.tolist().index([u, v])
    angles[edge] = np.nan
    assert set(_closure(flat, angles).vertices.tolist()) == set(checked.tolist()) - {u, v}


def test_a_pattern_that_is_not_flat_has_no_closure():
    folded = miura_sheet(3, 3, fold_angle=30.0)
    assert _closure(folded, _crease_angles(folded)) is None


def test_a_vertex_with_a_crease_of_no_length_is_not_checked():
    flat = miura_sheet(3, 3, fold_angle=0.0)
    angles = _crease_angles(miura_sheet(3, 3, fold_angle=30.0))
    checked = set(_closure(flat, angles).vertices.tolist())
    vertices = np.array(flat.vertices, dtype=float)
    u, v = next((u, v) for u, v in flat.edges.tolist() if u in checked and v in checked)
    vertices[v] = vertices[u]   # the crease (u, v) shrunk to a point
    closure = rigid_closure(vertices, flat.edges, angles, flat.faces)
    assert not {u, v} & set(closure.vertices.tolist())
    assert np.all(np.isfinite(closure.error_deg))
