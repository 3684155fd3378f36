"""The manipulator as a structure (kresling.arm and ``kresling arm``): the issue's checks.

Every test runs in about a second or less (arms of one to three modules of the optimum).
"""

import json
import math

import numpy as np
import pytest

from kresling.analyses import snap_through
from kresling.arm import (ArmParameters, ArmSolver, EquilibriumNotReached, all_configurations,
                          build_arm, load_capacity, parse_configuration, pull_until_snap,
                          tip_load)
from kresling.cli import main
from kresling.geometry import Design

LE = 55.8194667799374  # extended cell height of the optimum (docs/thesis_equations.md)
LC = 15.0


def cli_json(capsys, *args):
    """Run ``kresling arm ARGS --json`` in-process: (exit status, parsed output)."""
    status = main(["arm", *args, "--json"])
    return status, json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("configuration", all_configurations(3))
def test_unloaded_arm_is_stress_free_with_its_tip_at_the_sum_of_module_heights(configuration):
    arm = build_arm(configuration)
    state = ArmSolver(arm).built()
    height = sum(2 * (LE if c == "1" else LC) for c in configuration)
    assert arm.tip_height == pytest.approx(height, abs=1e-9)
    assert state.tip_position == pytest.approx([0, 0, height], abs=1e-9)
    assert state.energy == 0.0 and state.tension.tolist() == [0.0, 0.0, 0.0]
    assert state.negative_eigenvalues == 0
    forces = arm.model.element_state()
    assert np.abs(forces["bar_force"]).max() < 1e-9
    assert np.abs(forces["hinge_moment"]).max() < 1e-9
    assert state.configuration == configuration


def test_cli_reports_the_tip_of_the_unloaded_arm(capsys):
    status, out = cli_json(capsys, "--n", "10", "--lam", "0.9", "--Lc", "15", "--modules", "3",
                           "--config", "010")
    assert status == 0 and out["completed"] is True
    assert out["tip_position"] == pytest.approx([0, 0, 4 * LC + 2 * LE], abs=1e-9)
    assert out["module_length"] == pytest.approx([2 * LC, 2 * LE, 2 * LC], abs=1e-9)


def test_small_tip_loads_are_linear_and_the_compliance_is_symmetric():
    # Central differences (u(+F) - u(-F)) / 2F: a sideways load also lowers the tip by a
    # second-order term (the arm shortens as it bends), which is not compliance.
    arm = build_arm("011")
    solver = ArmSolver(arm)
    F = 0.01
    columns = []
    for k in range(3):
        e = np.eye(3)[k]
        plus, twice, minus = (tip_load(arm, s * F * e, solver=solver) for s in (1, 2, -1))
        assert plus.completed and twice.completed and minus.completed
        assert twice.tip_displacement[k] / plus.tip_displacement[k] == pytest.approx(2, rel=0.01)
        columns.append((plus.tip_displacement - minus.tip_displacement) / (2 * F))
    C = np.column_stack(columns)
    assert np.abs(C - C.T).max() < 1e-3 * np.abs(C).max()
    # The tangent compliance the analysis reports is the same matrix.
    assert np.abs(plus.compliance - C).max() < 0.02 * np.abs(C).max()
    assert np.abs(plus.compliance - plus.compliance.T).max() < 1e-9 * np.abs(C).max()


def test_a_contracted_module_at_the_base_costs_more_deflection_than_at_the_tip(capsys):
    deflection = {}
    for configuration in ("011", "110"):
        status, out = cli_json(capsys, "--modules", "3", "--config", configuration,
                               "--tip-load", "0.05", "0", "0")
        assert status == 0 and out["completed"] is True
        assert len(out["tip_displacement"]) == 3
        deflection[configuration] = out["tip_displacement"][0]
    assert deflection["011"] > 1.2 * deflection["110"] > 0


def test_pulling_all_tendons_snaps_one_extended_module_near_the_cells_snap_force(capsys):
    status, out = cli_json(capsys, "--n", "10", "--lam", "0.9", "--Lc", "15", "--modules", "1",
                           "--config", "1", "--pull-all")
    assert status == 0 and out["completed"] is True
    cell = snap_through(Design(10, 0.9, 15.0)).snap_force  # 8.99 N
    assert out["snap_tendon_force"] == pytest.approx(cell, rel=0.2)
    assert out["snapped_module"] == 0
    assert out["configuration_after"] == "x"  # one cell snapped; the other re-extended
    assert out["snap_motor_counts"][0] == pytest.approx(
        -out["snap_pull"] * 4704 / (math.pi * 20))


def test_pulling_one_tendon_snaps_at_a_smaller_force_and_a_longer_pull(capsys):
    status, out = cli_json(capsys, "--config", "1", "--pull-tendon", "1")
    assert status == 0 and out["snapped"] is True and out["snapped_module"] == 0
    _, both = cli_json(capsys, "--config", "1", "--pull-all")
    assert out["snap_tendon_force"] < both["snap_tendon_force"]  # 5.3 N against 8.1 N
    assert out["snap_pull"] > both["snap_pull"]                  # 44.7 mm against 21.5 mm
    assert out["snap_tension"][0] > 5 * max(out["snap_tension"][1:])


def test_pulls_shorten_the_tendons_and_tension_them(capsys):
    status, out = cli_json(capsys, "--config", "1", "--pulls", "2", "2", "2")
    assert status == 0 and out["completed"] is True
    assert all(p > 2 for p in out["pulls"])  # the pretension's pulls, then 2 mm more
    assert max(out["pulls"]) - min(out["pulls"]) < 0.1
    assert all(t > 1.0 for t in out["tension"])  # pretension 1 N, then pulled further
    assert out["tip_position"][2] < out["tip_position_unloaded"][2]


def test_pull_until_snap_reports_the_module_the_force_and_where_it_lands():
    arm = build_arm("10")
    r = pull_until_snap(arm)
    assert r.snapped and r.snapped_module == 0
    assert r.configuration_before == "10" and r.configuration_after == "x0"
    assert r.after.negative_eigenvalues == 0
    assert r.tension_sum == pytest.approx(r.tension.sum())
    # The path passes the force's maximum before it is lost; pulls are equal.
    peak = max(s.tension_sum for s in r.states)
    assert r.tension_sum < peak
    assert r.pulls == pytest.approx([r.pull] * 3)


def test_load_capacity_ends_where_a_tendon_goes_slack_or_a_module_snaps():
    arm = build_arm("1")
    sideways = load_capacity(arm, (1.0, 0.0, 0.0))
    assert sideways.limit == "slack" and sideways.tendon == 0 and sideways.load > 0.1
    # Pretension sets the margin: twice the pretension, about twice the sideways capacity.
    stronger = load_capacity(arm, (1.0, 0.0, 0.0), pretension=2.0)
    assert stronger.load == pytest.approx(2 * sideways.load, rel=0.15)


def test_losing_equilibrium_is_a_result_not_a_crash(capsys):
    # Pushing the tip of an extended module down far beyond its snap force: the path ends
    # where equilibrium is lost, with the load carried so far.
    status, out = cli_json(capsys, "--modules", "1", "--config", "1", "--tip-load", "0", "0",
                           "-30")
    assert status == 1 and out["completed"] is False
    assert 0 < out["load_factor"] < 1
    low, high = out["lost_between"]
    assert low == out["load_factor"] and 0 < high - low < 1e-3
    assert out["snapped_module"] == 0
    assert "between t =" in out["message"]
    capsys.readouterr()


STIFF_TENDONS = ArmParameters(tendon_stiffness=1e12)  # EA [N]: Newton on the pulls fails


def test_a_pretension_the_solver_does_not_reach_is_a_specific_error():
    solver = ArmSolver(build_arm("1", parameters=STIFF_TENDONS))
    with pytest.raises(EquilibriumNotReached, match="pretension 1.0 N not reached") as caught:
        solver.pretension(1.0)
    assert isinstance(caught.value, RuntimeError)  # what callers caught before
    assert caught.value.target == "pretension 1.0 N" and "no convergence" in caught.value.reason
    with pytest.raises(EquilibriumNotReached):
        load_capacity(solver.arm, (1, 0, 0), solver=solver)


def test_tendons_too_soft_to_pretension_are_not_a_bad_pull():
    # EA = 1e-310 N: the pull reaching 1 N overflowed and was refused as "pulls[2] = inf",
    # a value the caller never gave.
    solver = ArmSolver(build_arm("1", parameters=ArmParameters(tendon_stiffness=1e-310)))
    with pytest.raises(EquilibriumNotReached, match="pulls that would reach it are not finite"):
        solver.pretension(1.0)


def test_cli_says_in_one_line_that_the_pretension_was_not_reached(capsys):
    # A valid command line the solver cannot follow: exit 1 (stopped), not 2 (bad input).
    assert main(["arm", "--config", "1", "--capacity", "--tendon-stiffness", "1e12"]) == 1
    err = capsys.readouterr().err
    assert err.startswith("kresling arm: stopped: pretension 1.0 N not reached")
    assert err.count("\n") == 1 and "Traceback" not in err


@pytest.mark.parametrize("args, name", [
    (["--config", "0102"], "configuration"),
    (["--config", ""], "configuration"),
    (["--config", "01", "--modules", "3"], "configuration"),
    (["--config", "1", "--tendon-radius", "45"], "tendon_radius"),
    (["--config", "1", "--tendon-radius", "-1"], "tendon_radius"),
    (["--config", "1", "--tip-load", "1", "0", "0", "--pretension", "-1"], "pretension"),
    (["--config", "1", "--tip-load", "1", "0", "0", "--pull-all"], "--tip-load and --pull-all"),
    (["--modules", "0"], "modules"),
    (["--config", "1", "--pulls", "1", "-1", "0"], "pulls[1] = -1.0 mm is invalid: makes tendon 2 "
                                                 "longer than its slack length"),
    (["--config", "1", "--pull-all", "--max-pull", "-5"], "max_pull"),
    (["--config", "1", "--capacity", "--pretension", "0"], "pretension"),
    (["--table", "--modules", "2", "--plot", "x.png", "--config", "11"], "config"),
])
def test_bad_input_exits_2_naming_the_parameter(capsys, args, name):
    assert main(["arm", *args]) == 2
    err = capsys.readouterr().err
    assert name in err and err.count("\n") == 1


def test_bad_input_raises_value_error_naming_the_parameter():
    arm = build_arm("1")
    with pytest.raises(ValueError, match="configuration"):
        parse_configuration("012")
    with pytest.raises(ValueError, match="configuration"):
        build_arm("1x1")
    with pytest.raises(ValueError, match="tendon_radius"):
        build_arm("1", parameters=ArmParameters(tendon_radius=41.0))
    with pytest.raises(ValueError, match=r"pulls\[1\].*longer than its slack length"):
        tip_load(arm, [0, 0, 0], pulls=[0, -1, 0])
    with pytest.raises(ValueError, match="direction"):
        pull_until_snap(arm, (1, -1, 0))
    with pytest.raises(ValueError, match="max_load"):
        load_capacity(arm, (1, 0, 0), max_load=-5.0)
    with pytest.raises(ValueError, match="pretension"):
        load_capacity(arm, (1, 0, 0), pretension=0.0)
    with pytest.raises(ValueError, match="load"):
        tip_load(arm, [1, 2])


def test_load_capacity_table_shows_the_longest_arm_is_not_the_stiffest(tmp_path, capsys):
    status = main(["arm", "--table", "--modules", "3", "--json", "--plot",
                   str(tmp_path / "capacity.png")])
    out = json.loads(capsys.readouterr().out)
    assert status == 0 and out["completed"] is True and out["pretension"] == 1.0
    rows = {r["configuration"]: r for r in out["rows"]}
    assert sorted(rows) == all_configurations(3)
    longest = max(rows, key=lambda c: rows[c]["tip_height_mm"])
    stiffest = max(rows, key=lambda c: rows[c]["sideways_stiffness_N_per_mm"])
    assert longest == "111" and stiffest != "111"
    assert rows["111"]["tip_height_mm"] > 3 * rows["000"]["tip_height_mm"]
    for r in rows.values():
        for d in ("-z", "+x", "-x", "+y"):
            assert r[f"load_{d}_N"] > 0
            assert r[f"limit_{d}"].startswith(("tendon", "snap", "none"))
    assert (tmp_path / "capacity.png").stat().st_size > 10_000


def test_small_symmetric_pulls_bend_one_contracted_module_like_the_kinematic_model(
        capsys, record_property):
    # Tendon 1 in by 2k, tendons 2 and 3 out by k (section 4.3), k = 0..3: the bend's plane
    # and direction agree with the constant-curvature model; how closely is reported.
    status, out = cli_json(capsys, "--modules", "1", "--config", "0", "--protocol")
    assert status == 0 and out["completed"] is True and len(out["steps"]) == 11
    for step in out["steps"][1:4]:
        tip, kinematic = step["tip_position"], step["kinematic_tip_position"]
        assert tip[0] > 0 and kinematic[0] > 0  # both bend towards tendon 1 (+x)
        plane = math.degrees(step["bend_direction"])
        bend, kinematic_bend = step["bend_angles"][0], step["kinematic_bend_angles"][0]
        record_property(f"k={step['k']}", {"plane_deg": plane, "bend_deg": math.degrees(bend),
                                          "kinematic_bend_deg": math.degrees(kinematic_bend),
                                          "tip_error_mm": step["tip_error"]})
        assert abs(plane) < 1.0  # measured: 0.04 degrees
        assert bend == pytest.approx(kinematic_bend, rel=0.02)  # measured: 0.3 % smaller
    # The tips differ by about 2 mm at every step: the pretension (1 N per tendon)
    # compresses the contracted module from 30 to 28.1 mm; the kinematic model keeps 30.
    assert out["steps"][0]["tip_error"] == pytest.approx(1.94, abs=0.05)


def test_extended_modules_take_a_share_of_the_bend_the_kinematic_model_gives_the_joint():
    from kresling.arm.actuation import pseudo_linkage_run

    run = pseudo_linkage_run(build_arm("011"), steps=[0, 5, 10])
    assert run.completed
    total, kinematic_total = run.bend_angles.sum(axis=1), run.kinematic_bend_angles.sum(axis=1)
    assert total[1:] == pytest.approx(kinematic_total[1:], rel=0.06)  # the same total bend
    assert run.kinematic_bend_angles[:, 1:].max() == 0.0              # rigid links there
    assert run.bend_angles[2, 1] > 0.1 * run.bend_angles[2, 0]        # not rigid here
    assert run.tip_error[2] > 20.0                                    # so the tip lags


def test_table5_module_lengths_are_a_prediction_reported_beside_the_measurements():
    from kresling.arm.actuation import table5_comparison

    rows = table5_comparison()
    assert len(rows) == 24 and all(r["completed"] for r in rows)
    for r in rows:
        expected = 2 * (LE if r["state"] == 1 else LC)
        assert r["kinematic_min_mm"] == pytest.approx(expected, abs=1e-6)
        assert r["kinematic_max_mm"] == pytest.approx(expected, abs=1e-6)
        assert r["outside_by_mm"] >= 0 and r["inside"] == (r["outside_by_mm"] == 0)
    # The kinematic model predicts no variation; the structure's ranges under the protocol
    # are of the measured size (about 1 mm on average).
    bending = [r for r in rows if r["config"] != "111"]
    predicted = np.mean([r["predicted_max_mm"] - r["predicted_min_mm"] for r in bending])
    measured = np.mean([r["max_mm"] - r["min_mm"] for r in bending])
    assert 0.3 * measured < predicted < 3 * measured


def test_switching_map_pulling_all_tendons_contracts_the_tip_most_module_first():
    from kresling.arm.switching import switching_map

    switches = switching_map(2, pulls={"all": (1.0, 1.0, 1.0)})
    ends = {s.start: s.end for s in switches}
    assert ends == {"01": "0x", "10": "x0", "11": "1x"}
    for s in switches:
        assert s.snapped and 7.0 < s.tension_sum < 10.0
        assert s.motor_counts[0] < 0  # reeling in
