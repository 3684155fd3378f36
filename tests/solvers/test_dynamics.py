"""Implicit time integration from Python (kresling.solvers.solve_dynamics); the scheme's
closed forms are tested in C++ (cpp/tests/test_time_integration.cpp).

Tolerances: Newton's tolerance is set to 1e-12 mm on O(1 mm) motions; the checks at 1e-9
relative leave three orders for rounding over thousands of steps."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.model import Model
from kresling.solvers import solve_dynamics, solve_force_control


def _oscillator(k=4.0):
    return Model([[0.0, 0.0, 0.0]], [], [], bar_modulus=1.0, hinge_stiffness=1.0,
                 families={"springs": {"nodes": [0], "stiffness": [[k, k, k]],
                                       "anchor": [[0.0, 0.0, 0.0]]}})


def test_a_step_load_on_a_spring_balances_work_and_energy():
    # m = 1e-3 t, k = 4 N/mm: w = 63.2 rad/s. A step load F = 2 N: u oscillates between 0
    # and 2 F / k; the loads' work equals kinetic plus stored energy at every step.
    k, m, F = 4.0, 1e-3, 2.0
    T = 2 * np.pi / np.sqrt(k / m)
    h = solve_dynamics(_oscillator(k), [m], T / 40, 20 * T, forces=[F, 0, 0], tolerance=1e-12)
    assert h.completed and len(h.time) == 800
    np.testing.assert_allclose(h.kinetic + h.strain, h.work, rtol=1e-9, atol=1e-12)
    u = h.path.displacement[:, 0]
    assert u.max() == pytest.approx(2 * F / k, rel=2e-3)  # the scheme's sampling of the peak
    assert u.min() > -1e-9


def test_a_damped_run_settles_on_the_static_equilibrium():
    # A triangle of linear bars, node 2 pulled along y: released with damping, it comes to
    # rest where force control puts it.
    nodes = [[0, 0, 0], [10, 0, 0], [0, 10, 0]]
    fixed = np.array([[1, 1, 1], [0, 1, 1], [0, 0, 1]], bool)
    model = Model(nodes, [[0, 1], [1, 2], [0, 2]], [], bar_modulus=50.0, hinge_stiffness=0.0,
                  bar_law="linear", fixed=fixed)
    F = np.zeros(9)
    F[7] = 5.0
    static = solve_force_control(model, F, 5, tolerance=1e-12)
    assert static.completed
    h = solve_dynamics(model, np.full(3, 1e-4), 2e-3, 2.0, forces=F, mass_damping=20.0,
                       tolerance=1e-12)
    assert h.completed, h.path.message
    np.testing.assert_allclose(h.path.displacement[-1], static.displacement[-1], atol=1e-7)
    residual = assemble(model, h.path.displacement[-1], stiffness=False).force - F
    assert np.abs(residual[~fixed.ravel()]).max() < 1e-6
    assert h.dissipated[-1] > 0 and h.kinetic[-1] < 1e-12


def test_a_ramp_table_and_bad_input():
    h = solve_dynamics(_oscillator(), [1e-3], 1e-3, 0.05, forces=[1.0, 0, 0],
                       load_table=[[0.0, 0.0], [0.05, 1.0]])
    assert h.completed and h.work[0] < h.work[-1]
    with pytest.raises(ValueError, match="masses"):
        solve_dynamics(_oscillator(), [0.0], 1e-3, 0.01)
    with pytest.raises(ValueError, match="hht_alpha"):
        solve_dynamics(_oscillator(), [1e-3], 1e-3, 0.01, hht_alpha=-0.5)
    with pytest.raises(ValueError, match="load_table"):
        solve_dynamics(_oscillator(), [1e-3], 1e-3, 0.01, load_table=[[1.0, 0.0], [0.5, 1.0]])


def test_gravity_is_the_masses_times_g_and_the_sag_is_m_g_over_k():
    k, m = 4.0, 1e-3
    h = solve_dynamics(_oscillator(k), [m], 1e-3, 1.0, gravity=(0.0, 0.0, -9810.0),
                       mass_damping=50.0, tolerance=1e-12)
    assert h.completed
    assert h.path.displacement[-1, 2] == pytest.approx(-m * 9810.0 / k, rel=1e-9)
    np.testing.assert_allclose(h.path.displacement[-1, :2], 0.0, atol=1e-15)
