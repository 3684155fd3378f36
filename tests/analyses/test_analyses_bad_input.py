"""Bad input to the analyses: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""

import math

import numpy as np
import pytest

from bad_input_helpers import driven_cell
from kresling import Design
from kresling.model import Model


def test_linear_bending_at_lc_zero_names_lc():
    from kresling.analyses import linear_bending_stiffness
    with pytest.raises(ValueError, match=r"^Lc = 0 is invalid"):
        linear_bending_stiffness(Design(8, 0.8, 0.0), "contracted")
    assert math.isfinite(linear_bending_stiffness(Design(8, 0.8, 0.0), "extended"))


def test_nearly_flat_cells_are_refused_by_the_tests():
    # Psi below 1e-6 rad is not resolved by the model's hinge angles (MERLIN2's arccosine):
    # its forces there were noise of any size (a 2.5e12 N "snap force" at Lc = 2e-311).
    from kresling.analyses import bending_test, snap_through
    for design, name in ((Design(4, 0.6, 1e-300), "Lc"), (Design(4, 0.6, 1e-6), "Lc"),
                         (Design(3, 0.5 + 2**-52, 2.2e-311, 67.0), "Lc")):
        with pytest.raises(ValueError, match=rf"^{name} = .* is invalid: must be > 0 for the "
                                             r"snap-through test, and large enough that the "
                                             r"contracted cell is not flat"):
            snap_through(design)
    with pytest.raises(ValueError, match=r"^lam = 0.5000000000000002\d* is invalid: must be further "
                                         r"from 0.5 for the bending test in the extended state"):
        bending_test(Design(4, 0.5 + 2**-52, 0.0), "extended")
    assert math.isfinite(snap_through(Design(4, 0.6, 1e-3)).force[-1])


def test_random_designs_never_report_absurd_snap_forces():
    from kresling.analyses import snap_through
    rng = np.random.default_rng(7)
    for _ in range(20):
        d = Design(int(rng.integers(3, 13)), rng.uniform(0.51, 0.99),
                   float(rng.choice([1e-9, rng.uniform(0, 1), rng.uniform(0, 100)])),
                   float(10 ** rng.uniform(-1, 3)))
        try:
            r = snap_through(d)
        except ValueError as error:
            assert str(error).startswith(("Lc = ", "lam = ")), error
            continue
        assert np.isfinite(r.force).all()
        assert math.isnan(r.snap_force) or abs(r.snap_force) < 1e6, d


# 9. Non-integers silently truncated.
def test_non_integers_are_never_truncated():
    from kresling.analyses import (BendingTester, LinearBendingTester, SnapThroughTester)
    nodes = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    with pytest.raises(ValueError, match=r"^bars\[0, 1\] = 1.7 is invalid: must be an integer"):
        Model(nodes, [[0, 1.7]], [], bar_modulus=1.0, hinge_stiffness=1.0)
    with pytest.raises(ValueError, match=r"^bars has dtype bool: must be integers"):
        Model(nodes, [[False, True]], [], bar_modulus=1.0, hinge_stiffness=1.0)
    with pytest.raises(ValueError, match=r"^steps = 2.7 is invalid"):
        BendingTester(8, steps=2.7)
    with pytest.raises(ValueError, match=r"^cells = 4.9 is invalid"):
        BendingTester(8, cells=4.9)
    with pytest.raises(ValueError, match=r"^cells = 4.9 is invalid"):
        LinearBendingTester(8, cells=4.9)
    with pytest.raises(ValueError, match=r"^n = 8.9 is invalid"):
        SnapThroughTester(8.9)
    model, _ = driven_cell()
    with pytest.raises(ValueError, match=r"^node = 1.5 is invalid"):
        model.dof(1.5, "x")
    with pytest.raises(ValueError, match=r"^axis = True is invalid"):
        model.dof(1, True)
    assert model.dof(1.0, "y") == 4


# 12. A valid design raised RuntimeError: near-flat hinges read with an arccosine.
def test_facet_angle_of_a_nearly_flat_extended_cell():
    from kresling.analyses import facet_angle, facet_angles
    d = Design(15, 0.5000000000000001, 0.0)
    assert np.ptp(facet_angles(d, 1)) <= 1e-12 * max(d.psi_ext, 1e-300) + 1e-15
    assert facet_angle(d, 1) == pytest.approx(d.psi_ext, rel=1e-9)


# 15. The smaller ones.
def test_analyses_given_a_non_design():
    from kresling.analyses import (bending_test, facet_angle, linear_bending_stiffness,
                                   snap_through)
    for call in (lambda: snap_through("x"), lambda: bending_test((8, 0.8, 30), 1),
                 lambda: linear_bending_stiffness(None, 1), lambda: facet_angle(8, 1)):
        with pytest.raises(ValueError, match=r"^design = .* is invalid: must be a "
                                             r"kresling.Design"):
            call()


def test_linear_bending_never_returns_a_bare_nan():
    # Lc / R = 1e6: the condensed stiffness is rounding noise (-9.5e-9); it was a bare NaN.
    from kresling.analyses import linear_bending_stiffness
    with pytest.raises(ValueError, match=r"^design = Design\(n=8, .* has no linearised K_B in "
                                         r"the contracted state: the condensed stiffness is "):
        linear_bending_stiffness(Design(8, 0.584, 1000, 0.001), 0)


def test_an_eccentricity_whose_loads_overflow_is_refused_naming_it():
    # (found by the fuzz target at scale 50: the solver's "forces contains NaN or inf")
    from kresling.analyses.snap_dynamics import snap_in_time

    with pytest.raises(ValueError, match=r"eccentricity = .* is invalid: the top's loads"):
        snap_in_time(Design(10, 0.9, 15.0, 30.0), eccentricity=8.98846567431158e+307)
