"""Bad input to the geometry: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""

import math

import pytest

from kresling import Design


# 1. A subnormal bad value: std::stod threw out_of_range (an IndexError) in the message.
def test_subnormal_bad_value_is_a_value_error():
    with pytest.raises(ValueError, match=r"^Lc = -1e-310 is invalid: must be >= 0$"):
        Design(10, 0.8, -1e-310)


def test_psi_ratio_overflow_is_documented_inf():
    # Psi_con = 1.6e-312 rad: the ratio exceeds the largest float (documented: inf).
    d = Design(70, 0.8, 2.4e-306, 825111)
    assert d.psi_con > 0 and d.psi_ratio == math.inf
    assert "exceeds the largest float" in type(d).psi_ratio.__doc__


# 14. The property test's flaky example: alpha_e was exactly 0 at lam = 1 - 2^-52.
def test_alpha_e_is_positive_for_every_lambda_below_one():
    d = Design(28, 0.9999999999999998, 0, 1)
    assert 0.0 < d.alpha_e <= d.alpha0 < math.pi
    assert d.alpha_e == pytest.approx(math.pi - d.alpha0 - 2 * d.phi, abs=1e-15)
