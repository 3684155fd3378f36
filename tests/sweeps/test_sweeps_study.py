"""The thesis's conclusions on a coarse grid, the continuous optimiser and the sensitivity
report."""

import numpy as np
import pytest

from kresling import Design
from kresling.analyses import bending_stiffness
from kresling.sweeps import conclusions as c
from kresling.sweeps import design_grid, sweep
from kresling.sweeps.optimize import optimize_design
from kresling.sweeps.sensitivity import sensitivity


@pytest.fixture(scope="module")
def coarse():
    return sweep(design_grid(size=5), ["kb_ratio", "psi_ratio"], workers=2, progress=False)


def test_every_n_peaks_at_the_highest_lambda_and_lowest_Lc(coarse):
    psi = c.maxima_by_n(coarse, "psi_ratio")
    for n, best in c.maxima_by_n(coarse, "kb_ratio").items():
        assert (best["Lc"], best["lam"]) == (15.0, 0.9) == c.corner(coarse, n)
        assert (psi[n]["Lc"], psi[n]["lam"]) == (15.0, 0.9)


def test_maximum_rises_with_n_and_levels_off(coarse):
    maxima = [row["kb_ratio"] for row in c.maxima_by_n(coarse, "kb_ratio").values()]
    assert c.rising_steps(maxima) == 3
    # 4 -> 6 gains about 7.8; 8 -> 10 about 0.35: under a fifth of the first step.
    assert 0 < c.leveling(maxima) < 0.2


def test_optimum_and_trends(coarse):
    best = coarse.best("kb_ratio")
    assert (best["n"], best["Lc"], best["lam"]) == (10, 15.0, 0.9)
    for metric in ("kb_ratio", "psi_ratio"):
        assert c.monotone_fraction(coarse, metric, "lam", +1) == 1.0
        assert c.monotone_fraction(coarse, metric, "Lc", -1) == 1.0
    assert min(c.rank_correlation(coarse, "kb_ratio", "psi_ratio", n) for n in (4, 6, 8, 10)) > 0.95


def test_conclusion_helpers_on_made_up_numbers():
    assert c.rising_steps([1, 2, 2, 3]) == 2
    assert c.leveling([1, 3, 3.5, 3.6]) == pytest.approx(0.05)
    assert np.isnan(c.leveling([1, 2]))


def test_optimizer_finds_the_corner_and_respects_constraints():
    free = optimize_design(10, workers=1)
    assert free.success and (free.design.Lc, free.design.lam) == (15.0, 0.9)
    assert set(free.active) == {"Lc min", "lam max"}
    assert free.value == bending_stiffness(free.design, "0.001rad").ratio
    # A manufacturing bound on lambda moves the optimum onto it.
    bounded = optimize_design(10, lam=(0.7, 0.85), workers=1)
    assert (bounded.design.Lc, bounded.design.lam) == (15.0, 0.85)
    # A floor on K_con (a joint that is not too soft) makes the optimum interior in Lc.
    floor = optimize_design(10, constraints={"kb_con": (0.3, None)}, workers=1)
    assert floor.success and "kb_con min" in floor.active
    assert floor.values["kb_con"] == pytest.approx(0.3, rel=1e-5)
    assert 15 < floor.design.Lc < 60 and floor.design.lam == 0.9
    check = bending_stiffness(floor.design, "0.001rad")
    assert floor.value == pytest.approx(check.ratio, rel=1e-12) and floor.value < free.value


def test_optimizer_reports_an_infeasible_constraint():
    result = optimize_design(8, constraints={"kb_ext": (50.0, None)}, workers=1)
    assert not result.success and "constraints not met" in result.message


@pytest.mark.parametrize("kwargs, message", [
    (dict(n=7), "n = 7 is invalid for kb_ratio"),
    (dict(n=8, metric="nope"), "unknown metric column 'nope'"),
    (dict(n=8, constraints={"nope": (0, 1)}), "unknown metric column 'nope'"),
])
def test_optimizer_bad_input(kwargs, message):
    with pytest.raises(ValueError, match=message):
        optimize_design(**kwargs)


def test_sensitivity_at_the_optimum():
    result = sensitivity(Design(10, 0.9, 15), points=21, workers=1)
    assert result.value == bending_stiffness(Design(10, 0.9, 15), "0.001rad").ratio
    # The ratio falls away from the corner along both axes (derivatives from 1e-3 mm and
    # 1e-5 steps agree with a 1e-2 / 1e-3 secant to 1 %).
    assert result.gradient["Lc"] < 0 < result.gradient["lam"]
    secant = (bending_stiffness(Design(10, 0.9, 15.01), "0.001rad").ratio - result.value) / 0.01
    assert result.gradient["Lc"] == pytest.approx(secant, rel=0.01)
    x, y = result.profiles["Lc"]
    assert x[0] == 15 and x[-1] == 60 and np.all(np.diff(y) < 0)
    x, y = result.profiles["lam"]
    assert x[0] == 0.9 and x[-1] == pytest.approx(0.7) and np.all(np.diff(y) < 0)
    half = result.drop["Lc"][0.5]
    assert bending_stiffness(Design(10, 0.9, half), "0.001rad").ratio == \
        pytest.approx(0.5 * result.value, rel=0.02)
    assert "falls to 90%" in result.summary()


def test_exact_gradients_find_the_optimum_differences_find_in_fewer_evaluations():
    # The interior optimum of the K_con floor: SLSQP on the tests' exact derivatives and on
    # forward differences (step 1e-4 in the unit box, good to ~1e-5) stops at the same
    # design to 1e-6 (measured: 2e-10), the exact one after far fewer designs (5 against
    # 147 when measured).
    exact = optimize_design(10, constraints={"kb_con": (0.3, None)}, workers=1)
    differences = optimize_design(10, constraints={"kb_con": (0.3, None)}, workers=1,
                                  gradient="differences")
    assert exact.success and differences.success
    assert exact.design.Lc == pytest.approx(differences.design.Lc, rel=1e-6)
    assert exact.design.lam == differences.design.lam == 0.9
    assert exact.value == pytest.approx(differences.value, rel=1e-6)
    assert exact.evaluations < differences.evaluations / 5
    with pytest.raises(ValueError, match="gradient = 'adjoint' is invalid"):
        optimize_design(10, gradient="adjoint", workers=1)
