"""The factorisation the tangent solver chooses for real models (its cost model is unit
tested in C++): supernodal with Eigen's kernels for the Kresling bending specimen and for a
Miura-ori sheet of a few thousand DOFs (there with nested dissection), and the same solution
either way."""

import numpy as np
import pytest
import scipy.sparse as sp

from kresling import Design, _core
from kresling.assembly import tangent_stiffness
from kresling.io import miura_sheet
from kresling.model.calibration import SheetMaterial
from kresling.model.kresling_specimen import kresling_specimen
from kresling.model.pattern_model import build_pattern_model
from kresling.solvers import solve_displacement_control, solve_force_control, solve_mgdcm


def _free_lower(K, free):
    return sp.tril(K[free][:, free]).tocsc()


def test_bending_specimen_is_factorised_supernodal():
    # n = 10, four cells: 136 free DOFs, a factor ~55 % full: supernodal with Eigen's
    # kernels 32 us, dense 58 us, CHOLMOD's simplicial 88 us (benchmarks/cpp).
    s = kresling_specimen(Design(10, 0.9, 15), [1] * 4)
    fixed = np.zeros(s.model.num_dofs, bool)
    for level in (0, 4):
        for node in (s.node(level, 0), s.node(level, 5), s.centre(level)):
            fixed[3 * node:3 * node + 3] = True
    fixed[3 * s.level_nodes(2) + 1] = True
    plan = _core.solvers.factorization_plan(_free_lower(tangent_stiffness(s.model),
                                                        np.flatnonzero(~fixed)))
    assert (plan["cholesky"], plan["method"], plan["negative_eigenvalues"]) == \
        ("supernodal", "supernodal cholesky", 0)


def test_sheet_gets_nested_dissection_and_solves_alike():
    pm = build_pattern_model(miura_sheet(16, 16), material=SheetMaterial(5e3, 0.35, 0.127),
                             centre="mean")
    fixed = np.zeros((pm.model.num_nodes, 3), bool)
    fixed[:17] = True                                   # the row j = 0 of the sheet
    free = np.flatnonzero(~fixed.ravel())
    K = _free_lower(tangent_stiffness(pm.model), free)
    plan = _core.solvers.factorization_plan(K)
    assert len(free) > 1000
    assert (plan["cholesky"], plan["ordering"], plan["method"]) == \
        ("supernodal", "nested dissection", "supernodal cholesky")
    # The factor is sparse: far below the dense n (n + 1) / 2 entries.
    assert plan["factor_nonzeros"] < 0.1 * len(free) * (len(free) + 1) / 2


def _clamped_sheet():
    pm = build_pattern_model(miura_sheet(5, 5), material=SheetMaterial(5e3, 0.35, 0.127),
                             centre="mean")
    fixed = np.zeros((pm.model.num_nodes, 3), bool)
    fixed[:6] = True                                     # the row j = 0 of the sheet
    model = pm.model.replace(fixed=fixed)
    forces = np.zeros((model.num_nodes, 3))
    forces[30:36, 2] = 1e-4                              # the opposite edge, out of plane
    return model, forces


@pytest.mark.parametrize("solve", ["force_control", "mgdcm", "displacement_control"])
def test_every_forced_cholesky_follows_the_same_path(solve):
    # A sheet of 6 x 6 nodes bent out of plane (stable all along, so the Cholesky serves every
    # iteration): the three factorisations give the same path, to the Newton tolerance (1e-6
    # mm on the correction, as in the comparisons with MERLIN2; measured: up to 1.2e-8 mm).
    model, forces = _clamped_sheet()
    paths = {}
    for choice in ("auto", "dense", "simplicial", "supernodal"):
        if solve == "force_control":
            path = solve_force_control(model, forces, 3, cholesky=choice)
        elif solve == "mgdcm":
            path = solve_mgdcm(model, forces, initial_load_factor=0.5, max_increments=3,
                               cholesky=choice)
        else:
            prescribed = np.zeros((model.num_nodes, 3))
            prescribed[30:36, 2] = 2.0                    # mm
            path = solve_displacement_control(model, prescribed, 4, cholesky=choice)
        assert path.completed and (np.asarray(path.negative_eigenvalues) == 0).all()
        paths[choice] = np.asarray(path.displacement)
    for choice, u in paths.items():
        assert u.shape == paths["auto"].shape
        assert np.abs(u - paths["auto"]).max() <= 1e-6, choice


def test_an_unknown_cholesky_is_refused():
    model, forces = _clamped_sheet()
    with pytest.raises(ValueError, match="cholesky = 'cholmod' is invalid: must be one of "
                                         "'auto', 'dense', 'simplicial', 'supernodal'"):
        solve_force_control(model, forces, 3, cholesky="cholmod")
