"""A Kresling cell whose contracted state is flat (Lc = 0), pressed past it: without contact
its top polygon passes through its base and the cell ends inside out; with panel contact
([contact] self = true, the "self_contact" family on the specimen's triangles) it comes to
rest on itself, the top above the base, with every pair of panels apart at every increment.

Independent references: whether the top passes through the base is read off the geometry
(the top polygon's nodes against the base polygon's plane, and each node's move between
increments against the base's triangles, by the segment-triangle test of
tests/triangle_intersection_helpers.py); no solver quantity decides it."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.geometry import Design
from kresling.model import kresling_specimen
from kresling.model.masses import specimen_triangles
from kresling.solvers import solve_displacement_control, solve_force_control
from triangle_intersection_helpers import intersecting_pairs, segment_crosses_triangle

N = 8
D_HAT = 0.5          # mm
PRESS = 30.0         # N on the top polygon, shared by its corners (over five times the
                     # snap force of the same cell with Lc = 1 mm, 5.3 N)


def _cell(contact: bool):
    """The flat-contracting cell, extended, its base polygon held; with contact its
    triangles are a self_contact family. The specimen, the model and the triangles."""
    design = Design(N, 0.8, 0.0, 30.0)
    fixed = np.zeros((2 * (N + 1), 3), bool)
    fixed[: N + 1] = True                                   # the base polygon held
    specimen = kresling_specimen(design, ["extended"], fixed=fixed)
    model = specimen.model
    triangles = specimen_triangles(specimen)
    if contact:
        model = model.replace(families={"self_contact": {
            "triangles": triangles, "distance": [D_HAT], "stiffness": [1.0]}})
    return specimen, model, triangles


def _pressed(contact: bool):
    _, model, triangles = _cell(contact)
    forces = np.zeros((model.num_nodes, 3))
    forces[N + 1: 2 * N + 1, 2] = -PRESS / N
    path = solve_force_control(model, forces, 80)
    assert path.completed, path.message
    positions = [model.nodes + u.reshape(-1, 3) for u in path.displacement]
    return model, triangles, path, [model.nodes] + positions


def _base_triangles(triangles):
    base = set(range(N + 1))
    return [t for t in triangles if set(t) <= base]


def _crossings(triangles, positions):
    """(increment, node) of every top node whose move in that increment passes through a
    triangle of the base polygon."""
    found = []
    for k in range(1, len(positions)):
        before, after = positions[k - 1], positions[k]
        for node in range(N + 1, 2 * (N + 1)):
            if any(segment_crosses_triangle(before[node], after[node], *after[t])
                   for t in _base_triangles(triangles)):
                found.append((k, node))
    return found


@pytest.fixture(scope="module")
def free():
    return _pressed(contact=False)


@pytest.fixture(scope="module")
def touching():
    return _pressed(contact=True)


def test_without_contact_the_top_passes_through_the_base(free):
    _, triangles, _, positions = free
    # The flat state is no obstacle to the bars and hinges: the top goes through the base's
    # plane (measured: 52.6 mm below it under the full load, the cell inside out) and its
    # centre through the base polygon itself.
    assert positions[-1][N + 1:, 2].max() < -5.0
    centre = 2 * N + 1
    assert any(node == centre for _, node in _crossings(triangles, positions))


def test_with_contact_the_cell_rests_on_itself_with_its_panels_apart(touching):
    model, triangles, path, positions = touching
    # Every node of the top stays above the base at every increment, none passes through a
    # base triangle between increments, and no two panels intersect at any increment.
    assert min(x[N + 1:, 2].min() for x in positions) > 0.0
    assert _crossings(triangles, positions) == []
    for k, x in enumerate(positions[1:], start=1):
        assert intersecting_pairs(x, triangles) == [], f"increment {k}"
    # The nearest pair ends inside the barrier's range, apart (measured 0.049 mm), and the
    # layers of the flattened cell stack a few d_hat high (measured 0.60 mm).
    gaps = [float(model.element_state(u)["self_contact_gap"].min()) for u in path.displacement]
    assert min(gaps) > 0.0 and gaps[-1] < D_HAT
    assert 0.0 < positions[-1][N + 1:, 2].mean() < 4 * D_HAT


@pytest.mark.parametrize("adaptive", [False, True], ids=["fixed", "adaptive"])
def test_a_prescribed_motion_through_the_base_is_refused_at_contact_not_taken(adaptive):
    # The top polygon driven 3 mm past the base (displacement control, in fixed or adaptive
    # increments): the drive sets the top's DOFs itself, so the barrier cannot shorten that
    # move as it shortens Newton's corrections. Without contact the drive takes the top
    # through the base; with it, the increments are halved as the top nears the base and the
    # path ends there, saying why, with the top above the base at every recorded increment.
    for contact in (False, True):
        specimen, model, _ = _cell(contact)
        height = float(specimen.level_height[-1])
        prescribed = np.zeros((model.num_nodes, 3))
        prescribed[N + 1:, 2] = -(height + 3.0)
        path = solve_displacement_control(model, prescribed, 100, extrapolation=3,
                                          adaptive=adaptive)
        top = [(model.nodes + u.reshape(-1, 3))[N + 1:, 2].min() for u in path.displacement]
        if not contact:
            assert path.completed and top[-1] == pytest.approx(-3.0)
        else:
            assert not path.completed
            assert "carry panels into each other" in path.message
            assert min(top) > 0.0
            # It ended where the panels touch: the top within a few d_hat of the base
            # (the flattened cell's layers), past 95 % of the way down.
            assert path.load_factor[-1] > 0.95 * height / (height + 3.0)
