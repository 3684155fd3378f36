"""The reference written from Origami Simulator's equations (kresling/testing/origami_simulator.py):
its forces are its energy's gradient, its hinge angles are the faces' fold angles, and its
damped dynamics comes to rest where the forces vanish."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kresling.testing import origami_simulator as osm
from kresling.io import fold_angles, read_fold, read_pattern
from public_files import ORIGAMI_SIMULATOR, SHEET, SPEC


@pytest.fixture(scope="module")
def bird():
    pattern = read_pattern(ORIGAMI_SIMULATOR / "flappingBird.svg")
    return pattern, osm.build(pattern)


def test_forces_are_minus_the_energys_gradient_with_every_ingredient(bird):
    _, model = bird
    x = model.x0 + 0.05 * np.random.default_rng(3).standard_normal(model.x0.shape)
    force = osm.forces(model, x, np.zeros_like(x), 0.6)
    h = 1e-6
    gradient = np.zeros_like(x)
    for index in np.ndindex(x.shape):
        up, down = x.copy(), x.copy()
        up[index] += h
        down[index] -= h
        gradient[index] = (osm.energy(model, up, 0.6) - osm.energy(model, down, 0.6)) / (2 * h)
    # Central differences of an energy of order 10 with h = 1e-6: error ~ h^2 E''' + 1e-16/h,
    # well under 1e-6 of the largest force (~60).
    assert np.max(np.abs(force + gradient)) < 1e-6 * np.max(np.abs(gradient))


def test_hinge_angles_are_the_faces_fold_angles_where_the_faces_are_triangles():
    # The fold spec's diagonal: two triangles and one crease, turned rigidly by 70 deg.
    pattern = read_fold(SPEC / "diagonal-cp.fold", **SHEET)
    model = osm.build(pattern, [0, 0, 0, 0, 70.0])
    x = model.x0.copy()
    u, v = model.hinges[0, :2]
    axis = (x[v] - x[u]) / np.linalg.norm(x[v] - x[u])
    wing = model.hinges[0, 3]
    r = x[wing] - x[u]
    angle = math.radians(70.0)   # Rodrigues' rotation of the right wing about the axis
    x[wing] = x[u] + (r * math.cos(angle) + np.cross(axis, r) * math.sin(angle)
                      + axis * np.dot(axis, r) * (1 - math.cos(angle)))
    theta = osm.hinge_angles(model, x)[0]
    expected = fold_angles(pattern.faces, pattern.edges, x)[model.hinge_edge[0]]
    assert abs(theta) == pytest.approx(math.radians(70.0), abs=1e-12)
    assert theta == pytest.approx(expected, abs=1e-12)


def test_the_damped_dynamics_comes_to_rest_at_a_rigid_fold_of_one_crease():
    # One crease folded to 60 % of 90 deg: nothing resists it but its own spring, so the
    # rest state is the rigid fold at 54 deg with the bars at their lengths.
    pattern = read_fold(SPEC / "diagonal-cp.fold", **SHEET)
    model = osm.build(pattern, [0, 0, 0, 0, 90.0])
    run = osm.integrate(model, 0.6)
    assert run.settled
    assert np.degrees(osm.hinge_angles(model, run.x)[0]) == pytest.approx(54.0, abs=1e-3)
    lengths = np.linalg.norm(run.x[model.bars[:, 1]] - run.x[model.bars[:, 0]], axis=1)
    np.testing.assert_allclose(lengths, model.bar_length, rtol=1e-6)
