"""Bad input to the model: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""

import math

import numpy as np
import pytest

from bad_input_helpers import driven_cell
from kresling import Design
from kresling.model import Model
from kresling.model.kresling_specimen import kresling_specimen


# 11. Silent NaN on accepted input.
def test_element_state_of_nan_displacements_is_refused():
    model, _ = driven_cell()
    with pytest.raises(ValueError, match=r"u contains NaN or inf"):
        model.element_state(np.full(model.num_dofs, np.nan))
    with pytest.raises(ValueError, match=r"u has 3 entries"):
        model.element_state([0.0, 0.0, 0.0])


@pytest.mark.parametrize("fixed", [np.nan, 0.5, 2, "yes"])
def test_fixed_flags_are_booleans(fixed):
    nodes = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    mask = np.zeros((3, 3), dtype=object)
    mask[0, 0] = fixed
    with pytest.raises(ValueError, match=r"^fixed is invalid: must be booleans"):
        Model(nodes, [[0, 1]], [], bar_modulus=1.0, hinge_stiffness=1.0, fixed=mask)


def test_a_nearly_flat_specimen_builds():
    # 2 pi - 1e-17 rounded to 2 pi, a rest angle the model refuses
    specimen = kresling_specimen(Design(3, 0.75, 5.960464477539063e-08), [0])
    assert (specimen.model.hinge_rest_angle < 2 * math.pi).all()


def test_a_zero_poisson_ratio_names_it():
    from kresling.model import SheetMaterial, build_pattern_model
    square = (np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float), [[0, 1, 2, 3]])
    with pytest.raises(ValueError, match=r"^poisson_ratio = 0 is invalid for this pattern: it "
                                         r"gives bar \d+ .* a calibrated area of 0"):
        build_pattern_model(square, material=SheetMaterial(1.0, 0.0, 1.0))


def test_a_degenerate_panel_is_named():
    # a self-intersecting pentagon: its N5B8 centre landed on a corner and the model refused
    # "bar 0 (nodes 6, 0): rest length = 0"
    from kresling.model import SheetMaterial, build_pattern_model
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]], float)
    with pytest.raises(ValueError, match=r"^panel 0: two of its sides cross or touch"):
        build_pattern_model((vertices, [[0, 1, 2, 3, 4]]), material=SheetMaterial(1e3, 0.3, 0.25))
