"""Bad input of every layer: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""


import pytest

from bad_input_helpers import driven_cell
from kresling.model import Model
from kresling.solvers import (condensed_stiffness)


def test_none_and_wrong_types_are_value_errors(tmp_path):
    from kresling.manipulator.markers import read_markers
    from kresling.sweeps import design_grid, sweep
    nodes = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.1]]
    with pytest.raises(ValueError, match=r"^hinge_law = None is invalid: must be one of"):
        Model(nodes, [[0, 1]], [[1, 2, 0, 3]], bar_modulus=1.0, hinge_stiffness=1.0,
              hinge_law=None)
    markers = tmp_path / "m.csv"
    markers.write_text("config,step,marker,x,y\n")
    with pytest.raises(ValueError, match=r"^modules = None is invalid"):
        read_markers(markers, None)
    with pytest.raises(ValueError, match=r"^metrics = None is invalid"):
        sweep(design_grid((4,), 2), None, progress=False)
    model, _ = driven_cell()
    with pytest.raises(ValueError, match=r"^dofs = 3 is invalid: must be a sequence"):
        condensed_stiffness(model, 3)
    with pytest.raises(ValueError, match=r"^dofs\[0\] = 1.5 is invalid"):
        condensed_stiffness(model, [1.5])
