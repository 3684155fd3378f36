"""MGDCM where Newton's accuracy floor rises above the tolerance: a one-layer Kresling.

Six-sided, R = H = 50 mm, the top ring turned by 30 deg, 12 triangles; linear bars
(E = 10 N/mm^2, A = 19.7 mm^2) and enhanced-linear folds (18/342 deg, k L0 = 1e-3 N*mm/rad
each), bottom ring fixed, -0.4 N on each top node, tolerance 1e-10 mm. Its path crosses a
double bifurcation near u_z = -22.5 mm (and, from another start, one near -28.3 mm) where the
tangent's smallest eigenvalues pass zero and the corrections' rounding noise is ~1e-9 mm:
with MERLIN2's step control alone the step factor halved down to that floor and the path
crept on by 1e-10 mm per increment until the 100,000 increments ran out.
"""

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.solvers import solve_mgdcm
from kresling.testing.one_layer_kresling import SIDES, one_layer_kresling

@pytest.fixture(scope="module")
def kresling():
    return one_layer_kresling()


def test_the_path_passes_the_bifurcation_where_it_stalled(kresling):
    model, forces = kresling
    top = model.dof(SIDES, 2)
    path = solve_mgdcm(model, forces, initial_load_factor=0.003, tolerance=1e-10,
                       max_increments=100_000, monitor_dof=top, max_displacement=49.0)
    assert path.completed, path.message
    uz = path.displacement.reshape(path.num_steps, -1)[:, top]
    assert uz[-1] < -49.0 and uz.min() < -28.4   # past the stall at -28.31 mm
    # The last state is an equilibrium: f_int = lambda F at the free DOFs, to the rounding
    # of forces of ~1 N (the tolerance bounds the last correction, 1e-10 mm, times a
    # stiffness of at most ~10 N/mm).
    free = model.free_dofs
    u = path.displacement[-1].ravel()
    residual = assemble(model, u, stiffness=False).force[free] - \
        path.load_factor[-1] * forces.ravel()[free]
    assert np.abs(residual).max() < 1e-8
    # The same path as from a start that never met the floor (initial_load_factor 0.01):
    # where both are past the stall, the load factor at the same displacement agrees.
    reference = solve_mgdcm(model, forces, initial_load_factor=0.01, tolerance=1e-10,
                            max_increments=100_000, monitor_dof=top, max_displacement=49.0)
    assert reference.completed
    ref_uz = reference.displacement.reshape(reference.num_steps, -1)[:, top]
    tail, ref_tail = uz < -45.0, ref_uz < -45.0   # one branch, monotone in u_z there
    lam = np.interp(-uz[tail], -ref_uz[ref_tail], reference.load_factor[ref_tail])
    assert np.abs(lam - path.load_factor[tail]).max() < 1e-4 * np.abs(path.load_factor).max()


def test_a_floor_no_longer_step_passes_is_reported(kresling):
    """At 1e-13 mm the tolerance is below the corrections' rounding at the bifurcation
    itself and beyond: the path stops there and says why, with the increment."""
    model, forces = kresling
    path = solve_mgdcm(model, forces, initial_load_factor=0.003, tolerance=1e-13,
                       max_increments=100_000, monitor_dof=model.dof(SIDES, 2),
                       max_displacement=49.0)
    assert not path.completed
    assert "Newton's corrections stall at" in path.message
    assert f"MGDCM increment {path.num_steps + 1} " in path.message
    assert "mm or more clears this floor" in path.message
