"""Model construction: defaults from geometry, topology rules, and bad input."""

import math

import numpy as np
import pytest

from kresling.model import Model, panel_topology

SQUARE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)


def two_triangles(**kwargs):
    args = dict(bar_modulus=100.0, hinge_stiffness=1.0)
    args.update(kwargs)
    return Model.from_panels(SQUARE, [[0, 1, 2], [0, 2, 3]], **args)


def test_defaults_are_the_stress_free_geometry():
    m = two_triangles()
    assert len(m.bars) == 5 and len(m.hinges) == 1
    assert m.hinge_rest_angle[0] == pytest.approx(math.pi, abs=1e-8)
    assert np.allclose(sorted(m.bar_rest_length), [1, 1, 1, 1, math.sqrt(2)])
    assert m.hinge_length[0] == pytest.approx(math.sqrt(2))
    state = m.element_state()
    assert np.abs(state["bar_strain"]).max() < 1e-15 and np.abs(state["hinge_moment"]).max() < 1e-12


def test_quad_splits_on_the_shorter_diagonal_and_marks_a_bend():
    nodes = SQUARE.copy()
    nodes[2] = [1.5, 1.5, 0]  # diagonal 1-3 is now the shorter one
    topo = panel_topology(nodes, [[0, 1, 2, 3]])
    assert topo.triangles.tolist() == [[0, 1, 3], [1, 2, 3]]
    assert topo.hinges.tolist() == [[1, 3, 0, 2]] and topo.hinge_is_bend.tolist() == [True]


def test_n5b8_adds_a_centre_node():
    topo = panel_topology(SQUARE, [[0, 1, 2, 3]], split="N5B8")
    assert len(topo.nodes) == 5 and np.allclose(topo.nodes[4], [0.5, 0.5, 0])
    assert len(topo.triangles) == 4 and topo.hinge_is_bend.all() and len(topo.hinges) == 4


def test_polygon_split_recursively():
    angles = 2 * np.pi * np.arange(6) / 6
    hexagon = np.column_stack([np.cos(angles), np.sin(angles), np.zeros(6)])
    topo = panel_topology(hexagon, [list(range(6))])
    assert len(topo.triangles) == 4 and len(topo.hinges) == 3  # 3 diagonals


def test_three_triangles_on_an_edge():
    # Edge 0-1 shared by three triangles: MERLIN2 puts 3 bars and 3 hinges on it; the
    # de-duplicated topology one bar and the two hinges between neighbours around the edge.
    nodes = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1, 0], [0.5, 0, 1]], float)
    panels = [[0, 1, 2], [0, 1, 3], [0, 1, 4]]
    dup = panel_topology(nodes, panels)
    assert sum(1 for b in dup.bars.tolist() if b == [0, 1]) == 3
    assert sum(1 for h in dup.hinges.tolist() if h[:2] == [0, 1]) == 3
    dedup = panel_topology(nodes, panels, duplicate_shared_edges=False)
    assert sum(1 for b in dedup.bars.tolist() if b == [0, 1]) == 1
    wings = sorted(sorted(h[2:]) for h in dedup.hinges.tolist())
    # Around the edge: 2 at +y (0 deg), 4 at +z (90 deg), 3 at -y (180 deg); the widest
    # opening (180 deg, from 3 back to 2) carries no hinge.
    assert wings == [[2, 4], [3, 4]]


def test_replace_and_immutability():
    m = two_triangles()
    with pytest.raises(ValueError):
        m.bars[0, 0] = 3
    fixed = np.zeros((4, 3), bool)
    fixed[0] = True
    m2 = m.replace(fixed=fixed)
    assert m2.fixed[0].all() and not m.fixed.any()
    assert "4 nodes" in repr(m2)


@pytest.mark.parametrize(
    "change, message",
    [
        (dict(bars=[[0, 7]]), r"bars\[0\] = \[0, 7\]: node index out of range"),
        (dict(hinges=[[0, 2, 1, 9]]), r"hinges\[0\] = \[0, 2, 1, 9\]: node index out of range"),
        (dict(bars=[[1, 1]]), r"bar 0 \(nodes 1, 1\): a node appears twice"),
        (dict(bar_area=-1.0), r"bar 0 \(nodes 0, 2\): area = -1 is invalid: must be > 0"),
        (dict(bar_modulus=float("nan")), r"modulus = nan is invalid: must be a finite number"),
        (dict(hinge_stiffness=-0.5), r"hinge 0 \(nodes 0, 2, 1, 3\): stiffness = -0.5 is invalid"),
        (dict(hinge_limits=(0.2, 0.1)), r"spring limits \(0.2, 0.1\) are invalid"),
        (dict(bar_law="rubber"), r"bar_law = 'rubber' is invalid"),
        (dict(hinge_rest_angle=[7.0]), r"rest angle = 7 is invalid: must be in \[0, 2 pi\)"),
        (dict(fixed=np.zeros((3, 3), bool)), r"fixed has shape \(3, 3\)"),
    ],
)
def test_invalid_models_name_the_element(change, message):
    base = two_triangles()
    kwargs = dict(bar_modulus=100.0, hinge_stiffness=1.0)
    bars, hinges = base.bars, base.hinges
    if "bars" in change:
        bars = np.array(change.pop("bars"))
    if "hinges" in change:
        hinges = np.array(change.pop("hinges"))
    kwargs.update(change)
    with pytest.raises(ValueError, match=message):
        Model(SQUARE, bars, hinges, **kwargs)


def test_degenerate_geometry():
    collinear = SQUARE.copy()
    collinear[3] = [2, 2, 0]  # node 3 on the line through 0 and 2 (the hinge axis)
    with pytest.raises(ValueError, match=r"wing node 3 lies on the axis line"):
        Model(collinear, [[0, 1]], [[0, 2, 1, 3]], bar_modulus=1.0, hinge_stiffness=1.0)
    coincident = SQUARE.copy()
    coincident[1] = coincident[0]
    with pytest.raises(ValueError, match=r"bar 0 \(nodes 0, 1\): zero length"):
        Model(coincident, [[0, 1]], np.zeros((0, 4), int), bar_modulus=1.0, hinge_stiffness=1.0,
              bar_rest_length=[1.0])
    nan = SQUARE.copy()
    nan[2, 1] = np.nan
    with pytest.raises(ValueError, match=r"node 2: coordinate 1 = nan is not finite"):
        Model(nan, [[0, 1]], np.zeros((0, 4), int), bar_modulus=1.0, hinge_stiffness=1.0,
              bar_rest_length=[1.0], hinge_rest_angle=[])


def test_invalid_panels():
    with pytest.raises(ValueError, match=r"panel 1: has 2 nodes, must have at least 3"):
        panel_topology(SQUARE, [[0, 1, 2], [0, 2]])
    with pytest.raises(ValueError, match=r"panel 0: node 4 is out of range"):
        panel_topology(SQUARE, [[0, 1, 4]])
    with pytest.raises(ValueError, match=r"split = 'N9' is invalid"):
        panel_topology(SQUARE, [[0, 1, 2]], split="N9")


def test_hinge_angle_exact_by_default_and_merlin2s_on_request():
    # Wing 3 lifted by ~1e-9 out of the flat square: the exact (atan2) angle reads the lift
    # about the diagonal 0-2 to a few ulps of pi; MERLIN2's arccosine is ~1e-8 rad coarse
    # there (acos(-1 + d) = pi - sqrt(2 d): one ulp of the cosine is 2.1e-8 rad).
    nodes = SQUARE.copy()
    nodes[3] = [0.0, np.cos(1e-9), np.sin(1e-9)]
    lift = math.atan2(nodes[3, 2], nodes[3, 1] / math.sqrt(2))  # its distance to the axis
    flat = two_triangles()
    for form, tolerance in (("exact", 1e-15), ("merlin2", 3e-8)):
        m = two_triangles(hinge_angle=form)
        assert m.hinge_angle.tolist() == [{"exact": 0, "merlin2": 1}[form]]
        assert m.replace(fixed=m.fixed).hinge_angle.tolist() == m.hinge_angle.tolist()
        angle = m.element_state((nodes - SQUARE).ravel())["hinge_angle"][0]
        assert abs(abs(angle - flat.hinge_rest_angle[0]) - lift) <= tolerance, form
    assert flat.hinge_rest_angle[0] == pytest.approx(math.pi, abs=1e-15)
    with pytest.raises(ValueError, match="hinge_angle = 'acos' is invalid"):
        two_triangles(hinge_angle="acos")
