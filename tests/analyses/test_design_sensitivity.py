"""Exact design derivatives of a Kresling cell (kresling.analyses.design_sensitivity) against
central differences of the same tests run again with the variable moved.

The finite differences move lambda, Lc and R through the Design itself, kf through the
specimen's parameters, and the thickness through what it stands for (every bar's area times
t/t0, the spokes' factor times (t/t0)^3): none of them goes through the core's chain rule,
which is what they check. The tests are short versions of the thesis's (10 bending
increments, 30 snap-through increments) on an octagonal cell: a derivative is that of the
discretised test, so the differences see the same discretisation.

Tolerance: Newton converges to 1e-10 mm in both, and the forces carry rounding of about
1e-11 of their size (stiff bars, a 0.03 mm drive under the 0.001 rad protocol), which a
central difference divides by its relative step: 1e-6 at a step of 1e-5. So the steps are
1e-4 of lambda, Lc and R (truncation ~1e-8) and 1e-3 of the thickness and kf (K_B is
linear in kf, cubic at most in the thickness: truncation ~1e-7); measured, the derivatives
agree to 5e-7 or better. 1e-5 relative is far below a missing term (the drive's or the
rest values' motion is O(1) relative).
"""

import dataclasses
import math

import pytest

from kresling.analyses.design_sensitivity import (DESIGN_VARIABLES, bending_gradient,
                                               design_gradient, snap_through_gradient)
from kresling.geometry import Design
from kresling.model.kresling_specimen import SpecimenParameters

FACET_THICKNESS = 0.25
DESIGN = dict(n=8, lam=0.8, Lc=15.0, R=30.0)
BENDING_STEPS = 10
SNAP_STEPS = 30
REL_TOL = 1e-5


def _moved(variable, h, parameters=None):
    """The design and parameters with ``variable`` moved by h (its own units)."""
    values = dict(DESIGN)
    parameters = parameters or SpecimenParameters()
    if variable in ("lam", "Lc", "R"):
        values[variable] += h
    elif variable == "kf":
        parameters = dataclasses.replace(parameters, kf=parameters.kf + h)
    else:  # thickness
        s = 1.0 + h / FACET_THICKNESS
        parameters = dataclasses.replace(parameters, material_area=parameters.material_area * s,
                                         mountain_area=parameters.mountain_area * s,
                                         spoke_factor=parameters.spoke_factor * s ** 3)
    return Design(values["n"], values["lam"], values["Lc"], values["R"]), parameters


STEP = {"lam": 8e-5, "Lc": 1.5e-3, "R": 3e-3, "thickness": 2.5e-4, "kf": 4.7e-5}


def _central(quantity, variable, scale=1.0):
    h = STEP[variable] * scale
    plus, minus = (quantity(*_moved(variable, s * h)) for s in (1, -1))
    return (plus - minus) / (2 * h)


@pytest.mark.parametrize("state", [0, 1])
@pytest.mark.parametrize("protocol", ["5mm", "0.001rad"])
def test_bending_stiffness_derivatives_match_differences(state, protocol):
    design, parameters = _moved("lam", 0.0)
    k, gradient = bending_gradient(design, state, protocol, steps=BENDING_STEPS)
    assert set(gradient) == set(DESIGN_VARIABLES)
    for variable in DESIGN_VARIABLES:
        fd = _central(lambda d, p: bending_gradient(d, state, protocol, parameters=p,
                                                    steps=BENDING_STEPS, variables=["kf"])[0],
                      variable)
        assert gradient[variable] == pytest.approx(fd, rel=REL_TOL, abs=REL_TOL * abs(k)), \
            (state, protocol, variable, gradient[variable], fd)


def test_snap_force_and_energy_barrier_derivatives_match_differences():
    design, _ = _moved("lam", 0.0)
    result = snap_through_gradient(design, steps=SNAP_STEPS)
    for quantity in ("snap_force", "energy_barrier"):
        value, gradient = result[quantity]
        assert math.isfinite(value), quantity
        for variable in DESIGN_VARIABLES:
            fd = _central(lambda d, p: snap_through_gradient(d, parameters=p, steps=SNAP_STEPS,
                                                             variables=["kf"])[quantity][0],
                          variable)
            assert gradient[variable] == pytest.approx(fd, rel=REL_TOL, abs=REL_TOL * abs(value)), \
                (quantity, variable, gradient[variable], fd)


def test_the_ratio_follows_the_quotient_rule_and_the_values_are_the_tests():
    from kresling.analyses import bending_test

    design, _ = _moved("lam", 0.0)
    g = design_gradient(design, steps=BENDING_STEPS, variables=["lam", "kf"])
    k_ext, k_con = g.values["kb_extended"], g.values["kb_contracted"]
    assert g.values["kb_ratio"] == pytest.approx(k_ext / k_con, rel=1e-14)
    for v in ("lam", "kf"):
        expected = (g.gradient["kb_extended"][v] * k_con
                    - k_ext * g.gradient["kb_contracted"][v]) / k_con ** 2
        assert g.gradient["kb_ratio"][v] == pytest.approx(expected, rel=1e-12)
    # The values are the bending test's (converged further: to its 1e-6 mm tolerance).
    reference = bending_test(design, 1, steps=BENDING_STEPS, adaptive=False).stiffness
    assert k_ext == pytest.approx(reference, rel=1e-6)
    # K_B is proportional to kf (every stiffness is a ratio to it): dK/dkf = K/kf.
    assert g.gradient["kb_extended"]["kf"] == pytest.approx(k_ext / 0.047, rel=1e-8)


def test_bad_requests_are_refused():
    design, _ = _moved("lam", 0.0)
    with pytest.raises(ValueError, match="variables: 'E' is invalid: must be among lam"):
        bending_gradient(design, 1, variables=["E"])
    with pytest.raises(ValueError, match="variables is empty"):
        snap_through_gradient(design, variables=[])
    with pytest.raises(ValueError, match="n"):
        bending_gradient(Design(5, 0.8, 10.0, 30.0), 1, steps=BENDING_STEPS)
