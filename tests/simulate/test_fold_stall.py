"""Why a fold's path ended early, as the run's message says it
(kresling.simulate.fold_stall): measured on Origami Simulator's flapping bird, folded as a
new user folds it (nothing but the pattern), whose path ends at 56 % of its targets."""

from __future__ import annotations

import re

import numpy as np
import pytest
from scipy.optimize import minimize

from kresling import solvers
from kresling.assembly import assemble
from kresling.simulate import simulate
from kresling.simulate.fold_stall import COLLAPSED, squashed_triangle
from public_files import ORIGAMI_SIMULATOR


def _new_users_fold(name):
    return simulate({"pattern": {"file": str(ORIGAMI_SIMULATOR / name)},
                     "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
                     "analysis": {"method": "fold"}}, progress=False)


@pytest.fixture(scope="module")
def bird():
    return _new_users_fold("flappingBird.svg")


def _smallest_eigenvalue(sim, step):
    free = sim.model.free_dofs
    tangent = assemble(sim.model_at(step), sim.path.displacement[step]).stiffness.toarray()
    return np.linalg.eigvalsh(tangent[np.ix_(free, free)])[0]


def test_the_birds_message_says_its_path_ends_at_a_limit_point(bird):
    assert not bird.path.completed
    assert bird.stall and bird.stall in bird.message
    found = re.search(r"smallest eigenvalue (\S+) N/mm against (\S+) N/mm at (\S+): a limit "
                      r"point of the rest angles", bird.stall)
    assert found, bird.stall
    last, earlier, at = (float(found.group(k)) for k in (1, 2, 3))
    # The eigenvalues it names are the tangent's, computed here by numpy's dense solver, at
    # the last equilibrium and at the one a whole increment (1/40) before it (3 significant
    # digits: as printed).
    step = int(np.argmin(np.abs(bird.path.load_factor - at)))
    assert bird.path.load_factor[-1] - at == pytest.approx(1 / 40, abs=1 / 40)
    assert last == pytest.approx(_smallest_eigenvalue(bird, -1), rel=5e-3)
    assert earlier == pytest.approx(_smallest_eigenvalue(bird, step), rel=5e-3)
    # A limit point: stable, the smallest eigenvalue falling towards zero.
    assert 0 < last < 0.5 * earlier


def test_past_the_birds_limit_point_the_energy_leads_into_a_collapsed_triangle(bird):
    found = re.search(r"descending the energy at (\S+) from there collapses the panel "
                      r"triangle of nodes (\d+), (\d+) and (\d+) to a line", bird.stall)
    assert found, bird.stall
    ahead = float(found.group(1))
    named = {int(found.group(k)) for k in (2, 3, 4)}
    assert ahead == pytest.approx(bird.path.load_factor[-1] + 1 / 40, abs=1e-4)
    # The same question put to another descent (nonlinear conjugate gradients, where the
    # message's is L-BFGS) from the same last equilibrium: it ends with a panel triangle
    # below 1 % of its flat height too.
    model = solvers.fold_model_at(bird.model, bird.fold.stages, ahead)
    free = bird.model.free_dofs
    start = bird.path.displacement[-1]

    def energy(z):
        u = start.copy()
        u[free] = z
        try:
            a = assemble(model, u, stiffness=False)
        except ValueError:
            return np.inf, np.zeros_like(z)
        return a.energy, a.force[free]

    end = start.copy()
    end[free] = minimize(energy, start[free], jac=True, method="CG",
                         options={"maxiter": 3000, "gtol": 1e-8}).x
    triangle, ratio, _, _ = squashed_triangle(bird.pattern_model, end)
    assert ratio < COLLAPSED
    # The descents may collapse either of a symmetric pair; the message's is one of the
    # bird's panel triangles, and a real one (flat height above zero).
    assert named in [set(t) for t in bird.pattern_model.elements.triangles.tolist()]


def test_a_fold_that_completes_has_no_stall_and_flat_triangles_are_not_squashed():
    sim = _new_users_fold("birdBase.svg")
    assert sim.completed and sim.stall == "" and sim.message == ""
    _, ratio, corners, flat = squashed_triangle(sim.pattern_model,
                                                np.zeros(sim.model.num_dofs))
    assert ratio == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(corners, flat, atol=1e-9)
    assert corners.sum() == pytest.approx(180.0, abs=1e-9)


def test_a_path_ending_unstable_is_not_taken_for_a_limit_point():
    # The pinwheel base with stiff bars (1e5 N/mm^2) and no relaxation follows its path
    # through unstable equilibria to 83 % of its targets: its last equilibrium has a negative
    # eigenvalue (checked here by numpy), so no limit point is claimed and nothing is
    # descended past it.
    problem = {"pattern": {"file": str(ORIGAMI_SIMULATOR / "pinwheelBase.svg")},
               "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
               "analysis": {"method": "fold", "steps": 20},
               "material": {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
                            "fold_stiffness": 1.0, "bend_stiffness": 1.0},
               "laws": {"fold_limits_deg": [1.0, 359.0], "bend_limits_deg": [1.0, 359.0]}}
    sim = simulate(problem, progress=False)
    assert not sim.path.completed
    assert _smallest_eigenvalue(sim, -1) < 0
    assert "is unstable" in sim.stall and sim.stall in sim.message
    assert "limit point" not in sim.stall and "descending" not in sim.stall


def test_beyond_the_dense_size_the_limit_point_is_found_by_the_sparse_eigensolver(bird,
                                                                                 monkeypatch):
    # The bird's 102 free DOFs taken as beyond the dense size: shift-invert Lanczos at zero
    # on its stable tangents gives the eigenvalues the dense solver gives (printed to three
    # significant digits), the same limit point, and no descent (dense sizes only).
    from kresling.simulate import fold_stall as module

    monkeypatch.setattr(module, "MAX_MEASURED_DOFS", 10)
    sparse = module.fold_stall(bird)
    found = re.search(r"smallest eigenvalue (\S+) N/mm against (\S+) N/mm at (\S+): a limit "
                      r"point of the rest angles", sparse)
    assert found, sparse
    assert float(found.group(1)) == pytest.approx(_smallest_eigenvalue(bird, -1), rel=5e-3)
    assert sparse.split("; ")[0] == bird.stall.split("; ")[0]
    assert "descending the energy" not in sparse
