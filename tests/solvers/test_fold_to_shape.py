"""Folding by gradient (kresling.solvers.fold_to_shape): rest angles found from a shape; and
the sensitivities of a fold's every step (kresling.solvers.fold_sensitivity).

The reference is a forward fold: a Miura-ori sheet (3 x 3 cells, one panel held) folded
with a different rest angle on every fold crease (not a rigid folding: its panels bend and
store energy), its nodes' final positions taken as the targets. From another start the
least squares must give the same rest angles back. Both folds converge Newton to 1e-10 mm,
so the targets are met to ~1e-10 mm and the rest angles are determined to ~1e-9 rad by
them (the Jacobian's smallest singular value is O(1) mm/rad here); 1e-6 rad is the bound
asked of an inverse fold and still catches a wrong Jacobian (which stalls far above it).
"""

import dataclasses

import numpy as np
import pytest

from kresling.io.miura import miura_sheet
from kresling.model import ManualProperties, build_pattern_model
from kresling.model.fold_angles import hinge_fold_signs, rest_angles_for
from kresling.solvers import Parameter, solve_fold, with_parameter
from kresling.solvers.fold_sensitivity import fold_sensitivity
from kresling.solvers.fold_to_shape import TOLERANCE, fold_to_shape

STIFF = ManualProperties(bar_modulus=1e5, bar_area=1.0, fold_stiffness=1.0, bend_stiffness=1.0)


@pytest.fixture(scope="module")
def sheet():
    flat = miura_sheet(3, 3, fold_angle=0.0)
    folded = miura_sheet(3, 3, fold_angle=40.0)
    pattern = dataclasses.replace(flat, edges_assignment=folded.edges_assignment)
    fixed = np.zeros((pattern.num_vertices + len(pattern.faces), 3), bool)
    fixed[list(pattern.faces[0][:3])] = True
    pm = build_pattern_model(pattern, material=STIFF, fixed=fixed)
    hinges = np.array([h for h, f in enumerate(pm.hinge_family) if f != "bend"])
    signs = hinge_fold_signs(pm)
    by_edge = {tuple(sorted(e)): a for e, a in zip(folded.edges.tolist(), folded.edges_fold_angle)}
    # Each crease its own angle: 25-45 deg of the Miura's folding sense.
    rng = np.random.default_rng(3)
    angles = np.array([by_edge[tuple(sorted(pm.model.hinges[h][:2].tolist()))] for h in hinges])
    angles = np.sign(angles) * rng.uniform(25.0, 45.0, hinges.size)
    return pm, hinges, rest_angles_for(angles, signs[hinges])


def test_a_forward_folds_shape_gives_its_rest_angles_back(sheet):
    pm, hinges, truth = sheet
    model = pm.model
    path = solve_fold(model, [(hinges, truth)], 10, tolerance=TOLERANCE, extrapolation=2,
                      shift=0.0)
    assert path.completed
    nodes = np.arange(model.num_nodes)
    target = model.nodes + path.displacement[-1].reshape(-1, 3)
    # The folded sheet stores energy: its creases are not at their rest angles.
    assert path.energy[-1] > 1e-4
    start = truth + np.where(np.arange(truth.size) % 2 == 0, 0.1, -0.08)
    found = fold_to_shape(model, hinges, nodes, target, initial=start)
    assert found.success, found.message
    np.testing.assert_allclose(found.rest_angles, truth, atol=1e-6)
    assert found.error.max() < 1e-8
    assert found.evaluations < 20


def test_a_few_nodes_pin_down_fewer_creases(sheet):
    # Six corner and edge nodes' targets, four creases sought: still determined.
    pm, hinges, truth = sheet
    model = pm.model
    chosen = hinges[:4]
    path = solve_fold(model, [(chosen, truth[:4])], 10, tolerance=TOLERANCE, extrapolation=2,
                      shift=0.0)
    nodes = np.array([2, 5, 8, 11, 14, 17])
    nodes = nodes[nodes < model.num_nodes]
    target = (model.nodes + path.displacement[-1].reshape(-1, 3))[nodes]
    found = fold_to_shape(model, chosen, nodes, target, initial=truth[:4] + 0.05)
    np.testing.assert_allclose(found.rest_angles, truth[:4], atol=1e-6)


@pytest.mark.parametrize("kwargs, message", [
    (dict(hinges=[10_000]), "hinges = \\[10000\\] is invalid"),
    (dict(nodes=[0, 0]), "nodes = \\[0, 0\\] is invalid: must be distinct"),
    (dict(targets=np.zeros((2, 3))), "targets must have shape \\(1, 3\\)"),
    (dict(initial=[1.0, 2.0]), "initial has 2 entries"),
])
def test_bad_requests_are_refused(sheet, kwargs, message):
    pm, hinges, truth = sheet
    args = dict(hinges=hinges[:1], nodes=[0], targets=np.zeros((1, 3)))
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        fold_to_shape(pm.model, args["hinges"], args["nodes"], args["targets"],
                      initial=args.get("initial"))


def _two_stage_fold(model, hinges, truth, stiffness=None, shift_target=None):
    """Stage 1 folds every crease to ``truth``; stage 2 moves the first three 0.1 rad on."""
    stage1 = truth.copy()
    if shift_target is not None:
        stage1[shift_target[0]] += shift_target[1]
    stages = [(hinges, stage1), (hinges[:3], truth[:3] + 0.1)]
    if stiffness is not None:
        model = with_parameter(model, "hinges.stiffness", stiffness)
    path = solve_fold(model, stages, 5, tolerance=TOLERANCE, extrapolation=2, shift=0.0)
    assert path.completed
    return stages, path


def test_fold_sensitivities_match_folds_again(sheet):
    # d(every step's displacements and reactions)/d(the creases' stiffness, every target)
    # against the fold run again with each moved by +-h: stiffness h = 1e-5 of it, targets
    # h = 1e-6 rad (Newton's 1e-10 mm over 2h: 5e-5 of the 1 mm/rad scale; truncation ~h^2).
    pm, hinges, truth = sheet
    model = pm.model
    stages, path = _two_stage_fold(model, hinges, truth)
    stiffness = np.asarray(model.hinge_stiffness, dtype=float)
    w = np.zeros_like(stiffness)
    w[hinges] = 1.0
    crease_stiffness = Parameter("hinges", "stiffness", direction=w, name="creases")
    sens = fold_sensitivity(model, stages, path, [crease_stiffness], targets=True)
    assert sens.parameters[0] == "creases" and sens.parameters[1] == "stage 0 target[0]"
    assert sens.displacement.shape == (path.num_steps, model.num_dofs, 1 + hinges.size + 3)
    h = 1e-5 * stiffness[hinges].mean()
    plus = _two_stage_fold(model, hinges, truth, stiffness + h * w)[1]
    minus = _two_stage_fold(model, hinges, truth, stiffness - h * w)[1]
    fd = (plus.displacement - minus.displacement) / (2 * h)
    scale = np.abs(fd).max()
    assert scale > 1e-3
    assert np.abs(sens.displacement[:, :, 0] - fd).max() < 1e-4 * scale
    for j, (s, i) in enumerate([(0, 0), (0, 4), (1, 1)]):
        column = sens.parameters.index(f"stage {s} target[{i}]")
        h = 1e-6
        if s == 0:
            a = _two_stage_fold(model, hinges, truth, shift_target=(i, h))[1]
            b = _two_stage_fold(model, hinges, truth, shift_target=(i, -h))[1]
        else:
            def moved(dh):
                st = [(hinges, truth), (hinges[:3], truth[:3] + 0.1 + dh * (np.arange(3) == i))]
                return solve_fold(model, st, 5, tolerance=TOLERANCE, extrapolation=2, shift=0.0)
            a, b = moved(h), moved(-h)
        fd = (a.displacement - b.displacement) / (2 * h)
        np.testing.assert_allclose(sens.displacement[:, :, column], fd,
                                   atol=1e-4 * max(np.abs(fd).max(), 1e-3))
