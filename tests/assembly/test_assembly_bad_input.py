"""Bad input to the assembly: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""


import numpy as np
import pytest

from bad_input_helpers import driven_cell


def test_element_states_that_overflow_are_refused():
    from kresling.assembly import assemble
    model, _ = driven_cell()
    u = np.zeros(model.num_dofs)
    u[-1] = 1e100  # a stretch of 1e100: the Ogden law's s^4 overflows
    with pytest.raises(ValueError, match=r"^u is invalid: the element states are not finite"):
        model.element_state(u)
    with pytest.raises(ValueError, match=r"^u is invalid: the energy or the internal force"):
        assemble(model, u)
