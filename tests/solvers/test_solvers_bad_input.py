"""Bad input to the solvers: a ValueError naming the parameter, the value and what is allowed
(the command line: one line on stderr, exit 2), never another exception, a hang or a
silent NaN. Reproducers of defects a fuzzing audit found; each must stay fixed (the C++
side of several is in cpp/tests/test_hardening.cpp)."""

import _thread
import math
import signal
import threading
import time

import numpy as np
import pytest

from bad_input_helpers import driven_cell
from kresling import Design, _core
from kresling.model.kresling_specimen import kresling_specimen
from kresling.solvers import (solve_displacement_control,
                              solve_force_control, solve_mgdcm)


# 10. Long C++ runs ignored Ctrl-C and had no bound.
@pytest.fixture
def sigint_raises():
    """Ctrl-C as an interactive Python has it (KeyboardInterrupt), whatever the test run
    inherited: a background job (``make test &``, ``nohup``) starts with SIGINT ignored, and
    then neither Python's handler nor ``_thread.interrupt_main`` is there to test."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


# 2. max_bisections >= 31 was undefined behaviour (1 << 31 and beyond).
@pytest.mark.parametrize("bisections", [31, 32, 47, -1])
def test_bisections_beyond_30_are_refused(bisections):
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=rf"max_bisections = {bisections} is invalid: must be an "
                                         r"integer"):
        solve_displacement_control(model, prescribed, 2, max_bisections=bisections)


def test_thirty_bisections_run():
    model, prescribed = driven_cell()
    assert solve_displacement_control(model, prescribed, 2, max_bisections=30).completed


# 3. shift unchecked: 1e9, inf or -1e9 "converged" in one iteration with a wrong answer.
@pytest.mark.parametrize("shift", [1e9, math.inf, -1e9, math.nan, None, "1e-8"])
@pytest.mark.parametrize("solver", ["displacement", "force", "mgdcm"])
def test_shift_out_of_range_is_refused(shift, solver):
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^shift = .* is invalid: must be"):
        if solver == "displacement":
            solve_displacement_control(model, prescribed, 2, shift=shift)
        elif solver == "force":
            solve_force_control(model, -0.01 * np.sign(prescribed), 2, shift=shift)
        else:
            solve_mgdcm(model, -0.01 * np.sign(prescribed), max_increments=2, shift=shift)


def test_largest_shift_gives_the_same_path():
    model, prescribed = driven_cell()
    reference = solve_displacement_control(model, prescribed, 4)
    shifted = solve_displacement_control(model, prescribed, 4, shift=_core.solvers.MAX_SHIFT)
    assert shifted.completed
    np.testing.assert_allclose(shifted.constraint_force, reference.constraint_force,
                               rtol=1e-6, atol=1e-8)


def test_a_path_driven_flat_stops_before_the_flat_state():
    # The enhanced linear law is infinite at a hinge folded flat: the path keeps only finite
    # steps and says why it stopped (it ended "completed" on a -3.9e14 N force).
    design = Design(4, 0.6, 0.0)
    specimen = kresling_specimen(design, [1])
    fixed = np.zeros((specimen.model.num_nodes, 3), dtype=bool)
    fixed[specimen.level_nodes(0)] = True
    prescribed = np.zeros(fixed.shape)
    prescribed[specimen.level_nodes(1), 2] = -design.Le
    path = solve_displacement_control(specimen.model.replace(fixed=fixed), prescribed, 100,
                                      extrapolation=2)
    assert not path.completed and "not finite" in path.message
    assert np.isfinite(path.constraint_force).all()
    assert np.abs(path.constraint_force).max() < 1e6


def test_a_long_solve_stops_on_ctrl_c(sigint_raises):
    model, prescribed = driven_cell(n=40)  # 100000 increments: about 10 s or more of C++
    timer = threading.Timer(0.5, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            solve_displacement_control(model, prescribed, 100_000)
    finally:
        timer.cancel()
    assert time.perf_counter() - start < 5.0


def test_step_counts_are_bounded():
    model, prescribed = driven_cell()
    with pytest.raises(ValueError, match=r"^steps = 1000000000 is invalid: must be an integer "
                                         r"in \[1, 100000\]"):
        solve_displacement_control(model, prescribed, 10**9)
    with pytest.raises(ValueError, match=r"^max_increments = 1000000000 is invalid"):
        solve_mgdcm(model, -0.01 * np.sign(prescribed), max_increments=10**9)


@pytest.mark.parametrize("solver", ["displacement", "displacement_merlin2", "force", "mgdcm"])
def test_a_huge_initial_state_never_completes_with_nan(solver):
    model, prescribed = driven_cell()
    initial = np.zeros(model.num_dofs)
    initial[-1] = 1e300
    forces = -0.01 * np.sign(prescribed)
    if solver.startswith("displacement"):
        r = solve_displacement_control(model, prescribed, 2, initial=initial,
                                       merlin2_steps=solver.endswith("merlin2"))
    elif solver == "force":
        r = solve_force_control(model, forces, 2, initial=initial)
    else:
        r = solve_mgdcm(model, forces, max_increments=3, initial=initial)
    assert np.isfinite(r.constraint_force).all() and np.isfinite(r.energy).all()
    assert r.completed or r.message
