"""The linearised bending stiffness (Appendix A's model) against the nonlinear test."""

import math

import pytest

from kresling import Design
from kresling.analyses import LinearBendingTester, bending_test, linear_bending_stiffness
from kresling.model import SpecimenParameters

DESIGNS = [Design(8, 0.8, 30), Design(8, 0.8, 15), Design(4, 0.7, 30), Design(10, 0.9, 15),
           Design(6, 0.75, 50)]


@pytest.mark.parametrize("design", DESIGNS, ids=repr)
def test_agrees_with_the_nonlinear_small_deflection_protocol(design):
    # At 0.001 rad the nonlinear K_B differs from the linear one by the geometric
    # nonlinearity, measured 4e-6 to 1.4e-5 relative on these designs: within 3e-5.
    tester = LinearBendingTester(design.n)
    for state in (0, 1):
        nonlinear = bending_test(design, state, "0.001rad").stiffness
        assert tester.run(design, state) == pytest.approx(nonlinear, rel=3e-5)


def test_gap_to_the_nonlinear_test_shrinks_with_the_deflection():
    # The gap is second order in the angle (M is odd in delta): 1.2e-5 at 1e-3 rad, 1.2e-7
    # at 1e-4 rad; the Newton tolerance (1e-6 mm) leaves it there.
    d = Design(10, 0.9, 15)
    linear = linear_bending_stiffness(d, 1)
    big = bending_test(d, 1, "0.001rad").stiffness / linear - 1
    small = bending_test(d, 1, "0.001rad", deflection_angle=1e-4).stiffness / linear - 1
    assert abs(small) < abs(big) / 50 and abs(small) < 1e-6


def test_pin_line_turned_against_the_load_changes_the_stiffness():
    # Turning the pin line by pi/n relative to the load moves K_B by 4-65 % (MERLIN2 runs;
    # docs/thesis_equations.md, 'Bending test').
    for design, low, high in ((Design(10, 0.9, 15), 0.03, 0.10), (Design(4, 0.7, 30), 0.5, 0.7)):
        for state in (0, 1):
            ratio = linear_bending_stiffness(design, state, pin_offset=math.pi / design.n) / \
                linear_bending_stiffness(design, state)
            assert low < ratio - 1 < high


def test_scales_with_kf():
    d = Design(6, 0.8, 20)
    base = linear_bending_stiffness(d, 0)
    assert linear_bending_stiffness(d, 0, parameters=SpecimenParameters(kf=0.47)) == \
        pytest.approx(10 * base, rel=1e-9)


@pytest.mark.parametrize("call, message", [
    (lambda: LinearBendingTester(5), r"n = 5 is invalid: must be even for the bending test"),
    (lambda: LinearBendingTester(8, cells=3), r"cells = 3 is invalid"),
    (lambda: LinearBendingTester(8).run(Design(6, 0.8, 30), 1), r"design.n = 6 is invalid"),
    (lambda: LinearBendingTester(8).run(Design(8, 0.8, 30), 2), r"state = 2 is invalid"),
    (lambda: LinearBendingTester(8).run(Design(8, 0.8, 30), 1, angle=math.nan), r"angle = nan"),
])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()
