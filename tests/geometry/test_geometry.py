"""Known values of the generalized Kresling geometry (thesis Appendix E, the MERLIN2 reference
runs and golden model)."""

import math
import pickle

import numpy as np
import pytest

import kresling
from kresling import Design, data, design_quantities

# Le of the optimum, as the thesis's Appendix E code uses it. That value came from a numerical
# root; the closed form evaluated in 40-digit arithmetic (mpmath) gives
# 55.81946677978192128656821413771396, 1.6e-10 below it, which is what we compute.
LE_THESIS = 55.8194667799374
LE_EXACT = 55.81946677978192128656821413771396


def test_extended_height_of_the_optimum():
    d = Design(n=10, lam=0.9, Lc=15, R=30)
    assert d.Le == pytest.approx(LE_THESIS, abs=1e-9)
    assert d.Le == pytest.approx(LE_EXACT, abs=1e-13)
    # The extended module (two cells) of eqn 30.
    assert 2 * d.Le == pytest.approx(111.639, abs=5e-4)


@pytest.mark.parametrize(
    "n, lam, Lc, Le",
    [(8, 0.8, 30, 55.317649), (8, 0.8, 15, 48.836895), (4, 0.7, 30, 41.068587)],
)
def test_extended_heights_to_six_decimals(n, lam, Lc, Le):
    # The MERLIN2 reference runs' Le to 6 decimals; the table prints 8 (below).
    assert Design(n, lam, Lc).Le == pytest.approx(Le, abs=5e-7)


def test_extended_heights_match_the_merlin2_reference_table():
    table = np.genfromtxt(data.path("merlin2/table3_reference.csv"), delimiter=",", names=True)
    for row in table:
        d = Design(int(row["n"]), row["lambda"], row["Lc_mm"])
        assert d.Le == pytest.approx(row["Le_mm"], abs=5e-9)


def test_facet_angle_matches_the_merlin2_golden_hinge(golden_dir):
    # Hinge 1 of the golden model lies on a bottom polygon edge, between the base polygon and
    # a perimeter triangle; its as-built angle is Psi in the extended state.
    folds = np.genfromtxt(golden_dir / "folds.csv", delimiter=",", names=True)
    assert Design(4, 0.7, 30).psi_ext == pytest.approx(folds["theta0"][0], abs=1e-12)


def test_closed_forms_for_the_optimum():
    d = Design(10, 0.9, 15)
    assert d.P == pytest.approx(2 * 30 * math.sin(math.pi / 10), rel=1e-15)
    assert d.gamma == pytest.approx(math.pi * 8 / 20, rel=1e-15)
    assert d.alpha0 == pytest.approx(2 * 0.9 * d.gamma, rel=1e-15)
    assert d.alpha_e == pytest.approx(math.pi - d.alpha0 - 2 * math.pi / 10, rel=1e-15)
    # Law of cosines in the flat facet (P, Vg, Mg) closes: eqn 5 reproduces Mg.
    Mg = math.sqrt(d.P**2 + d.Vg**2 - 2 * d.P * d.Vg * math.cos(d.theta_g))
    assert Mg == pytest.approx(d.Mg, rel=1e-13)


def test_states_and_path():
    d = Design(10, 0.9, 15)
    assert d.height("extended") == d.Le and d.height(0) == d.Lc
    assert d.twist(1) == d.alpha_e and d.twist("contracted") == d.alpha0
    alpha = np.linspace(d.alpha_e, d.alpha0, 7)
    L = d.height_at(alpha)
    assert L.shape == (7,)
    assert L[0] == pytest.approx(d.Le, rel=1e-14) and L[-1] == pytest.approx(d.Lc, rel=1e-14)
    assert isinstance(d.height_at(d.alpha0), float)
    # Between the states the mountain bar is compressed: m(alpha) < Mg strictly inside.
    assert np.all(d.mountain_length_at(alpha[1:-1]) < d.Mg)
    assert d.facet_angle_at(d.alpha0) == pytest.approx(d.psi_con, rel=1e-14)
    assert d.psi_ratio == pytest.approx(d.psi_ext / d.psi_con)


def test_design_is_a_value():
    d = Design(10, 0.9, 15)
    assert d == Design(10.0, 0.9, 15.0) and hash(d) == hash(Design(10, 0.9, 15))
    assert pickle.loads(pickle.dumps(d)) == d
    m = d.mirrored()
    assert m.chirality == -1 and m.Le == d.Le and m.psi_ext == d.psi_ext
    assert "n=10" in repr(d)
    q = d.quantities()
    for key in ("P", "gamma", "V", "M", "Vg", "Mg", "theta_g", "alpha0", "alpha_e", "Le",
                "Psi_ext", "Psi_con"):
        assert math.isfinite(q[key])


def test_design_quantities_over_the_thesis_grid():
    Lc, lam = np.meshgrid(np.linspace(15, 60, 100), np.linspace(0.7, 0.9, 100))
    q = design_quantities(10, lam, Lc)
    assert q["Le"].shape == (100, 100) and q["n"].shape == (100, 100)
    i, j = 37, 81
    single = Design(10, lam[i, j], Lc[i, j]).quantities()
    for key, value in single.items():
        if key != "chirality":
            assert q[key][i, j] == value, key


def test_design_quantities_broadcasts_n():
    q = design_quantities(np.array([4, 6, 8, 10])[:, None], 0.8, np.array([15.0, 30.0]))
    assert q["Le"].shape == (4, 2)
    assert q["Le"][2, 1] == pytest.approx(55.317649, abs=5e-7)


def test_version():
    assert kresling.__version__
