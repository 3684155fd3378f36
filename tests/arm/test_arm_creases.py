"""A module of the arm switched by its creases instead of by pulling the tendons."""

import json
import math

import numpy as np
import pytest

from kresling import Design
from kresling.analyses import snap_through
from kresling.arm import ArmParameters, ArmSolver, build_arm
from kresling.arm.creases import crease_switch, resting_state
from kresling.cli import main
from kresling.model import SpecimenParameters


@pytest.fixture(scope="module")
def arm():
    return build_arm("1")     # one module of the thesis's optimum


@pytest.fixture(scope="module")
def extended(arm):
    """All folds of the module resting contracted (built extended) driven to extend it."""
    return crease_switch(arm, 0, start=resting_state(arm, 0, 0))


def test_the_creases_extend_a_contracted_module_to_its_built_state(arm, extended):
    r = extended
    assert (r.to, r.switched, r.configuration_before, r.configuration_after) == \
        ("extended", True, "0", "1")
    # The module's other stable state is its built one: each cell at the extended height the
    # snap-through test of a lone cell gives (Le), to 1e-6 mm (measured 1.5e-10; the
    # neighbours, the guides and the slack tendons carry no load there, so nothing else moves it).
    Le = snap_through(arm.design).extended_height
    np.testing.assert_allclose(r.after.cell_height, Le, atol=1e-6)
    np.testing.assert_allclose(r.after.tip_position, [0.0, 0.0, arm.tip_height], atol=1e-6)
    assert r.after.negative_eigenvalues == 0 and np.all(r.after.tension == 0.0)
    # Started contracted: both cells below (Le + Lc) / 2, the module shorter than built.
    assert np.all(r.start.cell_height < 0.5 * (arm.design.Le + arm.design.Lc))
    assert r.tendons is None          # tendons cannot extend a module
    np.testing.assert_allclose(r.tip_displacement, r.after.tip_position - r.start.tip_position)


def test_the_actuation_work_equals_the_energy_it_added(extended):
    # With no load the strain energy's derivative in the change along an equilibrium path
    # is the rest angles' generalised force, whose integral (trapezoids) is the work: the
    # moments and the energies are computed independently. 1e-3 allows the quadrature where
    # the path turns near the snap (measured 2e-6).
    r = extended
    added = r.snap.energy - r.start.energy
    assert r.work == pytest.approx(added, rel=1e-3)
    assert 0 < r.snap_change < math.radians(170) and r.moment > 0
    assert r.resolution <= math.radians(1e-5)
    # The path is continuous up to the snap: the module lengthens without a jump.
    assert np.all(np.diff(r.module_length) > -1e-9)


def test_a_group_that_cannot_contract_the_optimum_beside_the_tendons(arm):
    # As for the lone cell, the valleys cannot contract the optimum before their rest angles
    # leave (0, 360) deg; pulling all tendons snaps it (one cell: 'x').
    r = crease_switch(arm, 0, group="valley")
    assert r.to == "contracted" and not r.switched and r.after is None
    assert "no snap" in r.message
    # The scan ends a scan step short of where the first rest angle would leave the range:
    # each valley turns from its built extended angle towards its built contracted one.
    valleys = arm.hinge_family == "valley"
    rest = np.degrees(arm.model.hinge_rest_angle[valleys])
    contracted = np.degrees(build_arm("0").model.hinge_rest_angle[valleys])
    room = np.where(np.remainder(contracted - rest + 180.0, 360.0) >= 180.0, 360.0 - rest, rest)
    assert r.snap_change_deg == pytest.approx(room.min() - 0.25, abs=1e-9)
    assert r.creases == valleys.sum()
    assert r.tendons is not None and r.tendons.snapped
    assert r.tendons.configuration_after == "x"
    assert r.tendons.tension_sum == pytest.approx(8.11, abs=0.01)


def test_stiffer_valleys_contract_a_whole_module_which_pulling_all_tendons_does_not():
    # n = 8, lambda = 0.9, Lc = 15 mm with valleys twice as stiff: the valleys contract the
    # module (both cells), where pulling all tendons contracts one cell ('x').
    arm = build_arm("1", n=8, lam=0.9, Lc=15.0, parameters=ArmParameters(
        specimen=SpecimenParameters(valley_factor=2.0)))
    r = crease_switch(arm, 0, group="valley")
    assert (r.to, r.switched, r.configuration_after) == ("contracted", True, "0")
    assert r.after.negative_eigenvalues == 0
    assert np.all(r.after.cell_height < 0.5 * (arm.design.Le + arm.design.Lc))
    # The module has more than one contracted stable state (tilted to different sides,
    # with slightly different cell heights: 21.249/21.197 mm here, 21.326/21.092 mm from
    # the built contracted geometry), so the landing is checked as a minimum of its own:
    # released again with a tighter tolerance (1e-8 mm) it stays within 1e-6 mm (measured
    # 1.2e-8 mm).
    again, converged, _ = ArmSolver(arm, tolerance=1e-8).release(r.after)
    assert converged and again.negative_eigenvalues == 0
    assert np.abs(again.displacement - r.after.displacement).max() < 1e-6
    assert r.work == pytest.approx(r.snap.energy - r.start.energy, rel=1e-3)
    assert r.tendons.snapped and r.tendons.configuration_after == "x"


@pytest.mark.parametrize("kwargs, name", [
    ({"module": 1}, "module"), ({"module": 0, "group": "spoke"}, "group"),
    ({"module": 0, "to": "sideways"}, "to"), ({"module": 0, "to": "extended"}, "to"),
    ({"module": 0, "let_out": -1.0}, "let_out"), ({"module": 0, "start": "built"}, "start"),
    ({"module": 0, "scan_step_deg": 0.0}, "scan_step_deg"),
])
def test_bad_input_names_the_parameter(arm, kwargs, name):
    with pytest.raises(ValueError, match=name):
        crease_switch(arm, **kwargs)


def test_a_module_that_is_not_bistable_has_no_contracted_rest():
    # The thesis's figure 3.16 design is bistable as a lone cell but not as a module (its
    # cells' shared polygon is free): released contracted, it returns to extended.
    arm = build_arm("1", n=8, lam=0.8, Lc=30.0)
    with pytest.raises(ValueError, match="state = 0 is invalid"):
        resting_state(arm, 0, 0)


def test_cli(capsys):
    assert main(["arm", "--modules", "1", "--config", "1", "--crease-switch", "0",
                 "--crease-start", "contracted", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["switched"] and out["configuration_after"] == "1" and out["tendons"] is None
    assert main(["arm", "--modules", "1", "--config", "1", "--crease-switch", "0"]) == 0
    text = capsys.readouterr().out
    assert "pulling all tendons instead" in text
    assert main(["arm", "--modules", "1", "--crease-switch", "3"]) == 2
    assert "crease-switch = 3 is invalid" in capsys.readouterr().err
