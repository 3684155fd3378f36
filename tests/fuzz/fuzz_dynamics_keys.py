"""Fuzz: a motion in time whose creases are driven (``[[actuation]]`` with a step, ramp,
table, harmonic or chirp ``time``) and damped with the start's or the current tangent
(``[dynamics] damping_tangent``), from problem dicts and through ``solve_dynamics``. Bad input
is a ValueError naming the key; a run returns finite histories or says why it stopped."""

import copy

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, fuzz, junk, mostly, path_ok
from kresling.simulate import build_problem_model, simulate
from kresling.solvers import solve_dynamics

# Two triangles on the crease 0-2, the first held, a gram at the free corner.
BASE = {
    "pattern": {"vertices": [[0.0, 0.0, 0.0], [20.0, 0.0, 0.0], [20.0, 20.0, 0.0],
                             [0.0, 20.0, 0.0]], "panels": [[0, 1, 2], [0, 2, 3]]},
    "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                 "fold_stiffness": 0.05},
    "support": [{"nodes": [0, 1, 2], "fix": "xyz"}],
    "mass": [{"node": 3, "mass": 1e-6}],
    "analysis": {"method": "dynamic"}}
NAMES = ("actuation", "time", "ramp_time", "fold_angle_deg", "damping_tangent", "damping",
         "dynamics", "stage", "edges", "family", "scheme", "time_step", "duration", "beta",
         "hht_alpha", "delta", "hinges")

numbers = mostly(st.floats(-200.0, 200.0), edgy_floats, junk)
frequencies = mostly(st.floats(0.5, 200.0), edgy_floats, junk)
times = st.one_of(
    st.sampled_from(["step", "ramp", "sine", None]),
    st.lists(st.lists(numbers, min_size=2, max_size=2), min_size=0, max_size=3),
    st.builds(lambda a, f: {"harmonic": [a, f]}, numbers, frequencies),
    st.builds(lambda a, f0, f1, t: {"chirp": [a, f0, f1, t]}, numbers, frequencies,
              frequencies, mostly(st.floats(1e-3, 0.05), edgy_floats, junk)),
    st.builds(lambda k, v: {k: v}, st.sampled_from(["chirp", "harmonic", "ramp"]),
              st.lists(numbers, max_size=5)),
    junk)


@fuzz(25)
@given(times, mostly(st.floats(1e-3, 0.05), edgy_floats, junk),
       st.one_of(st.none(), numbers, st.just("file")), mostly(st.just(1), junk),
       mostly(st.sampled_from(["initial", "current"]), junk),
       mostly(st.floats(0.0, 1e-3), edgy_floats, junk),
       mostly(st.sampled_from(["newmark", "hht", "explicit"]), junk),
       st.sampled_from(["edges", "family", "stage"]))
def test_driven_creases_in_a_problem(time, ramp_time, angle, stage, tangent, beta, scheme,
                                     where):
    entry = {"edges": [[0, 2]]} if where != "family" else {"family": "fold"}
    for key, value in (("time", time), ("fold_angle_deg", angle), ("stage", stage)):
        if value is not None:
            entry[key] = value
    if time == "ramp":
        entry["ramp_time"] = ramp_time
    dynamics = {"scheme": scheme, "time_step": 1e-3, "duration": 5e-3,
                "damping": {"alpha": 1.0, "beta": beta}, "damping_tangent": tangent}
    problem = copy.deepcopy(BASE)
    if where == "stage":   # after a fold, from the rest angles it left
        problem.pop("analysis")
        problem["stage"] = [{"method": "fold", "steps": 2,
                             "actuation": [{"edges": [[0, 2]], "fold_angle_deg": 30.0}]},
                            {"method": "dynamic", "dynamics": dynamics, "actuation": [entry]}]
    else:
        problem.update(actuation=[entry], dynamics=dynamics)
    run = attempt(lambda: simulate(problem), *NAMES)
    if run is None:
        return
    for _, stage_run in getattr(run, "runs", [("", run)]):
        if hasattr(stage_run, "history"):
            h = stage_run.history
            path_ok(stage_run.path)
            finite(h.kinetic, h.strain, h.dissipated, h.work, h.actuation_work)
            finite(list(stage_run.history_columns().get("actuation_0_factor", [])))
            finite(stage_run.model_at(-1).hinge_rest_angle)
    assert run.completed or run.message


MODEL = build_problem_model({**BASE, "dynamics": {"time_step": 1e-3, "duration": 1e-3}}).model


@fuzz(20)
@given(st.one_of(st.lists(st.integers(-2, 3), max_size=3), junk),
       st.one_of(st.lists(numbers, max_size=3), junk), times,
       mostly(st.sampled_from(["initial", "current"]), junk),
       mostly(st.sampled_from(["newmark", "hht", "explicit"]), junk))
def test_solve_dynamics_with_actuation(hinges, delta, time, tangent, scheme):
    if time in ("step", "ramp", "sine"):
        time = None
    run = attempt(lambda: solve_dynamics(
        MODEL, np.full(MODEL.num_nodes, 1e-6), 1e-3, 4e-3,
        actuation=[(np.asarray(hinges) if isinstance(hinges, list) else hinges, delta, time)],
        stiffness_damping=1e-4, damping_tangent=tangent, scheme=scheme), *NAMES)
    if run is not None:
        path_ok(run.path)
        finite(run.kinetic, run.strain, run.dissipated, run.actuation_work)
