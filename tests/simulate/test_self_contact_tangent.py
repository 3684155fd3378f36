"""``[contact] tangent``: how the panel pairs' Hessians enter Newton's tangent: projected
onto the positive semi-definite cone, exact, or adaptive (the default: exact where the
whole tangent is positive definite, projected at the iterates where it is not).

Independent references: the equilibria do not depend on the tangent (each run converges to
the Newton tolerance), and the stability of a converged state is read off the eigenvalues of
the exact tangent there, assembled afresh by numpy-side code (a dense symmetric eigensolver
on the free DOFs), not from any solver's report."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.simulate import load_problem, simulate
from test_self_contact import _square_twist, _strip, _twist_problem


def _with_tangent(data, tangent):
    data["contact"]["tangent"] = tangent
    return data


def test_every_tangent_reaches_the_same_fold_and_the_exact_ones_in_fewer_iterations():
    runs = {tangent: simulate(_with_tangent(_strip(contact=True, angle=150.0), tangent),
                              progress=False)
            for tangent in ("projected", "exact", "adaptive")}
    assert all(sim.path.completed for sim in runs.values())
    # The family's column: the form's code, none for the default (adaptive).
    assert runs["projected"].model.family("self_contact")["tangent"].tolist() == [0.0]
    assert runs["exact"].model.family("self_contact")["tangent"].tolist() == [1.0]
    assert "tangent" not in runs["adaptive"].model.family("self_contact")
    # The same equilibria: each run stops within its last correction (at most the 1e-6 mm
    # tolerance) of the equilibrium, so they agree to 2e-6 mm (measured 1.1e-9 mm).
    for tangent in ("exact", "adaptive"):
        np.testing.assert_allclose(runs[tangent].path.displacement,
                                   runs["projected"].path.displacement, rtol=0, atol=2e-6)
    # In the last eight increments the panels touch: Newton converges quadratically there
    # with the exact tangent, only linearly with the projected one.
    projected = runs["projected"].path.iterations[-8:].sum()
    assert runs["exact"].path.iterations[-8:].sum() < projected
    assert runs["adaptive"].path.iterations[-8:].sum() < projected


def _unstable_increments(sim):
    """The increments whose converged state has a negative eigenvalue of the exact tangent
    (the model at that increment's rest angles, the pairs' Hessians exact), with their
    counts: {increment: count}."""
    exact = sim.model.with_families({"self_contact": dict(
        sim.model.family("self_contact"), tangent=np.array([1.0]))})
    hinges, targets = sim.fold.stages[0]
    start = np.asarray(exact.hinge_rest_angle)
    free = np.asarray(exact.free_dofs)
    out = {}
    for k, (u, t) in enumerate(zip(sim.path.displacement, sim.path.load_factor)):
        rest = start.copy()
        rest[hinges] = start[hinges] + t * (np.asarray(targets) - start[hinges])
        K = assemble(exact.replace(hinge_rest_angle=rest), u).stiffness.toarray()
        eigenvalues = np.linalg.eigvalsh(K[np.ix_(free, free)])
        count = int(np.sum(eigenvalues < -1e-9 * np.abs(eigenvalues).max()))
        if count:
            out[k + 1] = count
    return out


def test_the_adaptive_tangent_keeps_a_square_twist_on_stable_equilibria(tmp_path):
    path = _square_twist(tmp_path, twist_deg=20.0)
    exact = simulate(_with_tangent(_twist_problem(path, contact=True), "exact"), progress=False)
    adaptive = simulate(_twist_problem(path, contact=True), progress=False)
    assert exact.path.completed and adaptive.path.completed
    # With the exact tangent, Newton lands on unstable equilibria on the way (measured: 1 or
    # 2 negative eigenvalues at increments 22, 24, 25 and 26)...
    assert len(_unstable_increments(exact)) >= 2
    # ...which the adaptive one, projecting where the exact tangent is indefinite, avoids:
    # every state it converges to is stable.
    assert _unstable_increments(adaptive) == {}


def test_a_bad_tangent_names_the_key():
    with pytest.raises(ValueError, match="tangent"):
        load_problem(_with_tangent(_strip(contact=True), "newton"))
