"""Switching one cell by its creases: where it lands, the snap and the energy balance."""

import json
import math

import numpy as np
import pytest

from kresling import Design
from kresling.analyses.switching import GROUPS, switching
from kresling.cli import main

OPTIMUM = Design(10, 0.9, 15, 30)
OTHER = Design(8, 0.8, 30, 30)  # the thesis's figure 3.16 design, bistable and level


@pytest.fixture(scope="module")
def optimum():
    return switching(OPTIMUM)


@pytest.fixture(scope="module")
def other():
    return switching(OTHER)


def _switched(result):
    return [s for s in result.forward + result.backward if s.switched]


def test_every_group_is_reported_both_ways(optimum):
    assert optimum.snap.bistable
    assert [s.group for s in optimum.forward] == list(GROUPS)
    assert [s.group for s in optimum.backward] == list(GROUPS)
    # The thesis's specimens have their mountain creases cut: nothing to drive there.
    assert optimum.forward[1].creases == 0 and not optimum.forward[1].switched


def test_landing_heights_are_the_snap_through_states(optimum, other):
    # Released after the snap, the cell rests where the snap-through test's states are:
    # the contracted one (extended -> contracted), or the built extended one, height Le.
    # 1e-6 mm: both are energy minima found by descent to a step of 1e-8 mm.
    for result in (optimum, other):
        for forward, switches, target in ((True, result.forward, result.snap.stable_height),
                                          (False, result.backward, result.snap.extended_height)):
            for s in switches:
                if s.switched:
                    assert s.forward == forward
                    assert s.landing_height == pytest.approx(target, abs=1e-6), s.group
                    assert s.landing_negative_eigenvalues == 0
    # Which switches happen (the answers the docs give): with the thesis's stiffness no
    # group switches the optimum to its contracted state before a rest angle runs out of
    # its range (0, 360) degrees; its contracted state is switched back by the valleys and
    # by all folds; the other design switches forward by its valleys and back by every group.
    assert [s.switched for s in optimum.forward] == [False] * 4
    assert "leave (0, 360) degrees" in optimum.forward[0].message
    assert [s.group for s in optimum.backward if s.switched] == ["valley", "fold"]
    assert [s.group for s in other.forward if s.switched] == ["valley"]
    assert [s.group for s in other.backward if s.switched] == ["valley", "polygon", "fold"]


def test_the_landing_state_is_the_snap_through_state(other):
    # Its energy and pose too, not only its height (this design rests level).
    s = other.forward[0]
    assert s.landing_tilt == pytest.approx(other.snap.stable_tilt, abs=1e-6)
    assert s.landing_energy == pytest.approx(other.snap.stable_energy, rel=1e-6)


def test_the_actuation_work_is_the_energy_it_stores(optimum, other):
    # With no load, the strain energy's derivative in the rest-angle change along an
    # equilibrium path is the rest angles' generalised force: the work (trapezoids over the
    # path, increments of 0.25 deg and bisection's) equals the energy added. Measured: within
    # 1e-4 of it on these designs; 1e-3 leaves room for the quadrature near the snap, where
    # the path turns (a missed jump on the path shows up as a mismatch of the jump's energy).
    for result in (optimum, other):
        for s in result.forward + result.backward:
            if s.creases:
                added = s.snap_energy - s.start_energy
                assert s.work == pytest.approx(added, rel=1e-3), (s.group, s.forward)
    # Against the barrier (the strain energy at the level drive's unstable state): the
    # switches that happen need work of the order of it, more than the barrier seen from
    # the contracted state (the actuation also strains the driven creases themselves).
    for result in (optimum, other):
        barrier_back = result.snap.energy_barrier - result.snap.stable_energy
        for s in result.backward:
            if s.switched:
                assert s.work > barrier_back


def test_the_snap_is_where_the_branch_ends(other):
    # Independent of the bisection: the fold solver driving the valleys from the extended
    # state in 200 equal increments to 0.5 % past the snap stays on the branch (continuous
    # height) up to the snap and leaves it after.
    from kresling.model.kresling_specimen import kresling_specimen
    from kresling.solvers import solve_fold

    s = other.forward[0]
    fixed = np.zeros((18, 3), dtype=bool)
    fixed[:9] = True  # the bottom polygon
    spec = kresling_specimen(OTHER, [1], [1], fixed=fixed)
    valleys = np.flatnonzero(spec.hinge_family == "valley")
    rest = np.asarray(spec.model.hinge_rest_angle)[valleys]
    path = solve_fold(spec.model, [(valleys, rest + 1.005 * s.snap_change)], 200)
    heights = [s.start_height + np.mean(u[3 * 9 + 2:3 * 17:3]) for u in path.displacement]
    jumps = np.abs(np.diff(heights))
    first_jump = int(np.argmax(jumps > 1.0))
    assert jumps.max() > 1.0
    # The jump is in the last 0.5 % of the drive, past 99.5 % of it: step 199 of 200.
    assert (first_jump + 2) / 200 * 1.005 > 1.0 - 1e-9


def test_least_actuation(optimum, other):
    assert optimum.least_actuation("snap_change") == ""
    assert optimum.least_actuation("snap_change", forward=False) == "fold"
    assert optimum.least_actuation("moment", forward=False) == "valley"
    assert other.least_actuation("snap_change") == "valley"
    with pytest.raises(ValueError, match="by = 'force' is invalid"):
        optimum.least_actuation("force")


@pytest.mark.parametrize("kwargs, message", [
    ({"scan_step_deg": 0.0}, "scan_step_deg = 0.0 is invalid"),
    ({"max_change_deg": 200.0}, "max_change_deg = 200.0 is invalid"),
    ({"resolution_deg": 1.0}, "resolution_deg = 1.0 is invalid"),
    ({"overshoot_deg": math.nan}, "overshoot_deg"),
    ({"snap_through_steps": 0}, "snap_through_steps"),
])
def test_bad_options(kwargs, message):
    with pytest.raises(ValueError, match=message):
        switching(OTHER, **kwargs)


def test_a_flat_design_is_refused():
    with pytest.raises(ValueError, match="Lc"):
        switching(Design(8, 0.8, 0, 30))


def test_cli(capsys):
    assert main(["switch", "--n", "8", "--lam", "0.8", "--Lc", "30", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["least_change"] == {"forward": "valley", "backward": "fold"}
    assert out["forward"][0]["landing_height"] == pytest.approx(out["stable_height"], abs=1e-6)
    assert main(["switch", "--resolution", "-1"]) == 2
    assert "resolution_deg = -1.0 is invalid" in capsys.readouterr().err
