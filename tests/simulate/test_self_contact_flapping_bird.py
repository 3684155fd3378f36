"""Origami Simulator's flapping bird flat-folded with its panels kept apart: every crease
driven to its full target (+-180 deg), in one stage from the flat sheet, with Origami
Simulator's ingredients in this model's units (bars of EA = 20 / 0.7 N against creases of
1 N mm/rad per mm, face-angle springs of 0.2 R / 0.7 N mm/rad^2, R the sheet's bounding
radius in mm; docs/folding.md) on this package's own triangles (the quads split N4B5).

Independent reference: every increment is checked for intersecting triangles by a
separate test (tests/triangle_intersection_helpers.py), which shares no code with the
solver's distances or its collision check; the creases' senses are measured from the
faces' normals (kresling.io.fold_angles), not from the model's hinges."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.testing import origami_simulator as osm
from kresling.io import fold_angles, read_pattern
from kresling.simulate import simulate
from public_files import ORIGAMI_SIMULATOR, STIFF
from triangle_intersection_helpers import intersecting_pairs

BIRD = ORIGAMI_SIMULATOR / "flappingBird.svg"
D_HAT = 2.0  # [mm], on a sheet 533 mm across


def _bird_problem(pattern, contact):
    data = {"pattern": {"file": str(BIRD), "split": "N4B5"},
            "material": osm.material_in_model_units(pattern, STIFF),
            "support": [{"nodes": list(pattern.faces[0][:3]), "fix": "xyz"}],
            # Every mountain and valley crease to its edges_foldAngle.
            "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
            "analysis": {"method": "fold", "steps": 40, "snap": True}}
    if contact:
        data["contact"] = {"distance": D_HAT, "self": True}
    return data


def _intersecting_increments(sim):
    triangles = sim.pattern_model.elements.triangles
    return [k + 1 for k, u in enumerate(sim.path.displacement)
            if intersecting_pairs(sim.model.nodes + u.reshape(-1, 3), triangles)]


@pytest.fixture(scope="module")
def pattern():
    return read_pattern(BIRD)


def test_without_contact_the_flat_folded_bird_passes_through_itself(pattern):
    free = simulate(_bird_problem(pattern, contact=False), progress=False)
    # Measured: crossing triangles at 21 of its increments, from about halfway on.
    assert len(_intersecting_increments(free)) > 10


def test_the_bird_flat_folds_to_its_targets_with_no_two_triangles_intersecting(pattern):
    sim = simulate(_bird_problem(pattern, contact=True), progress=False)
    assert sim.path.completed, sim.path.message
    assert sim.path.load_factor[-1] == pytest.approx(1.0)
    assert _intersecting_increments(sim) == []
    gaps = sim.history_columns()["min_gap"]
    # Apart at every increment, the layers pressed within d_hat of each other at the end
    # (measured 0.031 mm: the creases' moments toward +-180 deg press the stacked layers).
    assert (gaps > 0).all() and gaps[-1] < D_HAT
    # Every crease folded its own way, by the faces' normals (more than 1 deg).
    x = (sim.model.nodes + sim.path.displacement[-1].reshape(-1, 3))[:pattern.num_vertices]
    creases = np.array([a in "MV" for a in pattern.edges_assignment])
    reached = np.degrees(fold_angles(pattern.faces, pattern.edges, x))[creases]
    wanted = np.sign(np.nan_to_num(pattern.edges_fold_angle)[creases])
    assert np.all(np.sign(reached) == wanted) and np.all(np.abs(reached) > 1.0)
