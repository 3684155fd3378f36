"""Folding by gradient (kresling.solvers.fold_to_shape): rest angles found from a shape.

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
from kresling.solvers import solve_fold
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
