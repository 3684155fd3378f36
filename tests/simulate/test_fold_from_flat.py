"""How a fold leaves the flat state (docs/folding.md, 'Folding from flat').

Every crease of a flat pattern could fold either way, but once its creases have stiffness
the flat state is not a singular point of the actuated model: the tangent there is positive
definite (the bars hold the sheet in its plane, the hinges out of it), so there is one
equilibrium path from flat, and the actuation's signs choose it. The checks: that tangent's
eigenvalues; the end of the fold not depending on how many increments reach it; a Miura
sheet driven to targets of one magnitude (not its rigid-folding ratios, so the senses are
not forced by a mechanism) taking the senses of its assignments, and with every assignment
flipped taking the flipped senses, as the mirror image of the first fold; and Rabbit Ear's
crane, which folds some creases the other way, doing so along one stable path."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.io import read_fold
from kresling.io.fold_format import fold_angles
from kresling.io.miura import miura_sheet
from kresling.model import ManualProperties, build_pattern_model
from kresling.simulate import simulate
from kresling.solvers import fold
from public_files import RABBIT_EAR, SHEET, held_and_far
from public_files import STIFF as STIFF_MATERIAL  # the same stiffness as a problem's table

STIFF = ManualProperties(bar_modulus=1e5, bar_area=1.0, fold_stiffness=1.0, bend_stiffness=1.0)


def _flat_miura():
    """A flat 2 x 2 Miura sheet with its folded state's assignments, one panel held."""
    flat = miura_sheet(2, 2, fold_angle=0.0)
    folded = miura_sheet(2, 2, fold_angle=40.0)
    pattern = dataclasses.replace(flat, edges_assignment=folded.edges_assignment)
    fixed = np.zeros((pattern.num_vertices + len(pattern.faces), 3), bool)
    fixed[list(pattern.faces[0][:3])] = True  # one panel held: no rigid motion is left
    return pattern, build_pattern_model(pattern, material=STIFF, fixed=fixed)


def _assigned_targets(pattern, pm, magnitude, flip=1.0):
    """Every crease's hinge to `magnitude` [deg] in its assigned sense (times `flip`)."""
    sense = {tuple(sorted(e)): (-1.0 if a == "M" else 1.0)
             for e, a in zip(pattern.edges.tolist(), pattern.edges_assignment)}
    return {h: flip * magnitude * sense[tuple(sorted(pm.model.hinges[h][:2].tolist()))]
            for h, family in enumerate(pm.hinge_family) if family != "bend"}


def _vertices(pattern, pm, result):
    return (pm.model.nodes + result.path.displacement[-1].reshape(-1, 3))[:pattern.num_vertices]


def test_the_flat_tangent_is_positive_definite_so_one_path_leaves_flat():
    pattern, pm = _flat_miura()
    model = pm.model
    free = model.free_dofs
    tangent = assemble(model, np.zeros(model.num_dofs)).stiffness.toarray()[np.ix_(free, free)]
    eigenvalues = np.linalg.eigvalsh(tangent)
    # Measured: smallest 0.0155 N/mm (an out-of-plane mode the hinges hold, of the order of
    # their stiffness 1 N mm/rad per mm over the panels' ~10 mm), largest ~1e5 (the bars).
    # Zero would be a singular point, where fold modes branch; this is far from it.
    assert eigenvalues[0] > 1e-3
    # The bars give no out-of-plane stiffness in the flat state (their length changes to
    # second order only), so the hinges alone hold the out-of-plane DOFs: without them
    # flat would be singular.
    bare = model.replace(hinge_stiffness=np.zeros(len(model.hinges)))
    tangent = assemble(bare, np.zeros(model.num_dofs)).stiffness.toarray()[np.ix_(free, free)]
    assert np.linalg.eigvalsh(tangent)[0] < 1e-9 * eigenvalues[-1]


def test_the_fold_from_flat_does_not_depend_on_its_increments():
    # One path: 4, 16 or 64 equal increments end at the same state. Newton's tolerance is
    # 1e-6 mm on the last correction, so the ends agree to a few of it: 1e-5 mm.
    pattern, pm = _flat_miura()
    targets = _assigned_targets(pattern, pm, 30.0)
    ends = []
    for steps in (4, 16, 64):
        result = fold(pm, targets, steps)
        assert result.completed, result.path.message
        ends.append(_vertices(pattern, pm, result))
    for end in ends[1:]:
        np.testing.assert_allclose(end, ends[0], atol=1e-5)


@pytest.mark.parametrize("magnitude", [10.0, 60.0])
def test_a_flat_miura_sheet_folds_each_crease_the_way_it_is_assigned_or_flipped(magnitude):
    # All creases to one magnitude: the Miura vertex's rigid folding has other ratios (its
    # mountains and valleys fold by different angles), so the sheet cannot reach these
    # targets and the senses are the model's choice, not a mechanism's. Measured: every
    # crease in its sense, the least folded at 0.59 of its target (10 deg) and 0.66 (60 deg).
    pattern, pm = _flat_miura()
    creases = np.array([a in "MV" for a in pattern.edges_assignment])
    sense = np.where(np.array(pattern.edges_assignment) == "M", -1.0, 1.0)[creases]
    ends = {}
    for flip in (1.0, -1.0):
        result = fold(pm, _assigned_targets(pattern, pm, magnitude, flip), 10)
        assert result.completed, result.path.message
        x = _vertices(pattern, pm, result)
        # The geometry's own fold angles (from the faces' normals), not the model's.
        reached = np.degrees(fold_angles(pattern.faces, pattern.edges, x))[creases]
        assert np.all(np.sign(reached) == flip * sense)
        assert np.all(np.abs(reached) > 0.5 * magnitude)
        ends[flip] = x
    # Flipping every target mirrors the problem in the sheet's plane (z = 0; the held panel
    # lies in it): the flipped fold is the first one's mirror image, to rounding and
    # Newton's tolerance (1e-5 mm, as above).
    mirrored = ends[1.0] * np.array([1.0, 1.0, -1.0])
    np.testing.assert_allclose(ends[-1.0], mirrored, atol=1e-5)
    assert np.abs(ends[1.0][:, 2]).max() > 1.0  # it did fold out of the plane


def test_the_cranes_fold_from_flat_is_one_stable_path_whatever_its_increments():
    # Rabbit Ear's crane, every crease driven to a tenth of its +-180 deg: some creases go
    # the other way (tests/io/test_io_public_folds.py records it), and this shows that it is
    # the model's one path from flat, not a branch taken by chance: 10 and 100 increments
    # end at the same state (measured 4.7e-11 mm apart; Newton's tolerance 1e-6 mm bounds
    # it) with the tangent positive definite at every increment.
    path = RABBIT_EAR / "crane.fold"
    pattern = read_fold(path, frame=1, **SHEET)
    letters = np.array(read_fold(path, **SHEET).edges_assignment)
    targets = 0.1 * np.where(letters == "M", -180.0, 180.0)
    actuation = [{"edges": [edge], "fold_angle_deg": float(target)}
                 for edge, letter, target in zip(pattern.edges.tolist(), letters, targets)
                 if letter in "MV"]
    ends = []
    for steps in (10, 100):
        sim = simulate({"pattern": {"file": str(path), "frame": 1, **SHEET}, "material": STIFF_MATERIAL,
                        "laws": {"fold_limits_deg": [1.0, 359.0]},
                        "support": [{"nodes": held_and_far(pattern)[0], "fix": "xyz"}],
                        "actuation": actuation, "analysis": {"method": "fold", "steps": steps}},
                       progress=False)
        assert sim.path.completed, sim.path.message
        assert np.all(np.asarray(sim.path.negative_eigenvalues) == 0)
        assert sim.summary()["fold"]["left_branch"] > 0  # the case the path decides
        ends.append(sim.path.displacement[-1])
    np.testing.assert_allclose(ends[1], ends[0], atol=1e-6)
