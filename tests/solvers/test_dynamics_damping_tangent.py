"""Rayleigh damping with the tangent of each step's start (``damping_tangent = "current"``)
against the start's tangent: the same motion on a linear model, a different one on a
nonlinear model whose energies still balance."""

import copy

import numpy as np
import pytest

from kresling.model import Model
from kresling.simulate import simulate
from kresling.solvers import solve_dynamics
from small_models import CREASED_SQUARE, chain


def test_a_linear_model_moves_the_same_with_either_tangent():
    # Three nodes on zero-length springs of different stiffness per axis: a linear model,
    # its tangent the same at every state.
    nodes = np.array([[0.0, 0.0, 0.0], [5.0, 0.0, 0.0], [0.0, 5.0, 0.0]])
    model = Model(nodes, np.zeros((0, 2), dtype=int), np.zeros((0, 4), dtype=int),
                  bar_modulus=[], bar_area=[], hinge_stiffness=[])
    model = model.with_families({"springs": {
        "nodes": np.arange(3), "stiffness": np.arange(1.0, 10.0).reshape(3, 3),
        "anchor": nodes}})
    runs = [solve_dynamics(model, np.full(3, 1e-6), 2e-5, 4e-3,
                           initial=np.linspace(0.1, 0.9, 9), mass_damping=30.0,
                           stiffness_damping=2e-5, damping_tangent=tangent, tolerance=1e-13)
            for tangent in ("initial", "current")]
    # Only round-off could tell the two apart (Newton stops at 1e-13 mm on 0.9 mm).
    np.testing.assert_allclose(runs[1].path.displacement, runs[0].path.displacement,
                               rtol=0, atol=1e-12)
    np.testing.assert_allclose(runs[1].dissipated, runs[0].dissipated, rtol=1e-10)
    assert runs[0].dissipated[-1] > 0.3 * runs[0].strain[0]   # damped: it matters


def swing(tangent):
    """CREASED_SQUARE's corner pushed through a large turn (to ~70 deg) and let go: the
    tangent changes with the turn."""
    p = copy.deepcopy(CREASED_SQUARE)
    p["load"] = [{"node": 3, "force": [0.0, 0.0, 0.3], "time": [[0.0, 1.0], [0.02, 1.0],
                                                              [0.0201, 0.0]]}]
    p["dynamics"] = {"scheme": "newmark", "time_step": 1e-4, "duration": 0.08,
                     "damping": {"beta": 2e-3}, "damping_tangent": tangent}
    p["analysis"] = {"method": "dynamic", "tolerance": 1e-11}
    run = simulate(p)
    assert run.completed
    return run


def test_a_nonlinear_model_is_damped_by_its_current_tangent_and_its_energies_balance():
    initial, current = swing("initial"), swing("current")
    u0, u1 = initial.path.displacement, current.path.displacement
    assert np.abs(u1 - u0).max() > 1e-3 * np.abs(u0).max()   # the tangent moved
    turn = np.degrees(np.arctan2(u1[:, 11], 14.14)).max()
    assert turn > 30.0
    for run in (initial, current):
        h = run.history
        # The dissipated energy never falls (the tangent here stays positive definite:
        # each step's (v_n + v_{n+1})^T C_n (v_n + v_{n+1}) dt / 4 >= 0), to round-off.
        assert h.dissipated.min() >= 0.0
        assert np.diff(h.dissipated).min() > -1e-12 * h.dissipated[-1]
        # Kinetic + strain + dissipated = work, to the average acceleration scheme's
        # error on a nonlinear model, O((w dt)^2) of the energies with w dt ~ 0.01 here.
        balance = h.kinetic + h.strain + h.dissipated - h.work
        assert np.abs(balance).max() < 1e-3 * h.work.max()
    # Newton converges as fast with the current tangent's damping (it is in the step's
    # tangent): no more iterations per step than with the start's, on average.
    iterations = [run.path.newton_iterations / run.path.num_steps for run in (initial,
                                                                              current)]
    assert iterations[1] <= iterations[0] + 0.25
    # From the step's predictor (off by O(dt^3)) to 1e-11 mm in at most 4 iterations:
    # quadratic convergence (a tangent missing the damping's share, 20 times the
    # stiffness here, would contract by ~0.95 per iteration).
    assert max(current.history_columns()["iterations"]) <= 4


@pytest.mark.parametrize("dynamics, message", [
    ({"damping_tangent": "later"}, r"damping_tangent' = 'later' is invalid: must be one of"),
    ({"damping_tangent": "current"}, r"damping_tangent' = 'current' needs damping"),
    ({"damping_tangent": "current", "damping": {"beta": 1e-3}, "scheme": "explicit",
      "time_step": 1e-6}, r"damping_tangent' = 'current' applies only with scheme"),
])
def test_bad_damping_tangents_are_refused(dynamics, message):
    p = copy.deepcopy(CREASED_SQUARE)
    p["dynamics"] = {"scheme": "newmark", "time_step": 1e-4, "duration": 1e-3, **dynamics}
    p["analysis"] = {"method": "dynamic"}
    with pytest.raises(ValueError, match=message):
        simulate(p)
    model, masses = chain(2)
    with pytest.raises(ValueError, match="damping_tangent = 'x' is invalid"):
        solve_dynamics(model, masses, 1e-4, 1e-3, damping_tangent="x")
