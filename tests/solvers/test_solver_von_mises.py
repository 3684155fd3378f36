"""The von Mises two-bar truss with a soft spring in series: limit points and a snap-back,
against the closed-form solution.

The truss bars follow the linear (Saint Venant-Kirchhoff) law S = C0 E. For the truss of
half-span a,
rise h and bar length L = sqrt(a^2 + h^2), with the apex at height z the load it carries is

    P(z) = A C0 z (h^2 - z^2) / L^3,

with limit points at z = +-h / sqrt(3), P_max = 2 A C0 h^3 / (3 sqrt(3) L^3). The load acts
through a vertical spring bar on top of the apex; a spring softer than the truss's steepest
negative stiffness makes the load point's displacement turn back (a snap-back), which
displacement control of that point cannot follow but MGDCM can. The spring uses the Ogden
law, whose axial force A C0/4 (s^4 - 1) is monotone in the stretch s (an SVK bar would
itself buckle under compression).
"""

import numpy as np
import pytest

from kresling.model import Model
from kresling.solvers import solve_force_control, solve_mgdcm

A_HALF, H, C0, AREA = 10.0, 1.0, 1000.0, 1.0
SPRING_LENGTH, SPRING_AREA = 10.0, 0.005  # k_s = 0.5 N/mm, softer than max |dP/dz| = 0.98
L = np.hypot(A_HALF, H)
P_MAX = 2 * AREA * C0 * H**3 / (3 * np.sqrt(3) * L**3)


def truss():
    nodes = [[-A_HALF, 0, 0], [A_HALF, 0, 0], [0, 0, H], [0, 0, H + SPRING_LENGTH]]
    fixed = [[1, 1, 1], [1, 1, 1], [1, 1, 0], [1, 1, 0]]
    return Model(nodes, [[0, 2], [1, 2], [2, 3]], np.zeros((0, 4), int), bar_modulus=C0,
                 bar_area=[AREA, AREA, SPRING_AREA], bar_law=["linear", "linear", "ogden"],
                 hinge_stiffness=0.0, fixed=fixed)


def truss_load(z):
    return AREA * C0 * z * (H**2 - z**2) / L**3


def spring_force(length):
    stretch = length / SPRING_LENGTH
    return -SPRING_AREA * C0 / 4 * (stretch**4 - 1)  # compression positive


@pytest.fixture(scope="module")
def path():
    model = truss()
    forces = np.zeros(model.num_dofs)
    forces[model.dof(3, "z")] = -1.0  # downward unit reference load on the spring's top
    result = solve_mgdcm(model, forces, initial_load_factor=0.01, max_step_factor=0.01,
                         max_increments=5000, monitor_dof=model.dof(2, "z"),
                         max_displacement=2.2 * H)
    return model, result


def test_path_reaches_the_far_side(path):
    model, result = path
    assert result.completed, result.message
    assert result.displacement[-1, model.dof(2, "z")] < -2.2 * H


def test_equilibrium_matches_closed_form(path):
    model, result = path
    z = H + result.displacement[:, model.dof(2, "z")]
    top = H + SPRING_LENGTH + result.displacement[:, model.dof(3, "z")]
    load = result.load_factor
    # Newton stops at ||du|| <= 1e-6 with quadratic convergence: the residual left is far
    # below 1e-9 of the load scale P_MAX.
    assert np.abs(load - truss_load(z)).max() <= 1e-9 * P_MAX
    assert np.abs(load - spring_force(top - z)).max() <= 1e-9 * P_MAX


def test_limit_load_and_snap_back(path):
    model, result = path
    load = result.load_factor
    top = result.displacement[:, model.dof(3, "z")]
    # The first peak of the load is the analytic limit load, sampled to within the step size
    # (O(dz^2) below it); the trough after it is -P_MAX. (Beyond z = -h the load rises again
    # without bound, so these are local extrema.)
    peak = np.argmax(np.diff(load) < 0)
    trough = peak + np.argmax(np.diff(load[peak:]) > 0)
    assert P_MAX * (1 - 1e-3) <= load[peak] <= P_MAX * (1 + 1e-9)
    assert -P_MAX * (1 + 1e-9) <= load[trough] <= -P_MAX * (1 - 1e-3)
    # Snap-back: the load point moves back up (its displacement increases) while the path
    # goes on, i.e. the load-point displacement is not monotonic along the path.
    dtop = np.diff(top)
    assert (dtop < 0).any() and (dtop > 1e-6).any()


def test_stability_follows_the_truss_stiffness(path):
    model, result = path
    z = H + result.displacement[:, model.dof(2, "z")]
    # Free tangent [[k_t + k_s, -k_s], [-k_s, k_s]] has det = k_t k_s: one negative
    # eigenvalue exactly where the truss's own stiffness dP/dz... is negative, i.e. where
    # the load falls as the apex goes down: |z| < h / sqrt(3). Points within a step of the
    # limit points are left out (the tangent there is factorised one iterate earlier).
    margin = 0.02 * H
    inside = np.abs(z) < H / np.sqrt(3) - margin
    outside = np.abs(z) > H / np.sqrt(3) + margin
    assert (result.negative_eigenvalues[inside] == 1).all()
    assert (result.negative_eigenvalues[outside] == 0).all()


def test_energy_balance(path):
    model, result = path
    # Work of the applied load, integrated along the path by the trapezoid rule, equals the
    # stored energy. The rule's error is O(step^2): with the step factor capped at 0.01
    # (P_MAX ~ 0.5) it stays below 1e-3 of the energy scale.
    u_top = result.displacement[:, model.dof(3, "z")]
    load = result.load_factor
    work = np.concatenate([[0.0], np.cumsum(0.5 * (load[1:] + load[:-1]) * -np.diff(u_top))])
    work += load[0] * -u_top[0] * 0.5  # first increment from the unloaded state
    energy = result.energy
    assert np.abs(work - energy).max() <= 1e-3 * energy.max()


def test_force_control_snaps_through_past_the_limit_point():
    # Load-stepped Newton cannot follow the falling branch: past P_MAX the apex snaps
    # through to the inverted branch (z < -h), where the closed form admits the load again.
    model = truss()
    forces = np.zeros(model.num_dofs)
    forces[model.dof(3, "z")] = -1.2 * P_MAX
    result = solve_force_control(model, forces, 12)
    z = H + result.displacement[:, model.dof(2, "z")]
    load = result.load_factor * 1.2 * P_MAX
    assert np.abs(truss_load(z) - load).max() <= 1e-9 * P_MAX
    before = load <= P_MAX * (1 + 1e-12)
    assert (z[before] > H / np.sqrt(3)).all()  # on the near branch up to the limit load
    assert (z[~before] < -H).all()             # then on the far side
