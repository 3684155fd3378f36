"""Panels of a thickness ([contact] thickness = t): their mid-surfaces are kept at least t
apart and t/2 off the rigid planes, the barrier acting within d_hat beyond that.

Independent references: the mid-surfaces' distance is measured with IPC Toolkit's own
distances (the ``ipctk`` package) over every point-triangle and edge-edge pair of triangles
that share no node, and a node's height over a floor from its coordinates; t = 0 is held to
the run without the key, bit for bit. The offset barrier's gradient and Hessian are checked
against finite differences in cpp/tests/test_contact_offset.cpp."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from kresling.model import Model
from kresling.simulate import simulate
from kresling.solvers import solve_force_control

STIFF = {"calibration": "manual", "bar_modulus": 1e4, "bar_area": 1.0,
         "fold_stiffness": 1.0, "bend_stiffness": 10.0}
D_HAT = 0.2


def _folded_flat(thickness=None, steps=20):
    """A 10 x 10 mm sheet with one crease down its middle (x = 5), the left panel held, the
    crease folded to 180 deg: without thickness the right panel would lie on the left one.
    The panels' diagonals are mirror images, so that no edge crosses another when folded."""
    vertices = [[0, 0, 0], [5, 0, 0], [10, 0, 0], [10, 10, 0], [5, 10, 0], [0, 10, 0]]
    contact = {"distance": D_HAT, "self": True}
    if thickness is not None:
        contact["thickness"] = thickness
    return {"pattern": {"vertices": vertices, "panels": [[0, 1, 4, 5], [2, 3, 4, 1]],
                        "split": "N4B5"},
            "material": STIFF, "laws": {"fold": "linear", "bend": "linear"},
            "support": [{"nodes": [0, 1, 4, 5], "fix": "xyz"}],
            "actuation": [{"edges": [[1, 4]], "fold_angle_deg": 180.0}],
            "analysis": {"method": "fold", "steps": steps}, "contact": contact}


def _mid_surface_distance(ipctk, x, triangles):
    """The smallest distance between two primitives of the mesh that share no node (the
    pairs the barrier sees), by ipctk's distances [mm]."""
    triangles = [tuple(t) for t in triangles]
    edges = sorted({tuple(sorted((t[i], t[(i + 1) % 3]))) for t in triangles for i in range(3)})
    nodes = sorted({n for t in triangles for n in t})
    squared = [ipctk.point_triangle_distance(x[p], *x[list(t)])
               for p in nodes for t in triangles if p not in t]
    squared += [ipctk.edge_edge_distance(*x[list(a)], *x[list(b)])
                for a, b in itertools.combinations(edges, 2) if not set(a) & set(b)]
    return math.sqrt(min(squared))


@pytest.mark.parametrize("thickness", [0.5, 1.0])
def test_panels_folded_flat_stop_with_their_mid_surfaces_the_thickness_apart(thickness):
    ipctk = pytest.importorskip("ipctk", reason="ipctk (IPC Toolkit's Python bindings) "
                                "measures the panels' distance independently")
    sim = simulate(_folded_flat(thickness), progress=False)
    assert sim.path.completed, sim.path.message
    triangles = sim.pattern_model.elements.triangles
    gaps = sim.history_columns()["min_gap"]
    for k, u in enumerate(sim.path.displacement):
        x = sim.model.nodes + u.reshape(-1, 3)
        distance = _mid_surface_distance(ipctk, x, triangles)
        # Never closer than t; min_gap is that distance less t (both are exact distances
        # of the same pairs, computed apart: 1e-12 mm leaves room for their rounding).
        assert distance > thickness, f"increment {k + 1}"
        assert gaps[k] == pytest.approx(distance - thickness, abs=1e-12)
    # At the end the barrier holds the faces within its range d_hat: the mid-surfaces are
    # between t and t + d_hat apart (measured: 0.197 and 0.195 mm beyond t). The free edge
    # (nodes 2, 3) stands over the held panel at a height z a little above that: the
    # nearest pair is the folded panel's diagonal passing the held panel's edge, at
    # z / sqrt(1 + z^2 / 100), less than z by under 0.01 mm for z < 1.3 mm.
    assert thickness < distance < thickness + D_HAT
    assert 0 < gaps[-1] < D_HAT
    assert distance <= x[[2, 3], 2].min() < distance + 0.01


def test_a_thicker_sheet_stops_further_open():
    # The free edge's height over the held panel grows with the thickness, by the
    # thickness's difference give or take d_hat (each run ends with its faces' gap in
    # (0, d_hat)); without thickness it ends within d_hat.
    heights = []
    for thickness in (0.0, 0.5, 1.0):
        sim = simulate(_folded_flat(thickness), progress=False)
        x = sim.model.nodes + sim.path.displacement[-1].reshape(-1, 3)
        heights.append(x[[2, 3], 2].min())
    assert np.diff(heights) == pytest.approx([0.5, 0.5], abs=D_HAT)
    assert heights[0] < D_HAT


def test_no_thickness_is_the_problem_without_the_key_to_the_bit():
    without = simulate(_folded_flat(None), progress=False)
    zero = simulate(_folded_flat(0.0), progress=False)
    np.testing.assert_array_equal(zero.path.displacement, without.path.displacement)
    a, b = zero.history_columns(), without.history_columns()
    assert a.keys() == b.keys()
    for key in a:
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)
    # The families' tables too: no thickness column, as before the key existed.
    assert "thickness" not in zero.model.family("self_contact")


def _node_over_floor(thickness, z=1.0, d_hat=0.2, kappa=100.0):
    families = {"springs": {"nodes": [0], "stiffness": [[1.0, 1.0, 1.0]],
                            "anchor": [[0.0, 0.0, z]]},
                "contact": {"nodes": [0], "origin": [[0.0, 0.0, 0.0]],
                            "normal": [[0.0, 0.0, 1.0]], "distance": [d_hat],
                            "stiffness": [kappa], "thickness": [thickness]}}
    return Model([[0.0, 0.0, z]], [], [], bar_modulus=1.0, hinge_stiffness=1.0,
                 families=families)


@pytest.mark.parametrize("thickness", [0.4, 1.0])
def test_a_node_pushed_onto_a_floor_stops_half_the_thickness_above_it(thickness):
    # A spring holding the node 1 mm over the floor, pushed down by 3 N: it stops within
    # d_hat beyond t/2, even in one step, and the plane's gap is its height less t/2.
    model = _node_over_floor(thickness)
    for steps in (1, 10):
        path = solve_force_control(model, [0.0, 0.0, -3.0], steps, tolerance=1e-10)
        assert path.completed, path.message
        z = 1.0 + path.displacement[:, 2]
        assert (z > thickness / 2).all()
        assert thickness / 2 < z[-1] < thickness / 2 + 0.2
        gap = model.element_state(path.displacement[-1])["contact_gap"][0]
        assert gap == pytest.approx(z[-1] - thickness / 2, abs=1e-15)


def test_a_node_starting_within_half_the_thickness_of_a_plane_is_refused():
    with pytest.raises(ValueError, match=r"contact: thickness = 2.5 mm is invalid: node 0 "
                                         r"starts 1 mm from plane 0.*must be below 2 mm"):
        _node_over_floor(2.5)


def _write(tmp_path, body):
    path = tmp_path / "problem.toml"
    path.write_text(body, encoding="utf-8")
    return path


SHEET = """
[pattern]
vertices = [[0, 0, 0], [5, 0, 0], [10, 0, 0], [10, 10, 0], [5, 10, 0], [0, 10, 0]]
panels = [[0, 1, 4, 5], [2, 3, 4, 1]]
split = "N4B5"

[material]
calibration = "manual"
bar_modulus = 1e4
bar_area = 1.0
fold_stiffness = 1.0
bend_stiffness = 10.0

[[support]]
nodes = [0, 1, 4, 5]
fix = "xyz"

[[actuation]]
edges = [[1, 4]]
fold_angle_deg = 180.0

[analysis]
method = "fold"
steps = 4

[contact]
distance = 0.2
"""


@pytest.mark.parametrize("value, allowed", [
    ("-0.5", r"must be >= 0"), ("nan", "must be a finite number"),
    ("inf", "must be a finite number"), ('"thick"', "must be a finite number"),
    ("true", "must be a finite number")])
def test_a_bad_thickness_is_refused_naming_the_file_and_key(tmp_path, value, allowed):
    path = _write(tmp_path, SHEET + f"self = true\nthickness = {value}\n")
    with pytest.raises(ValueError, match=rf"problem.toml:\d+: \[contact\] key 'thickness' "
                                         rf"= .* is invalid: {allowed}"):
        simulate(path, progress=False)


def test_a_thickness_the_panels_are_closer_than_at_rest_is_refused(tmp_path):
    # At rest the nearest pair not sharing a node is a panel's corner and the panel's other
    # triangle, across its diagonal: 50 / sqrt(125) = 4.472 mm (the panel's own width, in
    # its plane). A thickness of 4.4 mm leaves the barrier (0.2 mm) acting at rest.
    for thickness, message in [(4.5, "would overlap before anything moves; must be below "
                                     r"4.472"),
                               (4.4, r"thickness \+ distance must be below 4.472")]:
        path = _write(tmp_path, SHEET + f"self = true\nthickness = {thickness}\n")
        with pytest.raises(ValueError, match=rf"problem.toml: \[contact\]: self_contact: "
                                             rf"thickness = {thickness} mm .*is invalid: .*"
                                             rf"4.472\d* mm apart at rest.*{message}"):
            simulate(path, progress=False)
    path = _write(tmp_path, SHEET + "self = true\nthickness = 4.2\n")  # 4.2 + 0.2 < 4.472
    assert simulate(path, progress=False).path.completed


def test_a_thickness_no_smaller_than_a_panel_is_refused(tmp_path):
    # Planes alone (no panel pairs to measure): the shortest triangle edge, 5 mm, bounds it.
    floor = 'planes = [{ point = [0, 0, -20], normal = [0, 0, 1] }]\n'
    path = _write(tmp_path, SHEET + floor + "thickness = 5.0\n")
    with pytest.raises(ValueError, match=r"problem.toml: \[contact\] key 'thickness' = 5 mm "
                                         r"is invalid: must be below the size of every panel, "
                                         r"here the shortest edge of its triangles at rest, "
                                         r"5 mm"):
        simulate(path, progress=False)
