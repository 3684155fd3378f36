"""Bad design input: a ValueError naming the parameter, the value and the allowed range."""

import math

import numpy as np
import pytest

from kresling import Design, design_quantities


@pytest.mark.parametrize(
    "kwargs, fragment",
    [
        ({"n": 2}, "n = 2 is invalid: must be an integer >= 3"),
        ({"n": 10.5}, "n = 10.5 is invalid: must be an integer >= 3"),
        ({"n": "10"}, "n = '10' is invalid"),
        ({"n": True}, "n = True is invalid"),
        ({"n": float("nan")}, "n = nan is invalid"),
        ({"R": 0.0}, "R = 0 is invalid: must be > 0"),
        ({"R": -30.0}, "R = -30 is invalid: must be > 0"),
        ({"R": math.inf}, "R = inf is invalid: must be a finite number"),
        ({"lam": 0.5}, "lam = 0.5 is invalid: must be in the open interval (0.5, 1)"),
        ({"lam": 1.0}, "lam = 1 is invalid: must be in the open interval (0.5, 1)"),
        ({"lam": 1.2}, "lam = 1.2 is invalid"),
        ({"lam": float("nan")}, "lam = nan is invalid: must be a finite number"),
        ({"Lc": -1.0}, "Lc = -1 is invalid: must be >= 0"),
        ({"Lc": -math.inf}, "Lc = -inf is invalid: must be a finite number"),
        ({"chirality": 0}, "chirality = 0 is invalid: must be +1 or -1"),
        ({"chirality": 2}, "chirality = 2 is invalid"),
        ({"chirality": 0.5}, "chirality = 0.5 is invalid: must be an integer"),
    ],
)
def test_invalid_design(kwargs, fragment):
    args = {"n": 10, "lam": 0.9, "Lc": 15.0, "R": 30.0, "chirality": 1}
    args.update(kwargs)
    with pytest.raises(ValueError) as info:
        Design(**args)
    assert fragment in str(info.value)


def test_alpha_off_the_path():
    d = Design(10, 0.9, 0.0)
    with pytest.raises(ValueError, match=r"alpha = .*\(L\(alpha\)\^2 = -"):
        d.height_at(d.alpha0 + 0.2)
    with pytest.raises(ValueError, match="alpha = nan is invalid: must be a finite number"):
        d.mountain_length_at(float("nan"))


def test_invalid_state():
    with pytest.raises(ValueError, match="state = 2 is invalid"):
        Design(10, 0.9, 15).height(2)
    with pytest.raises(ValueError, match="state = 'open' is invalid"):
        Design(10, 0.9, 15).twist("open")


def test_vectorised_names_the_bad_entry():
    with pytest.raises(ValueError, match=r"lam\[3\] = 1.1 is invalid"):
        design_quantities(10, [0.7, 0.8, 0.9, 1.1], 15.0)
    with pytest.raises(ValueError, match=r"n\[1\] = 4.5 is invalid"):
        design_quantities([4, 4.5], 0.8, 15.0)
    with pytest.raises(ValueError, match=r"Lc\[1\] = nan is invalid"):
        design_quantities(10, 0.8, np.array([15.0, np.nan]))
