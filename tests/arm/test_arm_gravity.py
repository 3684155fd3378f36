"""The arm's masses, its sag under its own weight and its frequencies.

The sag is checked against two independent references: a tip mass on the horizontal arm
sags as the C++ arm solver's tip load of the same weight (another path: the tendons as the
arm solver holds them, its own load ramp) and, to first order, as the tangent's tip
compliance times the weight (a cantilever of the arm's linearised stiffness)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from kresling.arm import ArmSolver, build_arm, tip_load
from kresling.arm.frequencies import arm_frequencies
from kresling.arm.gravity import GRAVITY, gravity_sag, gravity_table, held_tendons_model
from kresling.arm.masses import (GUIDE_THICKNESS, SKELETON_MASS, ArmMasses, arm_masses)
from kresling.analyses.laminate import LAMINATE_AREAL_DENSITY
from kresling.assembly import assemble
from kresling.model.masses import PET_DENSITY


def _tip_mass(arm, mass):
    node = np.zeros(arm.model.num_nodes)
    node[arm.tip_node] = mass
    return ArmMasses(node, 0.0, 0.0, 0.0, 1.0)


def test_a_tip_mass_sags_as_the_arm_solvers_tip_load():
    arm = build_arm("0")
    solver = ArmSolver(arm)
    weight = 0.02   # N: small against the 1 N pretension, so the response is nearly linear
    sag = gravity_sag(arm, "horizontal", masses=_tip_mass(arm, weight / GRAVITY),
                      solver=solver)
    assert sag.completed
    loaded = tip_load(arm, [-weight, 0.0, 0.0], solver=solver)
    # The same equilibrium by two solvers, each to its Newton tolerance (1e-6 mm).
    np.testing.assert_allclose(sag.marker_sag[-1], loaded.tip_displacement, atol=1e-5)
    # The cantilever of the linearised stiffness: C F, to the response's nonlinearity
    # (doubling 0.01 N doubles the displacement to 0.1 %: 2 % leaves room at 0.02 N).
    linear = loaded.compliance @ np.array([-weight, 0.0, 0.0])
    np.testing.assert_allclose(sag.marker_sag[-1], linear, rtol=0.02,
                               atol=0.02 * np.abs(linear).max())


def test_the_arm_is_in_equilibrium_with_its_tendons_held():
    arm = build_arm("011")
    start = ArmSolver(arm).pretension(1.0)
    force = assemble(held_tendons_model(arm, start.pulls), start.displacement).force
    # The arm solver's Newton tolerance leaves a residual of the order of 1e-5 N.
    assert np.abs(force[arm.model.free_dofs]).max() < 1e-4


def test_hanging_and_standing_sag_mirror_each_other_at_rest():
    arm = build_arm("111")
    up, down = gravity_sag(arm, "standing"), gravity_sag(arm, "hanging")
    # Small sags: the response is linear to about 1 %, so the two are opposite.
    np.testing.assert_allclose(up.marker_sag, -down.marker_sag, atol=0.02 * down.sag.max())
    assert down.module_length_change[0] > 0 > up.module_length_change[0]


def test_arm_masses_from_the_materials():
    arm = build_arm("101")
    m = arm_masses(arm)
    assert m.total == pytest.approx(m.cells + m.guides + m.tendons, rel=1e-13)
    disc = math.pi * arm.parameters.guide_radius ** 2 * GUIDE_THICKNESS * PET_DENSITY
    assert m.guides == pytest.approx((arm.modules + 1) * disc, rel=1e-12)
    # Six cells of about 7.3 g less the five shared polygons: 37.5 g.
    assert m.cells == pytest.approx(37.45e-6, rel=1e-3)
    assert m.cells / LAMINATE_AREAL_DENSITY > 0
    measured = arm_masses(arm, measured_skeleton=True)
    assert measured.skeleton == pytest.approx(SKELETON_MASS, rel=1e-12)
    assert (m.node[arm.model.free_dofs[::3] // 3] > 0).all()   # every free node has mass


def test_gravity_table_and_frequencies_cover_the_configurations():
    rows = gravity_table(1, "hanging")
    assert [(r["config"], r["k"]) for r in rows] == [("0", 0), ("0", 10), ("1", 0)]
    assert all(r["completed"] for r in rows)

def test_arm_frequencies_match_a_dense_eigensolve():
    import scipy.linalg

    f = arm_frequencies("1", k=4)
    arm = build_arm("1")
    start = ArmSolver(arm).pretension(1.0)
    model = held_tendons_model(arm, start.pulls)
    free = model.free_dofs
    K = assemble(model, start.displacement).stiffness.toarray()[np.ix_(free, free)]
    M = np.repeat(arm_masses(arm).node, 3)[free]
    values = scipy.linalg.eigh((K + K.T) / 2, np.diag(M), eigvals_only=True)[:4]
    # Shift-invert Lanczos against LAPACK on the same matrices: round-off only.
    np.testing.assert_allclose(f.modes.frequencies_hz, np.sqrt(values) / (2 * np.pi),
                               rtol=1e-8)


@pytest.mark.parametrize("kwargs, name", [({"orientation": "sideways"}, "orientation"),
                                          ({"g": -1.0}, "g"), ({"masses": 3}, "masses"),
                                          ({"g": 5e-324}, "g = 5e-324")])  # m g underflows
def test_bad_gravity_options_are_named(kwargs, name):
    with pytest.raises(ValueError, match=name):
        gravity_sag(build_arm("0"), **kwargs)
