"""The snap-through test (section 3.5): the MERLIN2 reference run, the definitions of the
energy barrier and of bistability, figure 3.17's trends, reuse and bad input."""

import math

import numpy as np
import pytest

from kresling import Design
from kresling.analyses import SnapThroughTester, snap_through
from kresling.model import SpecimenParameters


def test_merlin2_reference_run():
    # docs/thesis_equations.md, 'Bending test' (snap-through): n=8, Lc=30, lambda=0.8 peaks at 4.34 N at 5.93 mm, then dips slightly below
    # zero. Converged (1600 steps): 4.3405 N at 5.924 mm.
    r = snap_through(Design(8, 0.8, 30))
    assert r.completed and len(r.force) == 101 and r.force[0] == 0 and r.displacement[0] == 0
    assert r.snap_force == pytest.approx(4.34, abs=0.005)
    assert r.snap_displacement == pytest.approx(5.93, abs=0.01)
    assert -0.2 < r.minimum_force < 0
    assert r.displacement[-1] == pytest.approx(r.extended_height - r.contracted_height, rel=1e-12)


def test_default_steps_are_converged():
    # 100 increments against 400: the snap force to 1e-4, its displacement to 0.01 mm.
    for design in (Design(4, 0.7, 30), Design(10, 0.9, 15)):
        coarse, fine = snap_through(design), snap_through(design, steps=400)
        assert coarse.snap_force == pytest.approx(fine.snap_force, rel=1e-4)
        assert coarse.snap_displacement == pytest.approx(fine.snap_displacement, abs=0.01)
        assert coarse.energy_barrier == pytest.approx(fine.energy_barrier, rel=1e-3, nan_ok=True)


def test_energy_barrier_is_the_work_of_the_drive():
    r = snap_through(Design(8, 0.8, 15), steps=400)
    below = r.displacement < r.unstable_displacement
    d = np.append(r.displacement[below], r.unstable_displacement)
    F = np.append(r.force[below], 0.0)
    work = float(np.sum(0.5 * (F[1:] + F[:-1]) * np.diff(d)))
    assert r.energy_barrier == pytest.approx(work, rel=1e-3)
    # Along the path the recorded strain energy is the integral of the force.
    trapezoid = np.concatenate([[0], np.cumsum(0.5 * (r.force[1:] + r.force[:-1]) * np.diff(r.displacement))])
    assert np.allclose(r.energy, trapezoid, rtol=2e-3, atol=1e-3)


def test_bistability_verdicts():
    bistable = snap_through(Design(8, 0.8, 30))
    assert bistable.bistable and bistable.stable_negative_eigenvalues == 0
    assert bistable.unstable_displacement < bistable.stable_displacement < bistable.displacement[-1]
    assert bistable.contracted_height < bistable.stable_height < 40
    assert bistable.stable_energy < bistable.energy_barrier
    # The thesis's sample 3: the force never returns to zero (as it says of figure 3.16).
    mono = snap_through(Design(4, 0.7, 30))
    assert not mono.bistable and mono.minimum_force > 0 and math.isnan(mono.energy_barrier)
    assert "monostable" in mono.bistability
    # The optimum comes to rest tilted: its level contracted equilibrium is a saddle.
    optimum = snap_through(Design(10, 0.9, 15))
    assert optimum.bistable and np.degrees(optimum.stable_tilt) > 10
    assert "tilted" in optimum.bistability


def test_second_state_near_the_edge_of_bistability():
    # A shallow dip (-0.015 N): released, the top polygon's centre node domes up by 0.6 mm;
    # the cell's travel is read from the perimeter, past the unstable state.
    r = snap_through(Design(4, 0.725, 33.75))
    assert -0.02 < r.minimum_force < 0
    assert r.bistable and r.stable_negative_eigenvalues == 0
    assert r.unstable_displacement < r.stable_displacement < r.displacement[-1]
    assert 0 < r.stable_energy < r.energy_barrier


def test_no_local_maximum_gives_nan_and_says_so():
    r = snap_through(Design(10, 0.7, 60))
    assert r.completed and not r.has_peak and math.isnan(r.snap_force)
    assert np.all(np.diff(r.force) > 0) and "no local maximum" in r.bistability


def test_figure_3_17_trends():
    # The snap force rises with lambda and falls with Lc, for every n of the study.
    for n in (4, 6, 8, 10):
        tester = SnapThroughTester(n)
        by_lam = [tester.run(Design(n, lam, 20)).snap_force for lam in (0.75, 0.8, 0.85, 0.9)]
        by_Lc = [tester.run(Design(n, 0.85, Lc)).snap_force for Lc in (15, 25, 40, 60)]
        assert np.all(np.diff(by_lam) > 0), (n, by_lam)
        assert np.all(np.diff(by_Lc) < 0), (n, by_Lc)


def test_forces_scale_with_kf():
    # Every stiffness is proportional to kf: forces and energies scale, displacements do not.
    d = Design(6, 0.85, 25)
    base = snap_through(d)
    scaled = snap_through(d, parameters=SpecimenParameters(kf=0.47))
    assert scaled.snap_force == pytest.approx(10 * base.snap_force, rel=1e-6)
    assert scaled.energy_barrier == pytest.approx(10 * base.energy_barrier, rel=1e-6)
    assert scaled.snap_displacement == pytest.approx(base.snap_displacement, rel=1e-6)
    assert scaled.bistable == base.bistable


def test_tester_is_reusable_and_equal_to_one_off_runs():
    tester = SnapThroughTester(8)
    for lam, Lc in ((0.9, 15.0), (0.7, 60.0), (0.8, 30.0)):
        d = Design(8, lam, Lc)
        a, b = tester.run(d), snap_through(d)
        assert np.array_equal(a.force, b.force) and a.bistable == b.bistable


def test_odd_n_runs():
    r = snap_through(Design(5, 0.85, 20))
    assert r.completed and r.snap_force > 0


@pytest.mark.parametrize("call, message", [
    (lambda: snap_through(Design(8, 0.8, 30), steps=0), r"steps = 0 is invalid"),
    (lambda: SnapThroughTester(8).run(Design(6, 0.8, 30)), r"design.n = 6 is invalid"),
    (lambda: SnapThroughTester(2), r"n = 2 is invalid"),
    (lambda: snap_through(Design(8, 0.8, 30), extrapolation=4), r"extrapolation = 4 is invalid"),
])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
