"""Contact between panels ([contact] self = true, the "self_contact" family): folds that
would make panels pass through each other stop with the panels apart, at every increment,
while the same folds without contact do pass through.

Independent references: the crossing of two panels is measured by the order of their free
edges along the strip (no solver quantity), and every increment of a fold is checked for
intersecting triangles by a separate segment-triangle test
(tests/triangle_intersection_helpers.py). The kernels are checked against ipctk and finite
differences in tests/elements/test_contact_kernels.py and the family's force against finite
differences in cpp/tests/test_self_contact.cpp; here the force is checked once more through
the Python binding."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.io import pattern_from_arrays, write_fold
from kresling.model import Model
from kresling.simulate import simulate
from triangle_intersection_helpers import intersecting_pairs

STIFF = {"calibration": "manual", "bar_modulus": 1e4, "bar_area": 1.0,
         "fold_stiffness": 1.0, "bend_stiffness": 10.0}
D_HAT = 0.2


def _strip(contact, angle=100.0, steps=20):
    """Three panels in a row (10, 2 and 10 mm wide, 10 mm long), the middle one held, both
    creases folded the same way to ``angle`` [deg]: past 90 deg each (200 deg in all) the
    outer panels' free edges, 2 mm apart when both stand upright, cross."""
    vertices = [[-10, 0], [0, 0], [2, 0], [12, 0], [12, 10], [2, 10], [0, 10], [-10, 10]]
    panels = [[0, 1, 6, 7], [1, 2, 5, 6], [2, 3, 4, 5]]
    data = {"pattern": {"vertices": [v + [0.0] for v in vertices], "panels": panels,
                        "split": "N4B5"},
            "material": STIFF,
            "support": [{"nodes": [1, 2, 5, 6], "fix": "xyz"}],
            "actuation": [{"edges": [[1, 6], [2, 5]], "fold_angle_deg": angle}],
            "analysis": {"method": "fold", "steps": steps}}
    if contact:
        data["contact"] = {"distance": D_HAT, "self": True}
    return data


def _positions(sim, k):
    return sim.model.nodes + sim.path.displacement[k].reshape(-1, 3)


def _edge_gap(sim, k):
    """How far the right panel's free edge (nodes 3, 4) is beyond the left one's (0, 7)
    along x [mm]: positive while they have not crossed, negative once they have."""
    x = _positions(sim, k)
    return float(min(x[3, 0], x[4, 0]) - max(x[0, 0], x[7, 0]))


@pytest.mark.parametrize("angle", [100.0, 150.0])
def test_a_strip_folded_past_its_panels_meeting_stops_with_them_apart(tmp_path, angle):
    # 100 deg: the panels meet in the last increment; 150 deg: in the last eight.
    sim = simulate(_strip(contact=True, angle=angle), progress=False)
    assert sim.path.completed, sim.path.message
    columns = sim.history_columns()
    gaps = [_edge_gap(sim, k) for k in range(sim.path.num_steps)]
    assert min(gaps) > 0.0
    # The nearest panels end within d_hat of each other, and not touching: the barrier
    # holds them at a gap of the order of d_hat.
    assert 1e-3 * D_HAT < columns["min_gap"][-1] < D_HAT
    assert (columns["min_gap"] > 0).all()
    assert columns["energy_self_contact"][-1] > 0
    triangles = sim.pattern_model.elements.triangles
    for k in range(sim.path.num_steps):
        assert not intersecting_pairs(_positions(sim, k), triangles), f"increment {k + 1}"
    written = sim.write(tmp_path)
    assert "contact pairs" in written["view"].read_text(encoding="utf-8")


def test_without_contact_the_same_strip_passes_through_itself():
    sim = simulate(_strip(contact=False), progress=False)
    assert sim.completed, sim.path.message
    assert _edge_gap(sim, sim.path.num_steps - 1) < -1.0
    assert intersecting_pairs(_positions(sim, -1), sim.pattern_model.elements.triangles)


def test_a_distance_that_panels_at_rest_are_within_is_refused():
    # The nearest pair at rest: a corner of the middle panel (2 x 10 mm) and the panel's
    # other triangle, whose diagonal passes 20 / sqrt(104) = 1.961 mm from it.
    problem = _strip(contact=True)
    problem["contact"]["distance"] = 5.0
    with pytest.raises(ValueError, match=r"\[contact\].*distance = 5 mm is invalid.*1.9611\d* mm "
                                         r"apart at rest \(node and triangle, nodes 2, 1, 5, 6\)"
                                         r".*must be below 1.9611"):
        simulate(problem, progress=False)


def test_self_contact_and_planes_together():
    # The strip over a floor 0.5 mm below it: both families act, and min_gap is the
    # smaller of the two kinds of gap.
    problem = _strip(contact=True)
    problem["contact"]["planes"] = [{"point": [0, 0, -0.5], "normal": [0, 0, 1]}]
    sim = simulate(problem, progress=False)
    assert sim.path.completed, sim.path.message
    columns = sim.history_columns()
    assert "energy_contact" in columns and "energy_self_contact" in columns
    assert columns["min_gap"][0] == pytest.approx(0.5, abs=1e-3)  # the floor, at first


def _square_twist(tmp_path, twist_deg=30.0, half=1.0, sheet=3.0):
    """A square twist: a central square of side 2 ``half`` [mm] whose four edges (valleys)
    each start a pleat of two parallel creases (one mountain, one valley) turned by
    ``twist_deg`` from the edge's normal, out to a square sheet of side 2 ``sheet``; every
    vertex is flat-foldable (Kawasaki: opposite sectors sum to 180 deg)."""
    phi = np.radians(twist_deg)

    def turn(k, v):
        c, s = np.cos(k * np.pi / 2), np.sin(k * np.pi / 2)
        return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])

    centre = [turn(k, (-half, -half)) for k in range(4)]
    ray = [turn(k, (np.sin(phi), -np.cos(phi))) for k in range(4)]
    hits = []  # the rays of edge k (from its first and second end) on side k of the sheet
    for k in range(4):
        normal = turn(k, (0.0, -1.0))
        for end in (centre[k], centre[(k + 1) % 4]):
            t = (sheet - end @ normal) / (ray[k] @ normal)
            hits.append(end + t * ray[k])
    corners = [turn(k, (-sheet, -sheet)) for k in range(4)]
    vertices = np.array(centre + hits + corners)
    faces, edges, kinds = [[0, 1, 2, 3]], [], []
    for k in range(4):
        a, b = k, (k + 1) % 4
        ha, hb = 4 + 2 * k, 5 + 2 * k
        faces.append([a, ha, hb, b])                       # the pleat of edge k
        previous_hit = 4 + 2 * ((k - 1) % 4) + 1           # edge k-1's ray from this corner
        faces.append([a, previous_hit, 12 + k, ha])        # the sheet's corner k
        edges += [[a, b], [a, ha], [b, hb]]
        kinds += ["V", "M", "V"]
    pattern = pattern_from_arrays(vertices, faces, edges=edges, edges_assignment=kinds)
    return write_fold(tmp_path / "square_twist.fold", pattern)


#: Soft bars and bends: a square twist does not fold rigidly, its panels must give.
SOFT = {"calibration": "manual", "bar_modulus": 10.0, "bar_area": 1.0,
        "fold_stiffness": 1.0, "bend_stiffness": 0.01}


def _twist_problem(path, contact, target=170.0, steps=40):
    data = {"pattern": {"file": str(path), "split": "N4B5"},
            "material": SOFT, "laws": {"fold": "linear", "bend": "linear"},
            "support": [{"nodes": [0, 1, 2], "fix": "xyz"}],
            "actuation": [{"family": "valley", "fold_angle_deg": target},
                          {"family": "mountain", "fold_angle_deg": -target}],
            "analysis": {"method": "fold", "steps": steps}}
    if contact:
        data["contact"] = {"distance": 0.05, "self": True}
    return data


def _intersecting_increments(sim):
    triangles = sim.pattern_model.elements.triangles
    return [k + 1 for k in range(sim.path.num_steps)
            if intersecting_pairs(_positions(sim, k), triangles)]


def test_a_square_twist_flat_folded_never_passes_through_itself(tmp_path):
    path = _square_twist(tmp_path, twist_deg=20.0)
    # Without contact its pleats fold through the central square and each other: from
    # about halfway on triangles cross (measured at 31 increments; Newton then fails in
    # the last increment, at 0.99995 of the way).
    free = simulate(_twist_problem(path, contact=False, target=180.0), progress=False)
    assert len(_intersecting_increments(free)) > 10
    sim = simulate(_twist_problem(path, contact=True, target=180.0), progress=False)
    assert sim.path.completed, sim.path.message
    assert _intersecting_increments(sim) == []
    gaps = sim.history_columns()["min_gap"]
    assert (gaps > 0).all() and gaps[-1] < 0.05  # the layers end within d_hat, apart


def test_a_mesh_without_pairs_reports_no_gap_and_the_force_is_the_energys_gradient():
    one = Model([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1], [1, 2], [0, 2]], [],
                bar_modulus=1.0, hinge_stiffness=1.0,
                families={"self_contact": {"triangles": [[0, 1, 2]], "distance": [0.1],
                                           "stiffness": [1.0]}})
    state = one.element_state()
    assert state["self_contact_gap"].size == 0 and state["self_contact_segments"].size == 0
    # Two triangles 1 mm apart, pushed to 0.3 mm (d_hat 0.5): the force through the
    # binding is the central difference of the energy (h = 1e-6 mm: error ~1e-9 relative).
    nodes = [[0, 0, 0], [4, 0, 0], [0, 4, 0], [1, 1, 1], [5, 1.5, 1], [0.5, 5, 1]]
    two = Model(nodes, [], [], bar_modulus=1.0, hinge_stiffness=1.0,
                families={"self_contact": {"triangles": [[0, 1, 2], [3, 4, 5]],
                                           "distance": [0.5], "stiffness": [10.0]}})
    u = np.zeros(18)
    u[[11, 14, 17]] = [-0.7, -0.75, -0.65]
    result = assemble(two, u)
    energy = lambda v: assemble(two, v).energies["self_contact"]  # noqa: E731
    fd = np.array([(energy(u + 1e-6 * e) - energy(u - 1e-6 * e)) / 2e-6 for e in np.eye(18)])
    assert result.energies["self_contact"] > 0
    np.testing.assert_allclose(result.force, fd, rtol=0, atol=1e-6 * np.abs(fd).max())
    # The nearest pair: the upper edge (3, 4) over the lower edge (1, 2), ~0.28 mm, below
    # node 3's 0.3 mm over the lower face.
    assert 0.25 < two.element_state(u)["self_contact_gap"][0] < 0.3
