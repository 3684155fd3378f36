"""Panel contact under every solver: force control, MGDCM (whose corrector solves the load
factor with the displacements) and the adaptive increments (whose predictors and samples
are read off curves between converged points) keep the panels apart at every recorded
state, where the same runs without contact pass them through each other.

Independent reference: every recorded state is checked for intersecting triangles by a
separate segment-triangle test (tests/triangle_intersection_helpers.py), which knows
nothing of the contact family's distances or collision checks."""

from __future__ import annotations

import pytest

from kresling.simulate import simulate
from test_self_contact import _positions, _strip
from triangle_intersection_helpers import intersecting_pairs


def _intersecting_increments(sim):
    triangles = sim.pattern_model.elements.triangles
    return [k + 1 for k in range(sim.path.num_steps)
            if intersecting_pairs(_positions(sim, k), triangles)]


def _pushed(contact, method):
    """The strip of three panels, its middle one held, the outer panels' free edges pushed
    up and towards each other by 1 N per node at 45 deg: each outer panel turns about its
    crease towards 135 deg, where the force lies along it, so that (200 deg and more in
    all) their free edges cross unless contact holds them apart."""
    data = _strip(contact)
    del data["actuation"]
    data["load"] = [{"nodes": [0, 7], "force": [1.0, 0.0, 1.0]},
                    {"nodes": [3, 4], "force": [-1.0, 0.0, 1.0]}]
    if method == "mgdcm":
        data["analysis"] = {"method": "mgdcm", "initial_load_factor": 0.05,
                            "max_load_factor": 1.0, "max_increments": 400}
    else:
        data["analysis"] = {"method": method, "steps": 20}
    return data


@pytest.mark.parametrize("method", ["force_control", "mgdcm"])
def test_a_load_that_pushes_panels_through_each_other_is_held_by_contact(method):
    free = simulate(_pushed(contact=False, method=method), progress=False)
    assert free.completed, free.path.message
    assert _intersecting_increments(free)  # so the check below can fail
    sim = simulate(_pushed(contact=True, method=method), progress=False)
    assert sim.completed, sim.path.message
    assert sim.path.load_factor[-1] >= 1.0  # the whole load carried
    assert _intersecting_increments(sim) == []
    assert (sim.history_columns()["min_gap"] > 0).all()


def test_adaptive_increments_of_a_fold_keep_the_panels_apart_at_every_sample():
    # The strip folded to 150 deg a crease: its outer panels would cross in the last eight
    # samples. The adaptive increments' predictors and their samples inside an increment
    # are moves too: each is limited by the collision check.
    problem = _strip(contact=False, angle=150.0)
    problem["analysis"]["increments"] = "adaptive"
    free = simulate(problem, progress=False)
    assert free.path.completed, free.path.message
    assert len(_intersecting_increments(free)) >= 8
    problem = _strip(contact=True, angle=150.0)
    problem["analysis"]["increments"] = "adaptive"
    sim = simulate(problem, progress=False)
    assert sim.path.completed, sim.path.message
    # Followed by the adaptive increments themselves: a stage they could not finish would
    # be followed again in fixed increments, the fixed run's path and iterations.
    problem["analysis"]["increments"] = "fixed"
    fixed = simulate(problem, progress=False)
    assert list(sim.path.iterations) != list(fixed.path.iterations)
    assert _intersecting_increments(sim) == []
    assert (sim.history_columns()["min_gap"] > 0).all()
