"""The held forces (dead loads) family: a constant force at a node, its potential -f.u in the
energy, no stiffness; through the assembly, a solve and the sensitivities."""

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.model import Model
from kresling.solvers import equilibrium_sensitivity, solve_force_control

K = np.array([2.0, 4.0, 8.0])     # the anchor springs' stiffness per axis [N/mm]
HELD = np.array([0.3, -0.2, 0.5])  # the held force [N]


def _node_on_springs(held=HELD):
    """One node on zero-length springs to its own position, a held force on it."""
    return Model(np.zeros((1, 3)), np.zeros((0, 2), dtype=int), np.zeros((0, 4), dtype=int),
                 bar_modulus=1.0, bar_area=1.0, hinge_stiffness=[],
                 families={"springs": {"nodes": [0], "stiffness": [K], "anchor": [[0.0, 0.0, 0.0]]},
                           "forces": {"nodes": [0], "force": [held]}})


def test_the_assembly_has_the_forces_potential_and_no_stiffness():
    model = _node_on_springs()
    u = np.array([0.1, 0.2, -0.3])
    state = assemble(model, u)
    # Internal force: the springs' K u minus the held force; energy 1/2 u K u - f.u.
    np.testing.assert_allclose(state.force, K * u - HELD, rtol=1e-15, atol=1e-15)
    assert state.energies["forces"] == pytest.approx(-HELD @ u, rel=1e-15)
    np.testing.assert_allclose(state.stiffness.toarray(), np.diag(K), rtol=1e-15)


def test_a_solve_under_a_held_force_and_a_ramped_one_is_the_closed_form():
    model = _node_on_springs()
    ramped = np.array([0.1, 0.0, 0.0])
    path = solve_force_control(model, ramped, 2, tolerance=1e-14)
    assert path.completed
    # u = (f_held + lambda F) / k at each step (lambda = 1/2, 1).
    for load_factor, u in zip(path.load_factor, path.displacement):
        np.testing.assert_allclose(u, (HELD + load_factor * ramped) / K, rtol=1e-12)


def test_the_equilibrium_moves_with_the_held_force_as_one_over_k():
    model = _node_on_springs()
    u = HELD / K
    sens = equilibrium_sensitivity(model, u, ["forces.force"], held=np.zeros(0, dtype=int))
    # du/dp, p moving every entry of the column by 1: 1/k per axis.
    np.testing.assert_allclose(sens.displacement[:, 0], 1.0 / K, rtol=1e-12)


def test_bad_forces_are_refused_naming_the_family():
    with pytest.raises(ValueError, match="force"):
        _node_on_springs(held=[np.nan, 0.0, 0.0])
