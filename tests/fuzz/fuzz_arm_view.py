"""Fuzz: the manipulator as a structure (kresling.arm: building the arm, tip loads, pulls
until a module snaps) and the interactive views (kresling.view: models, paths, FOLD
patterns, written pages)."""

import tempfile
from pathlib import Path

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, fuzz, junk, mostly
from kresling import Design
from kresling.arm import build_arm, pull_until_snap, tip_load
from kresling.arm.creases import crease_switch
from kresling.model.kresling_specimen import kresling_specimen
from kresling.solvers import solve_displacement_control
from kresling.view import view_model, view_path, write_html

ARM = ("configuration", "n", "lam", "Lc", "R", "design", "parameters", "load", "pulls",
       "pretension", "direction", "max_pull", "steps", "tolerance", "max_bisections", "arm",
       "pull", "tendon", "module", "group", "to", "let_out", "start", "scan_step_deg",
       "max_change_deg", "resolution_deg", "overshoot_deg")
configurations = mostly(st.sampled_from(["111", "101", "000", "1", "11", "0"]),
                        st.text(alphabet="012 ", max_size=4), junk)
vectors = mostly(st.lists(st.floats(-3, 3), min_size=3, max_size=3),
                 st.lists(edgy_floats, min_size=0, max_size=4), junk)


@fuzz(20)
@given(configurations, mostly(st.integers(3, 12), junk), mostly(st.floats(0.6, 0.95), junk),
       mostly(st.floats(5, 40), edgy_floats, junk), vectors,
       mostly(st.none(), st.lists(st.floats(0, 5), min_size=3, max_size=3), junk),
       mostly(st.floats(0, 3), edgy_floats, junk))
def test_arm_tip_load(configuration, n, lam, Lc, load, pulls, pretension):
    arm = attempt(lambda: build_arm(configuration, n=n, lam=lam, Lc=Lc), *ARM)
    if arm is None:
        return
    result = attempt(lambda: tip_load(arm, load, pulls=pulls, pretension=pretension), *ARM)
    if result is not None:
        finite(result.tip_displacement)
        assert result.completed or result.state is not None


@fuzz(20)
@given(configurations, vectors, mostly(st.none(), st.floats(0.1, 10), edgy_floats, junk))
def test_arm_pull_until_snap(configuration, direction, max_pull):
    arm = attempt(lambda: build_arm(configuration), *ARM)
    if arm is None:
        return
    result = attempt(lambda: pull_until_snap(arm, direction, max_pull=max_pull), *ARM)
    if result is not None:
        finite(result.pulls)


@fuzz(3)
@given(mostly(st.lists(st.floats(-80, 80), min_size=2, max_size=2).map(
           lambda xy: [*xy, 0.0]), junk),
       mostly(st.floats(150, 340), edgy_floats, junk),
       mostly(st.sampled_from([["111"], ["101"], ["1"], ["12"]]), junk),
       mostly(st.sampled_from(["travel", "stiffness"]), junk),
       mostly(st.floats(1e-4, 1.0), edgy_floats, junk))
def test_arm_reach(target_xy, z, configurations, prefer, tolerance):
    # Reaching a point: a result with a finite tip and pulls >= 0 (the meaning of --pulls),
    # or a ValueError naming what is wrong; never a traceback or a hang.
    from kresling.arm.reach import reach

    target = target_xy if not isinstance(target_xy, list) else [target_xy[0], target_xy[1], z]
    result = attempt(lambda: reach(target, configurations=configurations, prefer=prefer,
                                   tolerance=tolerance),
                     *ARM, "target", "configurations", "prefer", "tolerance", "modules")
    if result is not None:
        finite(result.tip_position, result.tendon_displacements, result.error)
        assert (result.tendon_displacements >= 0).all()
        assert result.reached == (result.error <= tolerance)


_ONE_MODULE = {c: build_arm(c) for c in ("1", "0")}


@fuzz(10)
@given(st.sampled_from(["1", "0"]), mostly(st.integers(0, 1), junk),
       mostly(st.sampled_from(["fold", "valley", "mountain", "polygon"]), junk),
       mostly(st.none(), st.sampled_from(["extended", "contracted"]), junk),
       mostly(st.none(), st.floats(0, 200), edgy_floats, junk),
       mostly(st.floats(2, 20), edgy_floats, junk), mostly(st.floats(0.5, 5), edgy_floats, junk))
def test_arm_crease_switch(configuration, module, group, to, let_out, max_change, step):
    arm = _ONE_MODULE[configuration]
    result = attempt(lambda: crease_switch(arm, module, group=group, to=to, let_out=let_out,
                                           max_change_deg=max_change, scan_step_deg=step,
                                           compare_tendons=False), *ARM)
    if result is not None:
        assert result.message
        if result.after is not None:
            finite(result.after.cell_height, result.tip_displacement)


_specimen = kresling_specimen(Design(4, 0.7, 30), [1])
MODEL = _specimen.model


@fuzz(30)
@given(mostly(st.none(), st.sampled_from([0.0, 1.0, 1e300]).map(
    lambda s: np.full(MODEL.num_dofs, s)), junk),
       mostly(st.none(), st.sampled_from(["energy", "strain", "nope"]), junk),
       mostly(st.none(), st.text(max_size=8), junk))
def test_view_model(u, field, title):
    figure = attempt(lambda: view_model(MODEL, u, field=field, title=title),
                     "u", "field", "title", "model")
    if figure is not None:
        with tempfile.TemporaryDirectory() as directory:
            write_html(figure, Path(directory) / "view.html")


_fixed = np.zeros((MODEL.num_nodes, 3), dtype=bool)
_fixed[_specimen.level_nodes(0)] = True
_drive = np.zeros((MODEL.num_nodes, 3))
_drive[_specimen.level_nodes(1), 2] = -5.0
PATH = solve_displacement_control(MODEL.replace(fixed=_fixed), _drive, 6)


@fuzz(20)
@given(mostly(st.none(), st.integers(1, 4), st.sampled_from([0, -1, 2.5, 10**20]), junk),
       mostly(st.integers(1, 300), st.sampled_from([0, -1, 10**20]), junk),
       mostly(st.none(), st.integers(0, 10), st.sampled_from([-1, 10**6]), junk))
def test_view_path(stride, max_frames, initial):
    figure = attempt(lambda: view_path(MODEL, PATH, frame_stride=stride, max_frames=max_frames),
                     "frame_stride", "max_frames", "path")
    if figure is not None:
        with tempfile.TemporaryDirectory() as directory:
            attempt(lambda: write_html(figure, Path(directory) / "path.html",
                                       initial_frame=initial), "initial_frame")
