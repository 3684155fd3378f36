"""Fuzz: the path solvers (displacement control, force control, MGDCM, folding, time
integration) and the linearised stiffness, on a small cell with random options, loads and
starting states."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, edgy_ints, finite, fuzz, junk, path_ok
from kresling import Design
from kresling.model.kresling_specimen import kresling_specimen
from kresling.solvers import (condensed_stiffness, solve_displacement_control, solve_dynamics,
                              solve_fold, solve_force_control, solve_mgdcm, stable_time_step)

_specimen = kresling_specimen(Design(4, 0.7, 30), [1])
_fixed = np.zeros((_specimen.model.num_nodes, 3), dtype=bool)
_fixed[_specimen.level_nodes(0)] = True
MODEL = _specimen.model.replace(fixed=_fixed)
TOP = _specimen.level_nodes(1)

OPTIONS = ("tolerance", "max_iterations", "reject_iterations", "max_bisections", "shift",
           "extrapolation", "merlin2_steps", "stop", "initial", "steps", "prescribed", "forces",
           "initial_load_factor", "max_increments", "max_load_factor", "monitor_dof",
           "max_displacement", "max_step_factor", "supports", "DOF")

small_ints = st.one_of(st.integers(-2, 60), st.sampled_from([2**31, 10**20, 2.5, True, None]))
options = st.fixed_dictionaries({}, optional={
    "tolerance": st.one_of(edgy_floats, st.sampled_from([1e-6, 1e-3]), junk),
    "max_iterations": small_ints, "max_bisections": small_ints,
    "shift": st.one_of(st.sampled_from([0.0, 1e-8, 1e-3, 2e-3]), edgy_floats, junk),
})


def load(scale, pattern):
    """A load or motion on the top polygon's DOFs."""
    values = np.zeros((MODEL.num_nodes, 3))
    values[TOP] = np.asarray(pattern, dtype=float) * scale
    return values


vector = st.lists(st.floats(-1, 1), min_size=3, max_size=3)
initial = st.one_of(st.none(), st.sampled_from([0.0, 1e-3, 1.0, 1e3, 1e300]).map(
    lambda s: np.full(MODEL.num_dofs, s)), junk)


@fuzz(60)
@given(st.one_of(st.floats(-40, 40), edgy_floats), vector,
       st.one_of(st.integers(1, 12), edgy_ints, junk), options,
       st.fixed_dictionaries({}, optional={
           "reject_iterations": small_ints, "extrapolation": st.one_of(st.integers(-1, 3), junk),
           "merlin2_steps": st.one_of(st.booleans(), junk)}), initial)
def test_displacement_control(scale, pattern, steps, opts, more, start):
    path = attempt(lambda: solve_displacement_control(MODEL, load(scale, pattern), steps,
                                                      initial=start, **opts, **more), *OPTIONS)
    if path is not None:
        path_ok(path)


@fuzz(60)
@given(st.one_of(st.floats(-5, 5), edgy_floats), vector,
       st.one_of(st.integers(1, 8), edgy_ints, junk), options, initial)
def test_force_control(scale, pattern, steps, opts, start):
    path = attempt(lambda: solve_force_control(MODEL, load(scale, pattern), steps, initial=start,
                                               **opts), *OPTIONS)
    if path is not None:
        path_ok(path)


@fuzz(60)
@given(st.one_of(st.floats(-5, 5), edgy_floats), vector, options,
       st.fixed_dictionaries({}, optional={
           "initial_load_factor": st.one_of(st.floats(-0.1, 0.1), edgy_floats, junk),
           "max_increments": st.one_of(st.integers(1, 20), edgy_ints, junk),
           "max_load_factor": st.one_of(st.floats(0, 10), edgy_floats, junk),
           "monitor_dof": st.one_of(st.integers(-2, 40), junk),
           "max_displacement": st.one_of(st.floats(0, 10), edgy_floats, junk),
           "max_step_factor": st.one_of(st.floats(0, 1), edgy_floats, junk)}), initial)
def test_mgdcm(scale, pattern, opts, more, start):
    opts.pop("max_bisections", None)  # not an MGDCM option
    path = attempt(lambda: solve_mgdcm(MODEL, load(scale, pattern), initial=start, **opts, **more),
                   *OPTIONS)
    if path is not None:
        path_ok(path)


@fuzz(100)
@given(st.one_of(st.lists(st.one_of(st.integers(-2, 40), junk), max_size=4), junk),
       st.one_of(st.none(), st.sampled_from([0.0, 1.0, 1e300, float("nan")]).map(
           lambda s: np.full(MODEL.num_dofs, s)), junk))
def test_condensed_stiffness(dofs, u):
    S = attempt(lambda: condensed_stiffness(MODEL, dofs, u), "dofs", "u", "DOF", "mechanism",
                "condensed_stiffness")
    if S is not None:
        finite(S)


DYNAMICS = ("masses", "time_step", "duration", "forces", "gravity", "load_table", "hht_alpha",
            "mass_damping", "stiffness_damping", "tolerance", "max_iterations", "max_halvings",
            "initial", "initial_velocity", "free DOF", "steps", "scheme", "loads", "harmonic",
            "record_every", "time")


@fuzz(40)
@given(st.one_of(st.sampled_from([1e-6, 1e-3]), edgy_floats, junk),
       st.one_of(st.sampled_from([1e-4, 1e-3]), edgy_floats, junk),
       st.one_of(st.sampled_from([5e-3, 2e-2]), edgy_floats, junk), vector,
       st.fixed_dictionaries({}, optional={
           "hht_alpha": st.one_of(st.sampled_from([0.0, -0.1, -1 / 3, -0.5, 0.1]), junk),
           "mass_damping": st.one_of(st.sampled_from([0.0, 10.0, -1.0]), edgy_floats),
           "stiffness_damping": st.one_of(st.sampled_from([0.0, 1e-4]), edgy_floats),
           "gravity": st.one_of(st.sampled_from([(0, 0, -9810.0), (0, 0), (1e300, 0, 0)]), junk),
           "load_table": st.one_of(st.sampled_from([[[0, 0], [1e-2, 1]], [[1, 0], [0, 1]],
                                                    [[0, float("nan")]]]), junk),
           "max_halvings": small_ints, "tolerance": st.one_of(edgy_floats, junk),
           "scheme": st.one_of(st.sampled_from(["newmark", "hht", "explicit", "rk4"]), junk),
           "record_every": st.one_of(st.sampled_from([1, 7, 0, 10**12]), junk),
           "loads": st.one_of(st.lists(st.tuples(
               st.sampled_from([np.ones(MODEL.num_dofs), np.zeros(3), [np.nan] * 3]),
               st.one_of(st.none(), st.sampled_from([
                   [[0, 0], [1e-2, 1]], {"harmonic": (1.0, 50.0)}, {"harmonic": (1.0, -1.0)},
                   {"harmonic": (np.inf, 1.0)}, {"sine": 1}, [[0.0]]]), junk)), max_size=2),
               junk)}), initial)
def test_dynamics(mass, dt, duration, pattern, opts, start):
    history = attempt(lambda: solve_dynamics(MODEL, mass, dt, duration, forces=load(1.0, pattern),
                                             initial=start, **opts), *DYNAMICS)
    if history is not None:
        path_ok(history.path)
        finite(history.velocity, history.kinetic, history.strain, history.dissipated,
               history.work)
        if history.scheme == "explicit":   # never above its stable step, which it reports
            assert 0 < history.time_step <= history.stable_time_step


@fuzz(30)
@given(st.one_of(st.sampled_from([1e-6, 1e-3, 0.0, -1.0]), edgy_floats, junk), initial,
       st.one_of(st.sampled_from([0.0, 10.0, -1.0]), edgy_floats, junk),
       st.one_of(st.sampled_from([0.0, 1e-4]), edgy_floats, junk))
def test_stable_time_step(mass, state, alpha, beta):
    stable = attempt(lambda: stable_time_step(MODEL, np.full(MODEL.num_nodes, mass) if
                                              isinstance(mass, float) else mass, state,
                                              mass_damping=alpha, stiffness_damping=beta),
                     "masses", "u", "mass_damping", "stiffness_damping")
    if stable is not None:
        assert stable.time_step > 0 and not np.isnan(stable.time_step)
        assert stable.omega_bound >= stable.omega_max * (1 - 1e-12) or \
            not np.isfinite(stable.omega_bound)


FOLD = ("stages", "steps", "forces", "tolerance", "max_iterations", "max_bisections",
        "extrapolation", "shift", "hinge", "target", "initial")


@fuzz(40)
@given(st.lists(st.tuples(st.lists(st.integers(-2, 40), max_size=4),
                          st.lists(st.one_of(st.floats(-1, 7), edgy_floats), max_size=4)),
                max_size=3),
       st.one_of(st.integers(1, 6), edgy_ints, junk), options, initial)
def test_fold(stages, steps, opts, start):
    path = attempt(lambda: solve_fold(MODEL, stages, steps, initial=start, **opts), *FOLD)
    if path is not None:
        path_ok(path)
