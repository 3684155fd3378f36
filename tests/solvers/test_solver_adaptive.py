"""The adaptive displacement control (dense output between adaptive increments) against the
fixed steps: the four Table 3 designs, both states, both bending protocols, and their
snap-through test; and a snapping truss whose path the adaptive increments cannot finish.

Reference: the fixed-step path (quadratic starting guess), itself MERLIN2's path to the Newton
tolerance. Tolerance: every sample's summed force within 1e-8 of the fixed path's largest
|force| (the stated accuracy of the adaptive mode; its own target is 1e-9; on the 5 mm
protocol the fixed path's forces from two Newton starting guesses agree to about 4e-12 of it).
"""

import numpy as np
import pytest

from kresling import Design
from kresling.analyses import BendingTester
from kresling.analyses.snap_through import SnapThroughTester
from kresling.model import Model
from kresling.solvers import solve_displacement_control

TABLE3 = [(10, 0.9, 15.0), (8, 0.8, 30.0), (8, 0.8, 15.0), (4, 0.7, 30.0)]


def make_tester(n, protocol, adaptive):
    return BendingTester(n, protocol, adaptive=adaptive)


@pytest.mark.parametrize("protocol", ["5mm", "0.001rad"])
@pytest.mark.parametrize("n, lam, Lc", TABLE3)
def test_adaptive_samples_match_fixed_steps(n, lam, Lc, protocol):
    design = Design(n, lam, Lc)
    for state in (0, 1):
        fixed = make_tester(n, protocol, False).run(design, state)
        adaptive = make_tester(n, protocol, True).run(design, state)
        assert adaptive.completed, adaptive.message
        assert len(adaptive.force) == len(fixed.force)
        np.testing.assert_array_equal(adaptive.deflection, fixed.deflection)
        scale = np.abs(fixed.force).max()
        assert np.abs(adaptive.force - fixed.force).max() <= 1e-8 * scale
        assert np.array_equal(adaptive.negative_eigenvalues, fixed.negative_eigenvalues)


def test_adaptive_options_are_checked():
    with pytest.raises(ValueError, match="adaptive_tolerance"):
        BendingTester(4, adaptive=True, adaptive_tolerance=0.5)
    with pytest.raises(ValueError, match="adaptive"):
        BendingTester(4, adaptive="yes")


def make_snap_tester(n, adaptive):
    return SnapThroughTester(n, adaptive=adaptive)


@pytest.mark.parametrize("n, lam, Lc", TABLE3)
def test_adaptive_snap_through_matches_fixed_steps(n, lam, Lc):
    # The snap-through path (100 increments from Le to Lc, through the unstable branch):
    # forces within 1e-8 of the largest, and the features read off them (the snap force, the
    # energy barrier) to the same relative accuracy (measured: 3e-10 and 1e-15).
    design = Design(n, lam, Lc)
    fixed = make_snap_tester(n, False).run(design)
    adaptive = make_snap_tester(n, True).run(design)
    assert adaptive.completed, adaptive.message
    f, a = np.asarray(fixed.force), np.asarray(adaptive.force)
    assert len(a) == len(f)
    scale = np.abs(f).max()
    assert np.abs(a - f).max() <= 1e-8 * scale
    assert adaptive.snap_force == pytest.approx(fixed.snap_force, rel=1e-8)
    assert adaptive.bistable == fixed.bistable
    if np.isfinite(fixed.energy_barrier):
        assert adaptive.energy_barrier == pytest.approx(fixed.energy_barrier, rel=1e-8)


def snapping_truss():
    """Two bars of the linear law (half-span 10 mm, rise 1 mm) meeting at an apex held in x
    and y, loaded through a soft Ogden spring bar (10 mm, 0.5 N/mm) on top: driving the
    spring's top down, the apex snaps through once the truss is stiffer than the spring."""
    nodes = np.array([[-10.0, 0, 0], [10.0, 0, 0], [0, 0, 1.0], [0, 0, 11.0]])
    fixed = np.array([[1, 1, 1], [1, 1, 1], [1, 1, 0], [1, 1, 0]], dtype=bool)
    return Model(nodes, [[0, 2], [1, 2], [2, 3]], np.zeros((0, 4), dtype=int),
                 bar_modulus=1000.0, hinge_stiffness=np.zeros(0), bar_area=[1.0, 1.0, 0.005],
                 bar_law=["linear", "linear", "ogden"], fixed=fixed)


def test_a_path_adaptive_increments_cannot_finish_is_followed_in_fixed_steps():
    # The truss's spring top driven 3.4 mm down in 5 samples: the apex snaps through, and
    # the adaptive increments' predictor, past the snap, leads Newton nowhere (they give up
    # at 0.4 of the motion when asked alone); from the last equilibrium the fixed steps
    # cross it. The solver then follows the path again in fixed steps and returns their
    # result, bit for bit, with the attempts of both runs counted.
    model = snapping_truss()
    prescribed = np.zeros(12)
    prescribed[11] = -3.4
    fixed = solve_displacement_control(model, prescribed, 5, extrapolation=2)
    adaptive = solve_displacement_control(model, prescribed, 5, extrapolation=2, adaptive=True)
    assert fixed.completed and adaptive.completed, adaptive.message
    np.testing.assert_array_equal(adaptive.load_factor, fixed.load_factor)
    np.testing.assert_array_equal(adaptive.displacement, fixed.displacement)
    np.testing.assert_array_equal(adaptive.constraint_force, fixed.constraint_force)
    assert adaptive.attempted_increments > fixed.attempted_increments
    assert adaptive.displacement[-1, 8] + 1.0 < -1.0 / np.sqrt(3.0)  # the apex snapped through


def slack_cable_truss():
    """A shallow two-bar truss (half-span 10 mm, rise 5 mm) whose apex, free in z, hangs on a
    cable to a node 10 mm below it; the cable's rest length, 11 mm, leaves it slack."""
    nodes = np.array([[-10.0, 0, 0], [10.0, 0, 0], [0, 0, 5.0], [0, 0, -5.0]])
    fixed = np.array([[1, 1, 1], [1, 1, 1], [1, 1, 0], [1, 1, 0]], dtype=bool)
    return Model(nodes, [[0, 2], [1, 2]], np.zeros((0, 4), dtype=int), bar_modulus=100.0,
                 hinge_stiffness=np.zeros(0), bar_law="linear", fixed=fixed,
                 cables=[([2, 3], 50.0, 11.0)])


def test_adaptive_increments_locate_a_cable_going_taut():
    # The cable's end driven 3 mm down: slack for the first third, then taut and pulling the
    # apex down (the drive's force has a kink at t = 1/3, between samples 33 and 34). The
    # adaptive increments locate that kink as they do a hinge law's: the samples they read
    # off their Hermite curves match the fixed steps' converged ones to 1e-8 of the largest
    # force (measured 5.7e-10; a cubic across the kink cannot follow its slope's jump).
    model = slack_cable_truss()
    prescribed = np.zeros(12)
    prescribed[11] = -3.0
    fixed = solve_displacement_control(model, prescribed, 100, extrapolation=3)
    adaptive = solve_displacement_control(model, prescribed, 100, adaptive=True)
    assert fixed.completed and adaptive.completed, adaptive.message
    np.testing.assert_array_equal(adaptive.load_factor, fixed.load_factor)
    scale = np.abs(fixed.constraint_force).max()
    assert np.abs(fixed.constraint_force[:33]).max() == 0.0 < fixed.constraint_force[33, 0]
    assert np.abs(adaptive.constraint_force - fixed.constraint_force).max() <= 1e-8 * scale
    assert np.abs(adaptive.displacement - fixed.displacement).max() <= 1e-8
    # Followed adaptively on both sides of the kink (not in the fixed steps' fallback).
    interpolated = np.flatnonzero(adaptive.iterations == 0)
    assert interpolated.min() < 33 and interpolated.max() > 34
    assert adaptive.attempted_increments < fixed.attempted_increments
