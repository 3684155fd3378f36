"""Bad solver input raises ValueError; numerical failure ends the path with a reason."""

import numpy as np
import pytest

import golden
from kresling.model import Model
from kresling.solvers import (condensed_stiffness, solve_displacement_control,
                              solve_force_control, solve_mgdcm)


@pytest.fixture(scope="module")
def model():
    return golden.model()


def test_prescribed_dof_that_is_also_fixed(model):
    p = golden.prescribed(model.num_nodes)
    p[0] = 1.0  # DOF 0 (node 0, x) is supported
    with pytest.raises(ValueError, match=r"DOF 0 \(node 0, x\) is also fixed"):
        solve_displacement_control(model, p, 10)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(steps=0), r"steps = 0 is invalid: must be an integer >= 1"),
        (dict(steps=2.5), r"steps = 2.5 is invalid"),
        (dict(tolerance=-1), r"tolerance = -1.0 is invalid"),
        (dict(prescribed=np.zeros(75)), r"prescribed: every entry is zero"),
        (dict(prescribed=np.full(74, 1.0)), r"prescribed has shape \(74,\)"),
        (dict(prescribed=np.full(75, np.nan)), r"prescribed contains NaN or inf"),
    ],
)
def test_bad_displacement_control_input(model, kwargs, message):
    args = dict(prescribed=golden.prescribed(model.num_nodes), steps=10)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        solve_displacement_control(model, **args)


def test_unconstrained_rigid_body_motion_is_named(model):
    free = model.replace(fixed=np.zeros((model.num_nodes, 3), bool))
    # The imposed y-motions of the middle polygon still hold y and rotation about z.
    with pytest.raises(ValueError, match=r"4 rigid-body motions are left free \(translation"):
        solve_displacement_control(free, golden.prescribed(model.num_nodes), 10)
    # Only the bottom pinned (no top support): rotation about the bottom pin line is free.
    fixed = model.fixed.copy()
    fixed[20:] = False
    with pytest.raises(ValueError, match=r"1 rigid-body motion is left free \(rotation about"):
        solve_force_control(model.replace(fixed=fixed), np.ones(model.num_dofs), 2)


def pendulum(**kwargs):
    # Node 3 hangs from the fixed nodes 0 and 1 by two bars and is the wing of a hinge of
    # zero stiffness: it can swing freely about the axis 0-1 (an internal mechanism).
    nodes = [[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1, 0.2]]
    fixed = [[1, 1, 1], [1, 1, 1], [1, 1, 1], [0, 0, 0]]
    return Model(nodes, [[0, 3], [1, 3]], [[0, 1, 2, 3]], bar_modulus=1.0, hinge_stiffness=0.0,
                 fixed=fixed, **kwargs)


def test_mechanism_is_named_in_the_failed_result():
    forces = np.zeros(12)
    forces[11] = 1.0
    result = solve_force_control(pendulum(), forces, 1, max_bisections=0)
    assert not result.completed and result.num_steps == 0 and result.failed_increment == 1
    assert "unbounded" in result.message and "mechanism" in result.message


def test_mechanism_under_load_swings_to_its_equilibrium():
    # With bisection the solver lets the mechanism move in small steps until the bars carry
    # the load: the pendulum ends straight above the axis (the load pulls up in z).
    forces = np.zeros(12)
    forces[11] = 1.0
    result = solve_force_control(pendulum(), forces, 4)
    assert result.completed
    end = np.array([0.5, -1, 0.2]) + result.displacement[-1, 9:]
    assert end[1] == pytest.approx(0.0, abs=1e-6) and end[2] > 1.0


def test_node_without_bars_is_reported():
    nodes = [[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -1, 0.2]]
    fixed = [[1, 1, 1], [1, 1, 1], [1, 1, 1], [0, 0, 0]]
    m = Model(nodes, [[0, 1], [1, 2]], [[0, 1, 2, 3]], bar_modulus=1.0, hinge_stiffness=1.0,
              fixed=fixed)
    with pytest.raises(ValueError, match=r"node 3 is attached to no bar"):
        solve_force_control(m, np.eye(12)[11], 1)


def test_mgdcm_input(model):
    forces = np.zeros(model.num_dofs)
    forces[31] = -1
    with pytest.raises(ValueError, match=r"initial_load_factor = 0 is invalid"):
        solve_mgdcm(model, forces, initial_load_factor=0.0)
    with pytest.raises(ValueError, match=r"monitor_dof = 999 is invalid"):
        solve_mgdcm(model, forces, monitor_dof=999)
    with pytest.raises(ValueError, match=r"forces: no force acts on a free DOF"):
        solve_mgdcm(model, np.eye(model.num_dofs)[0])


def test_step_budget_is_reported(model):
    forces = np.zeros(model.num_dofs)
    forces[31] = -1
    result = solve_mgdcm(model, forces, initial_load_factor=0.01, max_increments=3,
                         max_load_factor=100.0)
    assert not result.completed and result.num_steps == 3
    assert "step budget (3 increments) ran out" in result.message


def test_condensed_stiffness_input(model):
    with pytest.raises(ValueError, match=r"DOF 0 is supported"):
        condensed_stiffness(model, [0])
    with pytest.raises(ValueError, match=r"DOF 31 repeats"):
        condensed_stiffness(model, [31, 31])
