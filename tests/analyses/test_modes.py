"""Vibration modes: closed-form chain, an independent dense solve, the mass checks."""

import numpy as np
import pytest
import scipy.linalg

from small_models import chain
from kresling import Design
from kresling.analyses.modes import vibration_modes
from kresling.assembly import assemble
from kresling.model import kresling_specimen
from kresling.model.masses import lumped_masses


@pytest.mark.parametrize("n", [8, 40])
def test_chain_matches_closed_form(n):
    spring, mass = 2.5, 3e-6
    model, masses = chain(n, spring, mass)
    k = min(6, n - 2)
    modes = vibration_modes(model, masses, k=k)
    j = np.arange(1, k + 1)
    omega = 2 * np.sqrt(spring / mass) * np.sin((2 * j - 1) * np.pi / (2 * (2 * n + 1)))
    # Shift-invert Lanczos converges the eigenvalues to ARPACK's tolerance (machine
    # precision by default): 1e-8 relative is far above round-off in a 40-DOF solve.
    np.testing.assert_allclose(2 * np.pi * modes.frequencies_hz, omega, rtol=1e-8)
    assert not modes.rigid.any()
    # Mass-normalised, zero on supports; all the mass moves along x only.
    m = np.repeat(masses, 3)
    np.testing.assert_allclose(np.einsum("ij,j,ij->i", modes.shapes, m, modes.shapes), 1.0,
                               rtol=1e-12)
    assert np.all(modes.shapes[:, model.fixed.ravel()] == 0)
    assert np.all(modes.participation[:, 1:] == 0)
    # The chain's modes are sin(i theta_j), i = 1..n, theta_j = (2j - 1) pi / (2n + 1):
    # effective mass fraction (sum sin)^2 / (n sum sin^2).
    s = np.sin(np.outer(np.arange(1, n + 1), (2 * j - 1) * np.pi / (2 * n + 1)))
    expected = s.sum(axis=0) ** 2 / (n * (s ** 2).sum(axis=0))
    np.testing.assert_allclose(modes.effective_mass_fraction[:, 0], expected, rtol=1e-9)


def test_chain_all_modes_sum_to_free_mass():
    model, masses = chain(5)
    modes = vibration_modes(model, masses, k=5)   # every free DOF: the dense path
    np.testing.assert_allclose(modes.effective_mass_fraction[:, 0].sum(), 1.0, rtol=1e-12)


@pytest.mark.parametrize("state", ["extended", "contracted"])
def test_kresling_cell_matches_dense_solve(state):
    specimen = kresling_specimen(Design(n=10, lam=0.9, Lc=15, R=30), [state])
    fixed = np.zeros((specimen.model.num_nodes, 3), dtype=bool)
    fixed[specimen.level_nodes(0)] = True
    model = specimen.model.replace(fixed=fixed)
    masses = lumped_masses(specimen, 0.3, 1.38e-9)
    modes = vibration_modes(model, masses, k=10)
    # Independent: the dense tangent restricted by hand, scipy.linalg.eigh on (K, M).
    free = np.flatnonzero(~fixed.ravel())
    K = assemble(model).stiffness.toarray()[np.ix_(free, free)]
    M = np.diag(np.repeat(masses, 3)[free])
    values = scipy.linalg.eigh(K, M, eigvals_only=True)[:10]
    np.testing.assert_allclose(modes.eigenvalues, values, rtol=1e-8)
    # The shapes solve K phi = omega^2 M phi (residual relative to K phi).
    phi = modes.shapes[:, free]
    residual = phi @ K - modes.eigenvalues[:, None] * phi @ M
    assert np.abs(residual).max() < 1e-8 * np.abs(phi @ K).max()


def test_mechanism_modes_are_reported_rigid():
    model, masses = chain(6)
    free = model.fixed.copy()
    free[0] = [False, True, True]       # the whole chain may slide along x
    modes = vibration_modes(model.replace(fixed=free), masses, k=3)
    assert modes.rigid.tolist() == [True, False, False]
    assert abs(modes.frequencies_hz[0]) < 1e-3 * modes.frequencies_hz[1]


def test_massless_free_node_is_refused():
    model, masses = chain(6)
    masses[3] = 0.0
    with pytest.raises(ValueError, match=r"zero at free node\(s\) \[3\]"):
        vibration_modes(model, masses, k=2)
    with pytest.raises(ValueError, match="k = 99"):
        vibration_modes(model, np.ones(7), k=99)
    with pytest.raises(ValueError, match="masses has 3 entries"):
        vibration_modes(model, np.ones(3), k=2)
