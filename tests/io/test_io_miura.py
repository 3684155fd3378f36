"""The generated Miura-ori sheet: its geometry against the closed form it is built from."""

import math

import numpy as np
import pytest

from kresling.io import miura_sheet


def _corner_angles(vertices, face):
    out = []
    for k in range(4):
        p, a, b = vertices[face[k]], vertices[face[k - 1]], vertices[face[(k + 1) % 4]]
        u, v = a - p, b - p
        out.append(math.degrees(math.acos(u @ v / np.linalg.norm(u) / np.linalg.norm(v))))
    return out


@pytest.mark.parametrize("fold_angle", [0.0, 30.0, 75.0])
def test_panels_are_rigid_parallelograms_at_any_fold_angle(fold_angle):
    # Rigid folding keeps every side (a along y, b along x) and every corner angle (gamma
    # or 180 - gamma): exact up to rounding, asserted to 1e-9 (of 10 mm, of 60 degrees).
    sheet = miura_sheet(3, 4, a=10.0, b=7.0, sector_angle=60.0, fold_angle=fold_angle)
    assert (sheet.num_vertices, sheet.num_faces) == (20, 12)
    v = sheet.vertices
    lengths = sorted({round(float(np.linalg.norm(v[i] - v[j])), 9) for i, j in sheet.edges})
    assert lengths == [7.0, 10.0]
    for face in sheet.faces:
        angles = sorted(_corner_angles(v, face))
        assert angles == pytest.approx([60.0, 60.0, 120.0, 120.0], abs=1e-9)
    # Flat exactly when the fold angle is 0; folded, each crease is a mountain or a valley.
    assignments = set(sheet.edges_assignment) - {"B"}
    assert assignments == ({"F"} if fold_angle == 0 else {"M", "V"})
    assert (np.ptp(v[:, 2]) == 0) == (fold_angle == 0)


def test_the_sheet_builds_a_model():
    from kresling.model.calibration import SheetMaterial
    from kresling.model.pattern_model import build_pattern_model
    pm = build_pattern_model(miura_sheet(2, 2), material=SheetMaterial(5e3, 0.35, 0.127))
    assert pm.model.num_nodes == 9 + 4          # vertices, then one centre per panel (N5B8)


@pytest.mark.parametrize("kwargs, name", [
    (dict(nx=0, ny=2), "nx"), (dict(nx=2, ny=-1), "ny"), (dict(nx=2, ny=2, a=0.0), "a"),
    (dict(nx=2, ny=2, sector_angle=90.0), "sector_angle"),
    (dict(nx=2, ny=2, fold_angle=-1.0), "fold_angle"),
    (dict(nx=2000, ny=2000), "nx, ny")])
def test_bad_input_names_the_parameter(kwargs, name):
    with pytest.raises(ValueError, match=rf"^{name} = "):
        miura_sheet(**kwargs)
