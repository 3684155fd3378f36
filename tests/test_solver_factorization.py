"""The factorisation the tangent solver chooses for real models (its cost model is unit
tested in C++): dense for the Kresling bending specimen, sparse with nested dissection for a
Miura-ori sheet of a few thousand DOFs, and the same solution either way."""

import numpy as np
import scipy.sparse as sp

from kresling import Design, _core
from kresling.assembly import tangent_stiffness
from kresling.io import miura_sheet
from kresling.model.calibration import SheetMaterial
from kresling.model.kresling_specimen import kresling_specimen
from kresling.model.pattern_model import build_pattern_model


def _free_lower(K, free):
    return sp.tril(K[free][:, free]).tocsc()


def test_bending_specimen_is_factorised_dense():
    # n = 10, four cells: 136 free DOFs, a factor ~60 % full: dense 58 us, CHOLMOD 85 us.
    s = kresling_specimen(Design(10, 0.9, 15), [1] * 4)
    fixed = np.zeros(s.model.num_dofs, bool)
    for level in (0, 4):
        for node in (s.node(level, 0), s.node(level, 5), s.centre(level)):
            fixed[3 * node:3 * node + 3] = True
    fixed[3 * s.level_nodes(2) + 1] = True
    plan = _core.solvers.factorization_plan(_free_lower(tangent_stiffness(s.model),
                                                        np.flatnonzero(~fixed)))
    assert (plan["cholesky"], plan["method"], plan["negative_eigenvalues"]) == \
        ("dense", "dense cholesky", 0)


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
        ("simplicial", "nested dissection", "cholesky")
    # The factor is sparse: far below the dense n (n + 1) / 2 entries.
    assert plan["factor_nonzeros"] < 0.1 * len(free) * (len(free) + 1) / 2
