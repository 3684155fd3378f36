"""Folding by crease actuation: rest angles driven to targets (kresling.solvers.fold).

Independent references: the face normals' fold angle (kresling.io.fold_format.fold_angles,
computed from the geometry alone), the rigid-folding closure of a degree-4 vertex (the
product of the rotations about its creases is the identity), and a Miura-ori sheet's
rigidly folded geometry in closed form (kresling.io.miura)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from kresling.io import pattern_from_arrays, read_pattern
from kresling.io.fold_format import fold_angles
from kresling.io.miura import miura_sheet
from kresling.model import CreaseLaws, HingeLaw, ManualProperties, build_pattern_model
from kresling.model.fold_angles import fold_angles_deg, hinge_fold_signs, rest_angles_for
from kresling.solvers import fold, solve_fold

STIFF = ManualProperties(bar_modulus=1e5, bar_area=1.0, fold_stiffness=1.0, bend_stiffness=1.0)


#: A fold law linear from 5 to 355 deg, so that targets up to 175 deg of fold are in range.
WIDE = CreaseLaws(fold=HingeLaw(limits_deg=(5.0, 355.0)))


def _two_panels(laws=WIDE):
    # Two triangles on the crease 0-1, counter-clockwise about +z; the panel (0, 3, 1) is
    # held, the wing node 2 is free.
    vertices = [[0, 0, 0], [10, 0, 0], [5, 8, 0], [5, -8, 0]]
    pattern = pattern_from_arrays(vertices, [[0, 1, 2], [0, 3, 1]])
    fixed = np.zeros((4, 3), bool)
    fixed[[0, 1, 3]] = True
    return pattern, build_pattern_model(pattern, material=STIFF, fixed=fixed, laws=laws)


@pytest.mark.parametrize("target", [90.0, -90.0, 150.0, -30.0])
def test_one_crease_folds_to_its_target_the_way_fold_says(target):
    pattern, pm = _two_panels()
    hinge = next(h for h, f in enumerate(pm.hinge_family) if f != "bend")
    result = fold(pm, {hinge: target}, 20)
    assert result.completed, result.path.message
    # The free panel carries no load: it turns until the crease sits at its rest angle.
    assert result.fold_angle_deg[-1, hinge] == pytest.approx(target, abs=1e-6)
    x = pm.model.nodes + result.path.displacement[-1].reshape(-1, 3)
    # The geometry's own fold angle (from the faces' normals) agrees, sign included: a
    # valley lifts the wing to the faces' +z side.
    measured = np.degrees(fold_angles(pattern.faces, [[0, 1]], x))[0]
    assert measured == pytest.approx(target, abs=1e-6)
    assert np.sign(x[2, 2]) == np.sign(target)
    # Increments move the rest angle linearly: the fold angle follows them.
    fractions = result.path.load_factor
    np.testing.assert_allclose(result.fold_angle_deg[:, hinge], fractions * target, atol=1e-6)


def test_a_target_beyond_the_laws_limit_stops_short_of_it():
    # MERLIN2's default fold law is linear between 45 and 315 deg and stiffens beyond: a
    # rest angle of 30 deg (a 150 deg fold) leaves the crease where the law's moment
    # vanishes, short of the target.
    _, pm = _two_panels(laws=CreaseLaws())
    hinge = next(h for h, f in enumerate(pm.hinge_family) if f != "bend")
    result = fold(pm, {hinge: 150.0}, 20)
    assert result.completed
    assert 135.0 < result.fold_angle_deg[-1, hinge] < 149.0


def test_folding_and_unfolding_returns_to_flat():
    _, pm = _two_panels()
    hinge = next(h for h, f in enumerate(pm.hinge_family) if f != "bend")
    rest = pm.model.hinge_rest_angle[hinge]
    path = solve_fold(pm.model, [([hinge], [rest - 2.0]), ([hinge], [rest])], 10)
    assert path.completed, path.message
    assert path.load_factor[-1] == pytest.approx(2.0)
    # Back at the flat state to Newton's tolerance (1e-6 mm on the correction).
    assert np.abs(path.displacement[-1]).max() < 1e-6
    assert np.abs(path.displacement[len(path.load_factor) // 2 - 1]).max() > 1.0


def test_a_miura_sheet_folded_and_unfolded_returns_to_flat():
    # Every crease of the sheet to its rigidly folded angle (40 deg) in one stage and back
    # to its flat rest angle in a second: the sheet is flat again to Newton's tolerance
    # (1e-6 mm on the correction; measured 1.2e-7 mm), having moved by 8.5 mm between.
    _, folded, pm = _miura_problem()
    by_edge = {tuple(sorted(e)): a for e, a in zip(folded.edges.tolist(), folded.edges_fold_angle)}
    hinges = [h for h, f in enumerate(pm.hinge_family) if f != "bend"]
    angles = [by_edge[tuple(sorted(pm.model.hinges[h][:2].tolist()))] for h in hinges]
    targets = rest_angles_for(np.array(angles), hinge_fold_signs(pm)[hinges])
    flat = pm.model.hinge_rest_angle[hinges]
    path = solve_fold(pm.model, [(hinges, targets), (hinges, flat)], 20)
    assert path.completed, path.message
    assert np.abs(path.displacement[-1]).max() < 1e-6
    assert np.abs(path.displacement[np.argmin(np.abs(path.load_factor - 1.0))]).max() > 5.0
    assert path.energy[-1] < 1e-12


def test_the_signs_agree_with_a_fold_files_own_angles():
    # The single-vertex example is pre-folded (valleys +20, +10, +20 deg, a mountain -10):
    # the fold angles read from the geometry through the signs are the file's.
    pattern = read_pattern("examples/single_vertex/single_vertex.fold")
    pm = build_pattern_model(pattern, material=STIFF)
    rho = fold_angles_deg(pm)
    file_angle = {tuple(sorted(e)): a for e, a in zip(pattern.edges.tolist(),
                                                       pattern.edges_fold_angle)}
    folds = [h for h, f in enumerate(pm.hinge_family) if f != "bend"]
    for h in folds:
        edge = tuple(sorted(pm.model.hinges[h][:2].tolist()))
        assert rho[h] == pytest.approx(file_angle[edge], abs=1e-6)


def _rotation(axis, angle):
    axis = axis / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def _closure_residual(directions, rho):
    """|| R_1 R_2 R_3 R_4 - I || for rotations by rho_i about the flat crease directions:
    zero exactly when the four rigid panels around the vertex close (rigid folding)."""
    best = np.inf
    for sign in (1.0, -1.0):  # which way round the vertex the rotations are composed
        R = np.eye(3)
        for d, r in zip(directions, rho):
            R = R @ _rotation(d, sign * r)
        best = min(best, np.linalg.norm(R - np.eye(3)))
    return best


def test_a_degree_4_vertex_driven_by_one_crease_folds_rigidly():
    pattern = read_pattern("examples/single_vertex/single_vertex.fold")
    fixed = np.zeros((5, 3), bool)
    fixed[0] = True
    fixed[[2, 4], 0] = True
    fixed[1, 2] = True
    pm = build_pattern_model(pattern, material=STIFF, fixed=fixed)
    folds = [h for h, f in enumerate(pm.hinge_family) if f != "bend"]
    creases = {h: int(pm.model.hinges[h][1] if pm.model.hinges[h][0] == 0
                      else pm.model.hinges[h][0]) for h in folds}
    driven = next(h for h in folds if creases[h] == 1)
    # Stiff panels, soft passive creases: the driven one is 1,000 times stiffer.
    stiffness = np.full(len(pm.model.hinges), 1e-3)
    stiffness[driven] = 1.0
    pm = dataclasses.replace(pm, model=pm.model.replace(hinge_stiffness=stiffness))
    rest = pm.model.hinge_rest_angle.copy()
    result = fold(pm, {driven: 90.0}, 40)
    assert result.completed, result.path.message
    # The flat pattern's crease directions, counter-clockwise around the vertex.
    flat = pattern.vertices  # pre-folded by a few degrees; the sector angles are rigid
    order = sorted(folds, key=lambda h: np.arctan2(*flat[creases[h], [1, 0]]))
    # Directions in a flat layout with the same sector angles.
    sectors = []
    for i, h in enumerate(order):
        a = flat[creases[h]] - flat[0]
        b = flat[creases[order[(i + 1) % 4]]] - flat[0]
        sectors.append(np.arccos(np.dot(a, b) / np.linalg.norm(a) / np.linalg.norm(b)))
    assert sum(sectors) == pytest.approx(2 * np.pi, abs=1e-9)
    phi = np.concatenate([[0.0], np.cumsum(sectors[:-1])])
    directions = [np.array([np.cos(p), np.sin(p), 0.0]) for p in phi]
    rho = np.radians(result.fold_angle_deg[:, order])
    residuals = [_closure_residual(directions, r) for r in rho]
    assert max(residuals) < 1e-3, max(residuals)
    # It could fail: the passive creases held at their first angles do not close.
    held = rho.copy()
    held[:, [order.index(h) for h in folds if h != driven]] = rho[0, [order.index(h) for h in
                                                                   folds if h != driven]]
    assert _closure_residual(directions, held[-1]) > 0.1
    # The driven crease went far, and no passive crease was driven.
    assert result.fold_angle_deg[-1, driven] > 60.0
    final_rest = pm.model.hinge_rest_angle
    np.testing.assert_array_equal(final_rest, rest)  # the model itself is unchanged


def _miura_problem(nx=2, ny=2, angle=40.0):
    flat = miura_sheet(nx, ny, fold_angle=0.0)
    folded = miura_sheet(nx, ny, fold_angle=angle)
    # The flat sheet with the folded one's assignments.
    pattern = dataclasses.replace(flat, edges_assignment=folded.edges_assignment)
    fixed = np.zeros((pattern.num_vertices + len(pattern.faces), 3), bool)
    fixed[list(pattern.faces[0][:3])] = True  # one panel held: no rigid motion is left
    pm = build_pattern_model(pattern, material=STIFF, fixed=fixed)
    return pattern, folded, pm


def test_a_miura_sheet_folds_from_flat_to_its_rigid_shape():
    pattern, folded, pm = _miura_problem()
    targets = {}
    by_edge = {tuple(sorted(e)): a for e, a in zip(folded.edges.tolist(), folded.edges_fold_angle)}
    for h, f in enumerate(pm.hinge_family):
        if f != "bend":
            targets[h] = by_edge[tuple(sorted(pm.model.hinges[h][:2].tolist()))]
    result = fold(pm, targets, 20, extrapolation=2)
    assert result.completed, result.path.message
    x = (pm.model.nodes + result.path.displacement[-1].reshape(-1, 3))[:pattern.num_vertices]
    # Same shape as the closed form: every pairwise distance (rigid motions aside).
    d_fold = np.linalg.norm(x[:, None] - x[None], axis=2)
    d_ref = np.linalg.norm(folded.vertices[:, None] - folded.vertices[None], axis=2)
    np.testing.assert_allclose(d_fold, d_ref, atol=1e-4)
    # Rigidly foldable: at the end nothing is stored beyond Newton's tolerance.
    assert result.path.energy[-1] < 1e-8


def _held_energy(pm, targets):
    """The energy the same rest-angle changes would store with the sheet held as it is:
    sum 1/2 k L (change)^2 over the driven creases [N*mm]."""
    hinges = np.array(sorted(targets))
    change = np.radians([targets[h] for h in hinges]) - np.radians(
        fold_angles_deg(pm)[hinges])
    model = pm.model
    return 0.5 * np.sum(model.hinge_stiffness[hinges] * model.hinge_length[hinges] * change ** 2)


def test_a_rigidly_foldable_sheet_stores_almost_nothing_on_the_way():
    # The rest angles move linearly, the rigid folding motion's fold angles do not (their
    # ratios change as the sheet folds), so the panels take a little strain between the
    # flat and the folded state: measured at most 2.9e-4 of what the same actuation would
    # store in a held sheet; bounded here at 1e-3.
    pattern, folded, pm = _miura_problem()
    by_edge = {tuple(sorted(e)): a for e, a in zip(folded.edges.tolist(), folded.edges_fold_angle)}
    targets = {h: by_edge[tuple(sorted(pm.model.hinges[h][:2].tolist()))]
               for h, f in enumerate(pm.hinge_family) if f != "bend"}
    result = fold(pm, targets, 20, extrapolation=2)
    assert result.completed
    assert result.path.energy.max() < 1e-3 * _held_energy(pm, targets)


def test_a_vertex_asked_for_an_impossible_fold_stores_energy():
    # Four valleys of 60 deg around one degree-4 vertex close no loop of rotations, and the
    # stiff panels cannot stretch to make one: the vertex stays close to where it is and
    # its creases keep most of the actuation's energy (measured: 0.82 of the held energy,
    # 0.1 % of it in the bars), where a foldable set of targets, as above, leaves almost
    # none.
    pattern = read_pattern("examples/single_vertex/single_vertex.fold")
    fixed = np.zeros((5, 3), bool)
    fixed[0] = True
    fixed[[2, 4], 0] = True
    fixed[1, 2] = True
    pm = build_pattern_model(pattern, material=STIFF, fixed=fixed, laws=WIDE)
    targets = {h: 60.0 for h, f in enumerate(pm.hinge_family) if f != "bend"}
    result = fold(pm, targets, 20)
    assert result.completed, result.path.message
    assert result.path.energy[-1] > 0.1 * _held_energy(pm, targets)


def test_adaptive_increments_fold_a_miura_sheet_as_the_fixed_ones_do():
    # The same fold from flat in 100 samples, adaptive increments against fixed ones with a
    # cubic start: the samples agree to the Newton tolerance (1e-6 mm; measured 1.1e-7 mm)
    # and their stored energy to 1e-8 of its largest value (measured 2e-10), with fewer
    # Newton iterations (measured 109 against 176).
    pattern, folded, pm = _miura_problem()
    by_edge = {tuple(sorted(e)): a for e, a in zip(folded.edges.tolist(), folded.edges_fold_angle)}
    targets = {h: by_edge[tuple(sorted(pm.model.hinges[h][:2].tolist()))]
               for h, f in enumerate(pm.hinge_family) if f != "bend"}
    fixed = fold(pm, targets, 100, extrapolation=3).path
    adaptive = fold(pm, targets, 100, adaptive=True).path
    assert fixed.completed and adaptive.completed, adaptive.message
    np.testing.assert_array_equal(adaptive.load_factor, fixed.load_factor)
    assert np.abs(adaptive.displacement - fixed.displacement).max() <= 1e-6
    assert np.abs(adaptive.energy - fixed.energy).max() <= 1e-8 * fixed.energy.max()
    assert adaptive.newton_iterations < fixed.newton_iterations


def test_adaptive_fold_options_are_checked():
    pattern, pm = _two_panels()
    with pytest.raises(ValueError, match="adaptive_tolerance"):
        solve_fold(pm.model, [([0], [2.0])], 5, adaptive=True, adaptive_tolerance=1e-3)
    with pytest.raises(ValueError, match="adaptive"):
        solve_fold(pm.model, [([0], [2.0])], 5, adaptive="yes")
