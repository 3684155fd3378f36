"""Explicit central differences, their stable step, and the time functions of loads, from
Python, against closed forms (kresling.solvers.solve_dynamics, stable_time_step).

Tolerances are the schemes' own errors, said at each check; the implicit runs ask Newton
for 1e-12 mm on O(1 mm) motions so that it adds nothing visible."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.model import Model
from kresling.solvers import solve_dynamics, stable_time_step
from test_dynamics import _oscillator
from small_models import chain

SPRING, MASS = 2.5, 3e-6  # the chain's bar stiffness [N/mm] and node mass [t]


def _top_frequency(n):
    """The highest natural frequency of a fixed-free chain of n equal masses [rad/s]."""
    return 2 * np.sqrt(SPRING / MASS) * np.sin((2 * n - 1) * np.pi / (2 * (2 * n + 1)))


@pytest.mark.parametrize("n", [8, 40, 2000])
def test_the_stable_step_of_a_chain_is_two_over_its_highest_frequency(n):
    model, masses = chain(n, SPRING, MASS)
    s = stable_time_step(model, masses)
    w = _top_frequency(n)
    # Lanczos converges the top of the spectrum to rounding in n steps for n <= 300; for
    # n = 2000 (a 1-D spectrum, the slowest case) it stops at 300 steps and Gershgorin's
    # bound (3e-7 above the exact frequency) caps it: never below the true frequency.
    assert s.omega_max >= w * (1 - 1e-12)
    assert s.omega_max <= w * (1 + (1e-12 if n <= 300 else 1e-6))
    assert s.omega_bound >= s.omega_max
    assert s.time_step == pytest.approx(2 / s.omega_max, rel=1e-15)


def test_a_chain_at_its_stable_step_stays_bounded_and_above_it_is_refused():
    n = 40
    model, masses = chain(n, SPRING, MASS)
    # Start in the highest mode, the one the step limits: u_i = sin(i theta_n), 1e-6 mm
    # (the bars' Green strain makes larger motions nonlinear; the stable step is the
    # tangent's at the start).
    i = np.arange(n + 1)
    u = np.zeros((n + 1, 3))
    u[:, 0] = 1e-6 * np.sin(i * (2 * n - 1) * np.pi / (2 * n + 1))
    s = stable_time_step(model, masses, u)
    h = solve_dynamics(model, masses, 0.999 * s.time_step, 2000 * s.time_step, scheme="explicit",
                       initial=u)
    assert h.completed, h.path.message
    amplitude = np.abs(h.path.displacement[:, ::3]).max(axis=1)
    assert amplitude.max() < 1e-6 * (1 + 1e-6)     # the mode's amplitude never grows
    with pytest.raises(ValueError, match="above the explicit scheme's stable step"):
        solve_dynamics(model, masses, 1.001 * s.time_step, 1e-3, scheme="explicit", initial=u)


def test_a_run_that_becomes_unstable_is_stopped_and_says_so():
    # A slack cable has no stiffness at the start (no stable-step limit); once taut its
    # w dt is 16, far beyond 2: the energy explodes and the run ends with a message.
    fixed = np.ones((2, 3), bool)
    fixed[1, 0] = False
    model = Model([[0, 0, 0], [1.0, 0, 0]], [], [], bar_modulus=1.0, hinge_stiffness=[],
                  fixed=fixed, cables=[([0, 1], 100.0, 1.5)])
    h = solve_dynamics(model, [1e-3, 1e-3], 0.05, 10.0, scheme="explicit",
                       initial_velocity=[0, 0, 0, 10.0, 0, 0])
    assert not h.completed
    assert "unstable" in h.path.message and "smaller time_step" in h.path.message
    assert h.stable_time_step == np.inf


def test_explicit_and_newmark_agree_on_a_chain_to_second_order():
    model, masses = chain(8, SPRING, MASS)
    force = np.zeros(model.num_dofs)
    force[3 * 8] = 1e-3                      # the free end pulled along x
    dt = 0.1 * stable_time_step(model, masses).time_step
    duration = 400 * dt
    e = solve_dynamics(model, masses, dt, duration, scheme="explicit", forces=force)
    i = solve_dynamics(model, masses, dt / 4, duration, forces=force, tolerance=1e-14)
    assert e.completed and i.completed
    tip_e, tip_i = e.path.displacement[:, 24], i.path.displacement[3::4, 24]
    scale = np.abs(tip_i).max()
    # Both second order: their difference is O((w dt)^2) of the motion, (w_max dt)^2 = 0.04.
    assert np.abs(tip_e - tip_i).max() < 0.04 * scale
    assert np.abs(tip_e - tip_i).max() > 1e-6 * scale   # (two schemes, not one)


def test_rayleigh_damping_decays_as_the_closed_form():
    k, m, alpha, beta = 4.0, 1e-3, 3.0, 2e-3
    w = np.sqrt(k / m)
    xi = alpha / (2 * w) + beta * w / 2      # 0.087
    wd = w * np.sqrt(1 - xi ** 2)
    T = 2 * np.pi / w
    dt = T / 1000
    h = solve_dynamics(_oscillator(k), [m], dt, 5 * T, initial=[1.0, 0, 0],
                       mass_damping=alpha, stiffness_damping=beta, tolerance=1e-12)
    t = h.time
    exact = np.exp(-xi * w * t) * (np.cos(wd * t) + xi * w / wd * np.sin(wd * t))
    # The trapezoidal rule's phase error, (w dt)^2 / 12 per radian, over w t = 31 rad:
    # 1e-4 of the amplitude; 2e-4 allows for the damping's share.
    assert np.abs(h.path.displacement[:, 0] - exact).max() < 2e-4


@pytest.mark.parametrize("scheme", ["newmark", "explicit"])
def test_a_harmonic_load_gives_the_forced_response(scheme):
    k, m, F = 4.0, 1e-3, 0.5
    w = np.sqrt(k / m)
    f = 0.6 * w / (2 * np.pi)                # forcing at 0.6 of the natural frequency [Hz]
    r = 0.6
    force = np.array([F, 0, 0])
    dt = 2 * np.pi / w / 2000
    h = solve_dynamics(_oscillator(k), [m], dt, 3 * 2 * np.pi / w, scheme=scheme,
                       loads=[(force, {"harmonic": (1.0, f)})], tolerance=1e-12)
    assert h.completed
    t = h.time
    exact = F / k / (1 - r ** 2) * (np.sin(r * w * t) - r * np.sin(w * t))
    # Second-order schemes at w dt = 3.1e-3 over 19 rad: phase errors ~1e-5 of the motion.
    assert np.abs(h.path.displacement[:, 0] - exact).max() < 1e-4 * F / k
    # The loads' work balances the energy (to the scheme's accuracy).
    np.testing.assert_allclose(h.kinetic + h.strain, h.work, atol=1e-5 * F * F / k)


def test_load_terms_add_and_bad_input_is_named():
    model = _oscillator()
    one = solve_dynamics(model, [1e-3], 1e-3, 0.05, forces=[2.0, 0, 0])
    two = solve_dynamics(model, [1e-3], 1e-3, 0.05,
                         loads=[([1.5, 0, 0], None), ([1.0, 0, 0], [[0.0, 0.5], [1.0, 0.5]])])
    np.testing.assert_allclose(two.path.displacement, one.path.displacement, rtol=1e-12,
                               atol=1e-15)
    with pytest.raises(ValueError, match="scheme"):
        solve_dynamics(model, [1e-3], 1e-3, 0.01, scheme="leapfrog")
    with pytest.raises(ValueError, match="hht_alpha"):
        solve_dynamics(model, [1e-3], 1e-3, 0.01, scheme="explicit", hht_alpha=-0.1)
    with pytest.raises(ValueError, match="harmonic"):
        solve_dynamics(model, [1e-3], 1e-3, 0.01,
                       loads=[([1.0, 0, 0], {"harmonic": (1.0, -2.0)})])
    with pytest.raises(ValueError, match="record_every"):
        solve_dynamics(model, [1e-3], 1e-4, 0.01, scheme="explicit", record_every=0)
