"""Planning a reach from where the arm rests (kresling.arm.plan), and reaching under the arm's
own weight (kresling.arm.reach with gravity).

Every switch is checked on the model, here independently of the plan's own reading: each
module's state is read from its cells' heights (extended above (Le + Lc) / 2) where the arm
came to rest. The move is checked as the reach is: the pulls found give the tip back on the
arm of that configuration (`kresling arm --config C --pulls ...`). Two-module arms keep each
test to a few seconds.
"""

import json

import numpy as np
import pytest

from kresling.arm import build_arm, tip_load
from kresling.arm.gravity import gravity_sag
from kresling.arm.plan import MoveStep, SwitchStep, plan_reach, switch_module
from kresling.arm.reach import REACH_TOLERANCE, reach, tip_jacobian
from kresling.cli import main

PULLS = [3.0, 0.5, 1.0]   # mm: a target made by pulling an arm by these


def _pulled_tip(configuration, pulls=PULLS):
    return tip_load(build_arm(configuration), [0.0, 0.0, 0.0], pulls=pulls).state.tip_position


def _states_from_heights(state, design):
    """Module states read from the cells' heights: '1' both above (Le + Lc) / 2, '0' both
    below (anything else fails the test)."""
    middle = 0.5 * (design.Le + design.Lc)
    cells = np.asarray(state.cell_height) > middle
    out = ""
    for k in range(0, len(cells), 2):
        assert cells[k] == cells[k + 1], f"module {k // 2} half switched: {state.cell_height}"
        out += "1" if cells[k] else "0"
    return out


def test_a_plan_extends_a_module_by_its_creases_then_moves():
    target = _pulled_tip("10")
    plan = plan_reach(target, "00")
    assert plan.configuration == "10" and plan.switches == 1 and plan.reach.reached
    switch, move = plan.steps
    assert isinstance(switch, SwitchStep) and isinstance(move, MoveStep)
    assert (switch.module, switch.to, switch.means) == (0, "extended", "crease")
    assert "cannot extend" in switch.attempts[0]   # the tendons were not used, and why
    design = build_arm("10").design
    assert _states_from_heights(switch.state, design) == switch.configuration_after == "10"
    # The move is the reach of "10": the pulls that made the target, giving it back.
    np.testing.assert_allclose(move.tendon_displacements, PULLS, atol=1e-4)
    np.testing.assert_allclose(move.tendon_displacements, plan.reach.tendon_displacements)
    again = _pulled_tip("10", move.tendon_displacements)
    assert np.linalg.norm(again - target) < REACH_TOLERANCE


@pytest.mark.parametrize("configuration, module, after", [("01", 1, "00"), ("10", 0, "00")])
def test_tendons_contract_a_module_cell_by_cell(configuration, module, after):
    step = switch_module(configuration, module)
    assert step.means == "tendon" and step.to == "contracted"
    assert _states_from_heights(step.state, build_arm(configuration).design) == after
    # A pull per cell, and a third past the second cell's unstable equilibrium, where the
    # tendons go slack (measured: 0.01 N against about 8 N at the first cell's snap).
    pulls, tensions = step.actuation["pulls"], step.actuation["tension_sums"]
    assert len(pulls) == 3 and tensions[0] > 7.0 and tensions[-1] < 0.1
    assert np.all(np.diff([max(p) for p in pulls]) > 0)   # each pull goes further
    # Resting contracted, the module made extended stands taller than one built contracted
    # (two cells of 15 mm), but below two cells' (Le + Lc) / 2.
    assert 30.0 < step.module_length[module] < 70.0


def test_a_module_that_pulling_does_not_snap_first_is_refused_with_the_reasons():
    # From "11" pulling all tendons snaps the tip module, and the optimum's creases do not
    # contract a module: neither means contracts the base module alone.
    with pytest.raises(ValueError, match=r"module 0 of 11 cannot be switched to 01") as error:
        switch_module("11", 0)
    assert "snaps module 1 before module 0" in str(error.value) and "crease" in str(error.value)


def test_the_fewest_switches_and_comparable_travels():
    target = _pulled_tip("10")
    # Without a start the smallest travel wins; "01" and "10" both reach the target.
    alone = reach(target, modules=2)
    travels = {c: v[1] for c, v in alone.candidates.items()
               if isinstance(v, tuple) and v[0] <= REACH_TOLERANCE}
    assert set(travels) == {"01", "10"} and alone.configuration == "10"
    assert travels["01"] > travels["10"]
    assert travels["01"] < 1.2 * travels["10"]   # comparable
    # Resting in "01" the arm stays there (no switch) whatever is preferred: the travels
    # are comparable, and fewer switches win.
    for prefer in ("switches", "travel"):
        plan = plan_reach(target, "01", prefer=prefer)
        assert plan.configuration == "01" and plan.switches == 0 and plan.reach.reached
        assert len(plan.steps) == 1 and isinstance(plan.steps[0], MoveStep)
    # The move is what reach finds for "01" alone.
    np.testing.assert_allclose(plan.reach.tendon_displacements,
                               reach(target, configurations=["01"],
                                     modules=2).tendon_displacements)


def test_a_configuration_whose_switch_fails_is_passed_over():
    target = _pulled_tip("01")
    plan = plan_reach(target, "11", configurations=["01", "10"])
    # Only "01" reaches the target, but it needs the base module contracted, which fails on
    # the model: the plan goes to the nearest point "10" reaches, and says so.
    assert "01" in plan.passed_over and "snaps module 1 before module 0" in plan.passed_over["01"]
    assert plan.configuration == "10" and plan.switches == 1
    assert not plan.reach.reached and "out of reach" in plan.reach.message
    step = plan.steps[0]
    assert (step.module, step.means) == (1, "tendon")
    assert _states_from_heights(step.state, build_arm("11").design) == "10"


def test_where_no_configuration_can_be_switched_to_the_arm_stays():
    target = _pulled_tip("01")
    plan = plan_reach(target, "11", configurations=["01"])
    assert "01" in plan.passed_over
    assert plan.configuration == "11" and plan.switches == 0 and not plan.reach.reached
    assert len(plan.steps) == 1 and isinstance(plan.steps[0], MoveStep)
    # Its nearest point is the reach of "11" alone.
    alone = reach(target, configurations=["11"], modules=2)
    assert plan.reach.error == pytest.approx(alone.error, abs=1e-6)


@pytest.mark.parametrize("kwargs, message", [
    (dict(start_configuration="0a"), "start_configuration = '0a' is invalid"),
    (dict(start_configuration=11), "start_configuration = 11 is invalid"),
    (dict(start_configuration="00", modules=3), "has 2 modules"),
    (dict(start_configuration="00", prefer="speed"), "prefer = 'speed' is invalid"),
])
def test_bad_plans_are_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        plan_reach([0.0, 0.0, 100.0], **kwargs)


def test_the_command_line_plan_and_its_check(capsys, tmp_path):
    target = [f"{v:.9g}" for v in _pulled_tip("10")]
    page = tmp_path / "plan.html"
    assert main(["arm", "--reach", *target, "--from", "00", "--json", "--view",
                 str(page)]) == 0
    out = json.loads(capsys.readouterr().out)
    assert "from 00 by 1 switches, then configuration 10 reaching" in page.read_text()
    assert out["start_configuration"] == "00" and out["switches"] == 1
    switch, move = out["plan"]
    assert switch["kind"] == "switch" and switch["means"] == "crease"
    assert switch["module"] == 0 and switch["configuration_after"] == "10"
    assert switch["crease_group"] == "fold" and switch["crease_change_deg"] > 0
    assert move == {"kind": "move", "configuration": "10",
                    "tendon_displacements": out["tendon_displacements"],
                    "tip_position": out["tip_position"]}
    assert main(["arm", "--config", "10", "--pulls",
                 *[repr(p) for p in out["tendon_displacements"]], "--json"]) == 0
    check = json.loads(capsys.readouterr().out)
    np.testing.assert_allclose(check["tip_position"], out["tip_position"], atol=1e-4)


@pytest.mark.parametrize("argv, message", [
    (["--reach", "0", "0", "100", "--from", "0a"], "from = '0a' is invalid"),
    (["--reach", "0", "0", "100", "--from", "0000", "--modules", "3"], "has 4 modules"),
    (["--reach", "0", "0", "100", "--from", ""], "from = '' is invalid"),
    (["--from", "00"], "add --reach"),
    (["--reach", "0", "0", "100", "--prefer", "switches"], "add --from"),
])
def test_bad_plans_on_the_command_line(argv, message, capsys):
    assert main(["arm", *argv]) == 2
    assert message in capsys.readouterr().err


def _weighed_tip(configuration, pulls, orientation):
    arm = build_arm(configuration)
    s = gravity_sag(arm, orientation, start=tip_load(arm, [0, 0, 0], pulls=pulls).state)
    assert s.completed
    return arm.model.nodes[arm.tip_node] + s.displacement.reshape(-1, 3)[arm.tip_node]


def test_a_reach_under_gravity_and_its_check_on_the_command_line(capsys):
    # The target: the horizontal arm pulled by PULLS, then weighed (an independent path: the
    # arm solver's ten-step ramp and five load steps, as `--pulls --gravity` runs it).
    target = _weighed_tip("10", PULLS, "horizontal")
    r = reach(target, configurations=["10"], modules=2, gravity="horizontal")
    assert r.reached and r.gravity == "horizontal"
    np.testing.assert_allclose(r.tendon_displacements, PULLS, atol=1e-3)
    # Without its weight the arm needs other pulls: the weight matters here (~2 mm sag).
    dry = reach(target, configurations=["10"], modules=2)
    assert np.abs(dry.tendon_displacements - r.tendon_displacements).max() > 0.1
    assert main(["arm", "--modules", "2", "--config", "10", "--reach",
                 *[repr(float(v)) for v in target], "--gravity", "horizontal", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["gravity"] == "horizontal" and out["error"] < REACH_TOLERANCE
    assert main(["arm", "--config", "10", "--pulls",
                 *[repr(p) for p in out["tendon_displacements"]], "--gravity", "horizontal",
                 "--json"]) == 0
    check = json.loads(capsys.readouterr().out)
    assert np.linalg.norm(np.subtract(check["tip_position"], out["tip_position"])) < 0.1
    assert np.linalg.norm(np.subtract(check["tip_position_without_gravity"],
                                      out["tip_position"])) > 1.0


def test_the_loaded_arms_tip_jacobian_is_the_derivative_of_its_weighed_tip():
    from kresling.arm import ArmSolver
    from kresling.arm.reach import _follower, search_solver

    arm = build_arm("0")
    solver = search_solver(arm)
    base = solver.pretension(1.0)
    follow = _follower(arm, solver, base, "horizontal", False)
    P = np.array([2.0, 0.3, 0.5])
    J = tip_jacobian(arm, follow(None, P))
    # Central differences of the weighed tip, each equilibrium to Newton's 1e-6 mm: with
    # h = 0.05 mm the noise is below ~2e-5 and the truncation ~h^2 J''; measured 7e-7 of the
    # largest entry (2.5e-8 with h = 0.01 mm): 1e-5 leaves room for both.
    h = 0.05
    fd = np.column_stack([(follow(None, P + h * e).tip_position
                           - follow(None, P - h * e).tip_position) / (2 * h) for e in np.eye(3)])
    assert np.abs(fd).max() > 0.2
    np.testing.assert_allclose(J, fd, atol=1e-5 * np.abs(fd).max())
    # And it differs from the unloaded arm's (by 2 % of its largest entry, measured): the
    # weight moves the arm, and the tangent with it.
    dry = tip_jacobian(arm, ArmSolver(arm).ramp(base, base.pulls + P)[0][-1])
    assert np.abs(dry - J).max() > 1e-3 * np.abs(J).max()


def test_bad_gravity_in_a_reach_is_named(capsys):
    with pytest.raises(ValueError, match="gravity = 'sideways' is invalid"):
        reach([0.0, 0.0, 100.0], modules=1, gravity="sideways")
    assert main(["arm", "--config", "1", "--reach", "0", "0", "100", "--gravity",
                 "--closed-loop"]) == 2
    assert "leave --gravity out" in capsys.readouterr().err
    assert main(["arm", "--config", "1", "--tip-load", "0", "0", "0.1", "--pulls", "1", "1",
                 "1", "--gravity"]) == 2
    assert "leave --tip-load out" in capsys.readouterr().err
