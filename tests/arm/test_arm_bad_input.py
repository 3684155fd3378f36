"""Bad input to the arm: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""

import math

import pytest

from bad_input_helpers import driven_cell
from kresling.solvers import (solve_displacement_control)


def test_arm_and_view_inputs_are_value_errors(tmp_path):
    from kresling.arm import build_arm, pull_until_snap
    from kresling.view import view_model, view_path, write_html
    with pytest.raises(ValueError, match=r"^direction = \{\} is invalid"):
        pull_until_snap(build_arm("111"), {})
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^field = \[\] is invalid"):
        view_model(model, field=[])
    with pytest.raises(ValueError, match=r"^u = <object"):
        view_model(model, object())
    figure = view_path(model, solve_displacement_control(model, prescribed, 3))
    for frame in (math.nan, "", [], math.inf):
        with pytest.raises(ValueError, match=r"^initial_frame = "):
            write_html(figure, tmp_path / "page.html", initial_frame=frame)
