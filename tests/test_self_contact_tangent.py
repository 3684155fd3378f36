"""``[contact] tangent = "exact"``: the panel pairs' exact Hessians in Newton's tangent
instead of their positive semi-definite projections. The equilibria are the same (to the
Newton tolerance); Newton needs fewer iterations where pairs act."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.simulate import load_problem, simulate
from test_self_contact import _strip


def _with_tangent(tangent):
    data = _strip(contact=True, angle=150.0)
    data["contact"]["tangent"] = tangent
    return data


def test_the_exact_tangent_reaches_the_same_fold_in_fewer_iterations():
    projected = simulate(_with_tangent("projected"), progress=False)
    exact = simulate(_with_tangent("exact"), progress=False)
    assert projected.completed and exact.completed
    assert "exact_tangent" in exact.model.family("self_contact")
    assert "exact_tangent" not in projected.model.family("self_contact")
    # The same equilibria: each run stops within its last correction (at most the 1e-6 mm
    # tolerance) of the equilibrium, so they agree to 2e-6 mm (measured 1.1e-9 mm).
    np.testing.assert_allclose(exact.path.displacement, projected.path.displacement,
                               rtol=0, atol=2e-6)
    # In the last eight increments the panels touch: Newton converges quadratically there
    # with the exact tangent, only linearly with the projected one.
    assert exact.path.iterations[-8:].sum() < projected.path.iterations[-8:].sum()


def test_a_bad_tangent_names_the_key():
    with pytest.raises(ValueError, match="tangent"):
        load_problem(_with_tangent("newton"))
