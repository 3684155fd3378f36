"""Contact between the arm's panels (ArmParameters.contact_distance): the self-contact family
on the cells' side triangles and the levels' polygons, within and between modules.

References: the triangles are compared with the specimen's own triangulation
(kresling.model.masses.specimen_triangles, written apart from the arm's C++); whether
panels pass through each other is decided by an independent segment-triangle test
(tests/triangle_intersection_helpers.py), not by the contact family's distances."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.arm import build_arm
from kresling.arm.analyses import ArmSolver, pull_until_snap
from kresling.arm.masses import _cell_triangles
from kresling.arm.structure import ArmParameters
from triangle_intersection_helpers import intersecting_pairs

CONTACT = ArmParameters(contact_distance=0.3, contact_stiffness=485.0)


def _crossing_pairs(arm, u) -> int:
    """Triangle pairs that share no node and intersect at displacement u. (Pairs that share
    a node are left out: the helper cannot tell a crossing from a shared corner of two
    nearly coplanar fan triangles of a guide plate.)"""
    tri = _cell_triangles(arm)
    x = arm.model.nodes + np.reshape(u, (-1, 3))
    return sum(1 for i, j in intersecting_pairs(x, tri) if not set(tri[i]) & set(tri[j]))


def test_the_family_holds_every_panel_of_the_arm():
    arm = build_arm("010", parameters=CONTACT)
    table = arm.model.family("self_contact")
    # 6 cells of 2n = 20 side triangles, 7 levels of n = 10 polygon triangles.
    np.testing.assert_array_equal(table["triangles"], _cell_triangles(arm))
    assert table["triangles"].shape == (190, 3)
    assert float(table["distance"][0]) == 0.3 and float(table["stiffness"][0]) == 485.0
    assert "self_contact" not in build_arm("010").model.families


def test_contact_needs_a_stiffness_and_a_distance_below_the_built_gap():
    with pytest.raises(ValueError, match="contact_stiffness"):
        build_arm("1", parameters=ArmParameters(contact_distance=0.3))
    with pytest.raises(ValueError, match="contact_distance"):
        build_arm("1", parameters=ArmParameters(contact_distance=-1.0, contact_stiffness=1.0))
    # A contracted module's nearest panels are 0.595 mm apart as built: a larger d_hat
    # would push them apart before anything moves, and the model refuses it.
    with pytest.raises(ValueError, match="distance"):
        build_arm("0", parameters=ArmParameters(contact_distance=0.7, contact_stiffness=1.0))
    assert build_arm("0", parameters=ArmParameters(contact_distance=0.5,
                                                   contact_stiffness=1.0)).model.num_nodes


def test_a_single_tendon_pull_bends_the_arm_without_panels_passing_through():
    # (001) pulled by tendon 2 alone: without contact the two contracted modules' panels
    # pass through each other on the inside of the bend (over a hundred crossing pairs
    # before the snap and after the landing) and the tip module snaps at 76 mm of pull.
    # With contact no pair crosses, at any equilibrium of the pull or after the landing;
    # the contracted modules, which can no longer close through themselves, bend less, and
    # the tip module snaps earlier (52 mm).
    free_arm, arm = build_arm("001"), build_arm("001", parameters=CONTACT)
    free = pull_until_snap(free_arm, (0.0, 1.0, 0.0))
    held = pull_until_snap(arm, (0.0, 1.0, 0.0))
    assert free.snapped and held.snapped, (free.message, held.message)
    assert free.configuration_after == held.configuration_after == "00x"
    assert _crossing_pairs(free_arm, free.states[-1].displacement) > 100
    assert _crossing_pairs(free_arm, free.after.displacement) > 100
    assert all(_crossing_pairs(arm, s.displacement) == 0 for s in held.states)
    assert _crossing_pairs(arm, held.after.displacement) == 0
    assert held.pull < free.pull - 10.0


@pytest.mark.slow
def test_a_solver_reused_after_a_pull_follows_the_pattern_its_pairs_changed():
    # A pull brings pairs within d_hat and grows the tangent's pattern; the next solve from
    # the built arm factorises a tangent of another pattern, which the solver must be told.
    arm = build_arm("100", parameters=CONTACT)
    solver = ArmSolver(arm)
    first = pull_until_snap(arm, (1.0, 0.0, 0.0), solver=solver)
    assert first.snapped and first.configuration_after == "x00"
    built = solver.built()
    assert not built.displacement.any() and built.negative_eigenvalues == 0
    again = pull_until_snap(arm, (1.0, 0.0, 0.0), solver=solver)
    assert again.pull == pytest.approx(first.pull, rel=1e-12)
