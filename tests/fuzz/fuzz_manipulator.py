"""Fuzz: the manipulator's kinematics (the model, forward and inverse kinematics, arcs and
tendons, workspaces, the protocol, the tendon drive)."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, fuzz, junk, mostly
from kresling import Design
from kresling.manipulator import (Manipulator, TendonDrive, arc_from_tendons,
                                  forward_kinematics, inverse_kinematics,
                                  protocol_tendon_lengths, pseudo_linkage, tendons_from_arc,
                                  workspace)

NAMES = ("modules", "design", "tendon_radius", "segments", "cells_per_module", "frame",
         "tendon_bounds", "configuration", "tendon_lengths", "lengths", "target", "k",
         "rest_length", "d", "N", "arcs", "grid_points", "configurations", "tolerance",
         "steps", "l1", "l2", "l3", "tendon")
designs = st.builds(Design, n=st.integers(3, 12), lam=st.floats(0.55, 0.95),
                    Lc=st.floats(1, 60), R=st.floats(5, 60))
models = st.fixed_dictionaries({}, optional={
    "modules": mostly(st.integers(1, 4), st.sampled_from([0, 2.5, 10**20]), junk),
    "design": mostly(designs, junk),
    "tendon_radius": mostly(st.floats(1, 60), edgy_floats, junk),
    "segments": mostly(st.integers(1, 4), st.sampled_from([0, 1.5]), junk),
    "frame": mostly(st.sampled_from(["twist_free", "thesis"]), junk),
    "tendon_bounds": mostly(st.none(), st.tuples(st.floats(0, 50), st.floats(0, 100)), junk)})
configurations = mostly(st.text(alphabet="01", min_size=1, max_size=4),
                        st.lists(st.integers(-1, 2), max_size=4), junk)
lengths = mostly(st.lists(st.lists(mostly(st.floats(10, 80), edgy_floats), min_size=3,
                                   max_size=3), min_size=1, max_size=4),
                 st.none(), junk)


@fuzz(150)
@given(models, configurations, lengths)
def test_forward_kinematics(kwargs, configuration, tendon_lengths):
    model = attempt(lambda: Manipulator(**kwargs), *NAMES)
    if model is None:
        return
    state = attempt(lambda: forward_kinematics(model, configuration, tendon_lengths), *NAMES)
    if state is not None:
        finite(state.markers, state.module_lengths)
    drive = TendonDrive()
    counts = attempt(lambda: drive.motor_counts(model, configuration, tendon_lengths), *NAMES)
    if counts is not None:
        finite(counts)


@fuzz(60)
@given(models, mostly(st.lists(mostly(st.floats(-300, 300), edgy_floats), min_size=3,
                               max_size=3), junk),
       mostly(st.none(), st.lists(st.text(alphabet="01", min_size=1, max_size=3), max_size=2),
              junk),
       mostly(st.sampled_from([1e-6, 1e-3]), edgy_floats, junk))
def test_inverse_kinematics(kwargs, target, configurations, tolerance):
    model = attempt(lambda: Manipulator(**kwargs), *NAMES)
    if model is None:
        return
    found = attempt(lambda: inverse_kinematics(model, target, configurations=configurations,
                                               tolerance=tolerance), *NAMES)
    if found is not None:
        finite(found.position, found.tendon_lengths, found.distance)


@fuzz(150)
@given(mostly(st.lists(st.lists(mostly(st.floats(0, 100), edgy_floats), min_size=3, max_size=3),
                       max_size=3), junk),
       mostly(st.floats(1, 60), edgy_floats, junk), mostly(st.integers(1, 4), edgy_floats, junk))
def test_arcs_and_tendons(rows, d, N):
    arcs = attempt(lambda: arc_from_tendons(rows, d, N), *NAMES)
    if arcs is not None:
        finite(arcs)
        back = attempt(lambda: tendons_from_arc(arcs, d, N), *NAMES)
        if back is not None:
            finite(back)


@fuzz(40)
@given(models, configurations, mostly(st.integers(2, 6), st.sampled_from([0, 1, 10**6, 2.5]),
                                      junk))
def test_workspace(kwargs, configuration, grid_points):
    model = attempt(lambda: Manipulator(**kwargs), *NAMES)
    if model is None:
        return
    ws = attempt(lambda: workspace(model, configuration, grid_points), *NAMES)
    if ws is not None:
        finite(ws.points)


@fuzz(100)
@given(mostly(st.floats(-20, 20), edgy_floats, junk), mostly(st.floats(1, 100), edgy_floats, junk),
       models, configurations,
       mostly(st.lists(st.integers(0, 10), max_size=4), st.lists(edgy_floats, max_size=2), junk))
def test_protocol(k, rest, kwargs, configuration, steps):
    values = attempt(lambda: protocol_tendon_lengths(k, rest), *NAMES)
    if values is not None:
        finite(values)
    model = attempt(lambda: Manipulator(**kwargs), *NAMES)
    if model is None:
        return
    run = attempt(lambda: pseudo_linkage(model, configuration, steps), *NAMES)
    if run is not None:
        finite(np.asarray(run.markers, dtype=float))
