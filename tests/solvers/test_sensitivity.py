"""Exact sensitivities (kresling.solvers.sensitivity) against finite differences.

The model is a clamped Miura-ori sheet of 6 x 6 nodes (N5B8, a thin sheet's calibration),
bent out of plane by a prescribed motion or by forces on its far edge, as the factorisation
tests bend it. The finite differences solve the whole path again with a parameter moved by
+-h and Newton converged to 1e-11 mm: their error is the Newton residue over 2 h plus the
truncation, ~h^2 relative. h is 1e-5 of the parameter's size, and 1e-4 for the bars' (stiff:
the reactions' residue is their stiffness times 1e-11 mm, which a smaller step magnifies).
Measured, the differences agree with the exact derivatives to 2e-5 of each history column's
largest entry or better; the tests assert 1e-4, far below a wrong term's O(1).

The rest angles differentiated are the folds' (enhanced-linear law): the panels' bend
hinges follow MERLIN2's super-linear law kp |d|^(4/3), whose second derivative is infinite
at d = 0, so differences across an unbent panel converge only like h^(1/3).
"""

import dataclasses

import numpy as np
import pytest

from kresling import _core
from kresling.io import miura_sheet
from kresling.model.calibration import SheetMaterial
from kresling.model.pattern_model import build_pattern_model
from kresling.solvers import solve_displacement_control, solve_force_control
from kresling.solvers.sensitivity import (Parameter, equilibrium_gradient,
                                          equilibrium_sensitivity, parameter_jacobian,
                                          parameter_names, path_sensitivity, with_parameter)

REL_STEP = {"bars": 1e-4, "hinges": 1e-5}
REL_TOL = 1e-4
TOLERANCE = 1e-11  # Newton's, on the correction [mm], for the finite differences


@pytest.fixture(scope="module")
def sheet():
    pm = build_pattern_model(miura_sheet(5, 5), material=SheetMaterial(5e3, 0.35, 0.127),
                             centre="mean")
    fixed = np.zeros((pm.model.num_nodes, 3), bool)
    fixed[:6] = True                                     # the row j = 0 of the sheet
    return pm.model.replace(fixed=fixed)


def _prescribed(model):
    prescribed = np.zeros((model.num_nodes, 3))
    prescribed[30:36, 2] = 2.0                           # the opposite edge lifted [mm]
    return prescribed


def _forces(model):
    forces = np.zeros((model.num_nodes, 3))
    forces[30:36, 2] = 1e-4                              # [N]
    return forces


def _lift(model):
    return solve_displacement_control(model, _prescribed(model), 4, tolerance=TOLERANCE,
                                      extrapolation=2)


def _push(model):
    return solve_force_control(model, _forces(model), 3, tolerance=TOLERANCE)


def _moved(model, name, sign):
    p = Parameter.parse(name)
    values = np.asarray(model.family(p.family)[p.column], float)
    w = p.weights(values.size)
    h = REL_STEP[p.family] * np.abs(values[w != 0]).mean()
    return with_parameter(model, name, values + sign * h * w), h


def _central(model, name, solve, field):
    plus, h = _moved(model, name, +1)
    minus, _ = _moved(model, name, -1)
    a, b = solve(plus), solve(minus)
    assert a.completed and b.completed
    return (np.asarray(getattr(a, field)) - np.asarray(getattr(b, field))) / (2 * h)


def _close(exact, fd, rel=REL_TOL):
    scale = np.abs(fd).max()
    assert scale > 0
    return np.abs(exact - fd).max() <= rel * scale


def test_the_parameters_are_named_by_family_and_column(sheet):
    names = parameter_names(sheet)
    assert names[:6] == ["bars.area", "bars.rest_length", "bars.modulus", "hinges.stiffness",
                         "hinges.rest_angle", "hinges.length"]


@pytest.mark.parametrize("name", ["bars.area", "bars.rest_length", "bars.modulus",
                                  "hinges.stiffness", "hinges.rest_angle", "hinges.length"])
def test_the_jacobian_is_the_forces_difference(sheet, name):
    # At a bent state of the sheet: every entry's column against central differences of
    # the whole model's force (steps of 1e-6 relative; the force is smooth in each
    # parameter there, rounding ~1e-10 of the largest force).
    u = np.asarray(_lift(sheet).displacement[-1])
    force, energy = parameter_jacobian(sheet, u, name)
    p = Parameter.parse(name)
    values = np.asarray(sheet.family(p.family)[p.column], float)
    for j in (0, len(values) // 2, len(values) - 1):
        h = 1e-6 * abs(values[j])
        evaluations = []
        for sign in (1, -1):
            moved = values.copy()
            moved[j] += sign * h
            e, f, _ = _core.assembly.assemble(with_parameter(sheet, name, moved)._core, u, 0.0,
                                              False)
            evaluations.append((np.asarray(f), float(np.sum(e))))
        fd = (evaluations[0][0] - evaluations[1][0]) / (2 * h)
        column = force[:, j].toarray().ravel()
        assert np.abs(column - fd).max() <= 1e-6 * max(np.abs(fd).max(), 1e-300), (name, j)
        efd = (evaluations[0][1] - evaluations[1][1]) / (2 * h)
        # One element's share of the whole energy: the difference is exact to the rounding
        # of the total, eps E / h.
        rounding = 100 * np.finfo(float).eps * abs(evaluations[0][1]) / h
        assert energy[j] == pytest.approx(efd, rel=1e-6, abs=rounding), (name, j)


def _folds_rest_angle(model):
    return Parameter("hinges", "rest_angle", direction=(model.hinge_law == 1).astype(float),
                     name="folds' rest angle")


@pytest.mark.parametrize("name", ["hinges.stiffness", "bars.modulus", "folds"])
def test_a_displacement_controlled_path_against_paths_solved_again(sheet, name):
    if name == "folds":
        name = _folds_rest_angle(sheet)
    path = _lift(sheet)
    s = path_sensitivity(sheet, path, [name])
    assert s.constraint_force.shape == (4, 6, 1) and s.displacement.shape == (4, sheet.num_dofs, 1)
    assert _close(s.constraint_force[:, :, 0], _central(sheet, name, _lift, "constraint_force"))
    assert _close(s.displacement[:, :, 0], _central(sheet, name, _lift, "displacement"))
    assert _close(s.energy[:, 0], _central(sheet, name, _lift, "energy"))


@pytest.mark.parametrize("name", ["hinges.stiffness", "bars.area"])
def test_a_force_controlled_path_against_paths_solved_again(sheet, name):
    path = _push(sheet)
    s = path_sensitivity(sheet, path, [name])
    # The support reactions balance the fixed load: their derivative sums to zero per axis.
    reactions = s.constraint_force[-1, :, 0].reshape(-1, 3)
    assert np.abs(reactions.sum(axis=0)).max() <= 1e-9 * np.abs(reactions).max()
    assert _close(s.displacement[:, :, 0], _central(sheet, name, _push, "displacement"))
    assert _close(s.constraint_force[:, :, 0], _central(sheet, name, _push, "constraint_force"))
    assert _close(s.energy[:, 0], _central(sheet, name, _push, "energy"))


@pytest.fixture(scope="module")
def bent_cell():
    """A four-cell Kresling specimen in the thesis's three-point bending set-up (n = 8,
    extended, 0.5 mm at the middle polygon): a smooth path that adaptive increments follow
    in a few knots (the Miura sheet's panels bend by a law whose tangent is not smooth at
    flat, which keeps every increment short)."""
    from kresling.geometry import Design
    from kresling.model.kresling_specimen import SpecimenParameters
    from kresling.model.model import Model

    parameters = SpecimenParameters(hinge_angle="exact").to_core()
    test = _core.analyses.BendingTest(8, 0.5, 0.0, 40, 4, parameters,
                                      _core.solvers.DisplacementControlOptions())
    specimen, prescribed = test.setup(Design(8, 0.8, 15.0, 30.0)._core, 1)
    return Model._from_core(specimen.model), np.asarray(prescribed)


def _bend_adaptive(prescribed):
    def solve(model):
        return solve_displacement_control(model, prescribed, 40, tolerance=1e-10,
                                          extrapolation=2, shift=0.0, adaptive=True,
                                          keep_knots=True)
    return solve


@pytest.mark.parametrize("name", ["hinges.stiffness", "bars.modulus", "hinges.rest_angle"])
def test_an_adaptive_path_is_differentiated_through_its_knots(bent_cell, name):
    # The samples of an adaptive path are cubic Hermite curves between its knots, so their
    # derivatives come from the knots' and from their rates along the path (the rates'
    # mixed second derivative by a central difference along the path). They must agree
    # with the per-sample derivatives of the equilibria the samples stand for to the
    # interpolation error and that difference's (measured: 1.1e-6 of the largest energy
    # derivative, 4e-7 of the displacements', 3e-8 of the drive's; asserted 1e-5), and the
    # drive's summed force with the same adaptive path solved again with the column scaled
    # by 1 +- 1e-3 (measured 4.5e-6; its knots move with it, by the interpolation error).
    # The drive is compared summed: how it is shared among the driven DOFs is determined
    # only to the Newton tolerance. (The per-sample derivatives themselves are checked
    # against differences on the sheet above; on this specimen, with bars 1e5 times
    # stiffer than its hinges, differences of the displacements carry 1e-3 of noise.)
    model, prescribed = bent_cell
    family, column = name.split(".")
    values = np.asarray(model.family(family)[column], float)
    stiff = np.asarray(model.family("hinges")["stiffness"], float) > 0
    # Rest angles moved together where the hinge has stiffness (a cut crease has none).
    direction = stiff * 1.0 if column == "rest_angle" else values
    parameter = Parameter(family, column, direction=direction)
    solve = _bend_adaptive(prescribed)
    path = solve(model)
    knots = path.knots
    assert knots is not None and len(knots.t) < path.num_steps / 2
    assert (knots.step_knot > 0).all() and (path.iterations == 0).sum() > path.num_steps / 2
    s = path_sensitivity(model, path, [parameter])
    per_sample = path_sensitivity(model, dataclasses.replace(path, knots=None), [parameter])
    assert _close(s.constraint_force.sum(axis=1), per_sample.constraint_force.sum(axis=1), 1e-5)
    assert _close(s.displacement, per_sample.displacement, 1e-5)
    assert _close(s.energy, per_sample.energy, 1e-5)
    h = 1e-3
    plus, minus = (solve(with_parameter(model, name, values + sign * h * direction))
                   for sign in (1, -1))
    difference = (np.asarray(plus.constraint_force).sum(axis=1)
                  - np.asarray(minus.constraint_force).sum(axis=1)) / (2 * h)
    assert _close(s.constraint_force[..., 0].sum(axis=1), difference)


def test_the_adjoint_gives_every_elements_derivative_at_once(sheet):
    # J = the lifted edge's reaction force sum at the end of the lift; its gradient with
    # respect to each hinge's stiffness by one adjoint solve, against the direct derivative
    # of a few single hinges.
    path = _lift(sheet)
    u = np.asarray(path.displacement[-1])
    held = np.asarray(path.constraint_dofs)
    weights = np.zeros(sheet.num_dofs)
    rng = np.random.default_rng(3)
    free = np.setdiff1d(sheet.free_dofs, held)
    weights[free] = rng.standard_normal(free.size)      # J = weights . u
    gradient = equilibrium_gradient(sheet, u, weights, ["hinges.stiffness"], held=held)
    g = gradient["hinges.stiffness"]
    assert g.shape == (len(sheet.hinges),)
    for j in (0, 7, len(sheet.hinges) - 1):
        direct = equilibrium_sensitivity(sheet, u, [f"hinges.stiffness[{j}]"], held=held)
        assert g[j] == pytest.approx(weights @ direct.displacement[:, 0], rel=1e-9,
                                     abs=1e-12 * np.abs(g).max())


def test_bad_requests_are_refused_clearly(sheet):
    u = np.zeros(sheet.num_dofs)
    with pytest.raises(ValueError, match="has no parameter 'stiffness': must be one of area, "
                                         "rest_length, modulus"):
        parameter_jacobian(sheet, u, "bars.stiffness")
    with pytest.raises(ValueError, match="no element family 'springs'"):
        parameter_jacobian(sheet, u, "springs.stiffness")
    with pytest.raises(ValueError, match="must be 'family.column'"):
        parameter_jacobian(sheet, u, "modulus")
    with pytest.raises(ValueError, match=r"entry 100000 is out of range"):
        equilibrium_sensitivity(sheet, u, ["bars.area[100000]"])
    with pytest.raises(ValueError, match="held: DOF 0 is supported"):
        equilibrium_sensitivity(sheet, u, ["bars.area"], held=[0])
    free = sheet.replace(fixed=np.zeros((sheet.num_nodes, 3), bool))
    with pytest.raises(ValueError, match="rigid-body"):
        equilibrium_sensitivity(free, u, ["bars.area"])
    stopped = solve_displacement_control(sheet, 100 * _prescribed(sheet), 1, max_iterations=2,
                                         max_bisections=0)
    assert not stopped.completed
    with pytest.raises(ValueError, match="did not complete"):
        path_sensitivity(sheet, stopped, ["bars.area"])


def test_knots_that_do_not_match_their_path_are_refused(bent_cell):
    model, prescribed = bent_cell
    path = _bend_adaptive(prescribed)(model)
    k = path.knots
    short = dataclasses.replace(k, step_knot=k.step_knot[:-1])
    with pytest.raises(ValueError, match="step_knot: must have one entry per state"):
        path_sensitivity(model, dataclasses.replace(path, knots=short), ["bars.area"])
    backwards = dataclasses.replace(k, t=k.t[::-1].copy())
    with pytest.raises(ValueError, match="knots: t must increase"):
        path_sensitivity(model, dataclasses.replace(path, knots=backwards), ["bars.area"])
