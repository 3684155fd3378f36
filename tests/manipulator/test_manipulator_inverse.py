"""Inverse kinematics (configuration planner) and workspace maps."""

import numpy as np
import pytest

from kresling.manipulator import (Manipulator, configuration_name, forward_kinematics,
                                  inverse_kinematics, solve_configuration, workspace, workspaces)


def test_fk_sampled_targets_are_reached_in_every_configuration():
    arm = Manipulator()
    rng = np.random.default_rng(2)
    for configuration in arm.configurations[:-1]:  # (111) has no inputs
        lengths = rng.uniform(*arm.tendon_bounds, size=(30, 3))
        targets = np.array([forward_kinematics(arm, configuration, l).tip for l in lengths])
        solved = solve_configuration(arm, configuration, targets)
        assert solved["converged"].all(), configuration
        # Round trip through forward kinematics, 1e-6 mm (the required bound).
        reached = np.array([forward_kinematics(arm, configuration, l).tip
                            for l in solved["tendon_lengths"]])
        assert np.abs(reached - targets).max() < 1e-6


def test_planner_reaches_a_target_and_prefers_the_stiffest_arm():
    arm = Manipulator()
    target = forward_kinematics(arm, "110", [24.0, 33.0, 36.0]).tip
    found = inverse_kinematics(arm, target)
    assert found.reachable and found.distance < 1e-6
    # Only configurations with one flexible module can be this long: (110), (101), (011).
    assert found.configuration.count(0) == 1
    tip = forward_kinematics(arm, found.configuration, found.tendon_lengths).tip
    np.testing.assert_allclose(tip, target, atol=1e-6)


@pytest.mark.parametrize("target", [[0, 0, 1000.0], [0, 0, -50.0], [400.0, 0, 0], [0, 300.0, 10.0]])
def test_targets_outside_every_workspace_are_reported_not_raised(target):
    arm = Manipulator()
    found = inverse_kinematics(arm, target)
    assert not found.reachable
    assert found.distance > 1.0
    # The nearest point is a real tip position of the chosen configuration.
    lengths = found.tendon_lengths if 0 in found.configuration else None
    np.testing.assert_allclose(forward_kinematics(arm, found.configuration, lengths).tip,
                               found.nearest_reachable_point, atol=1e-9)
    assert len(found.candidates) == 8


def test_all_extended_target():
    arm = Manipulator()
    found = inverse_kinematics(arm, [0.0, 0.0, 3 * arm.extended_length])
    assert found.reachable and configuration_name(found.configuration) == "111"


def test_workspace_maps():
    arm = Manipulator()
    maps = workspaces(arm, grid_points=4)
    assert len(maps) == 8 and maps["111"].points.shape == (1, 3)
    space = workspace(arm, "000", grid_points=5)
    assert space.points.shape == (125, 3)
    # Straight at the box's corners (all tendons equal): tip on the axis at 3 x length.
    straight = np.all(space.tendon_lengths == space.tendon_lengths[:, :1], axis=1)
    np.testing.assert_allclose(space.points[straight, 2], 3 * space.tendon_lengths[straight, 0])
    assert space.extent.shape == (2, 3)


def test_bad_ik_input():
    arm = Manipulator()
    with pytest.raises(ValueError, match="target"):
        inverse_kinematics(arm, [0.0, float("nan"), 1.0])
    with pytest.raises(ValueError, match="target"):
        inverse_kinematics(arm, [1.0, 2.0])
    with pytest.raises(ValueError, match="configurations is empty"):
        inverse_kinematics(arm, [0, 0, 100.0], configurations=[])
