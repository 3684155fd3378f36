"""Contact with rigid planes: the barrier family ("contact") through the assembly, the
path follower, time integration and problem files ([contact]).

References: the barrier kernels are compared with ipctk and finite differences in
tests/elements/test_contact_kernels.py; here the checks are of equilibrium (forces balance to the
Newton tolerance) and of the one property contact must have: no node ever passes a plane,
at any converged step, while the same problem without [contact] does pass it."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.model import Model
from kresling.simulate import load_problem, simulate
from kresling.simulate.problem_keys.contact import auto_barrier_stiffness
from kresling.solvers import solve_dynamics, solve_force_control

FLOOR = {"origin": [[0.0, 0.0, 0.0]], "normal": [[0.0, 0.0, 1.0]]}


def _node(z=1.0, k=(1.0, 1.0, 1.0), d_hat=0.2, kappa=100.0, contact=True):
    families = {"springs": {"nodes": [0], "stiffness": [list(k)], "anchor": [[0.0, 0.0, z]]}}
    if contact:
        families["contact"] = dict(FLOOR, nodes=[0], distance=[d_hat], stiffness=[kappa])
    return Model([[0.0, 0.0, z]], [], [], bar_modulus=1.0, hinge_stiffness=1.0,
                 families=families)


@pytest.mark.parametrize("steps", [1, 10])
def test_a_node_pushed_onto_the_floor_stops_above_it_and_the_forces_balance(steps):
    # Spring k = 1 N/mm holding the node 1 mm above the floor, pushed down by 3 N: free, it
    # would end 2 mm below the floor. With the barrier it stops within d_hat of it, even
    # when pushed there in one step.
    path = solve_force_control(_node(), [0.0, 0.0, -3.0], steps, tolerance=1e-10)
    assert path.completed, path.message
    z = 1.0 + path.displacement[:, 2]
    assert (z > 0).all()
    assert 0.0 < z[-1] < 0.2
    # At rest the barrier carries what the spring does not: F - k (1 - z).
    contact_force = assemble(_node(), path.displacement[-1]).force[2] - (-(1.0 - z[-1]))
    assert -contact_force == pytest.approx(3.0 - (1.0 - z[-1]), rel=1e-6)
    assert path.energy_of("contact")[-1] > 0


def test_without_contact_the_same_node_passes_through_the_floor():
    path = solve_force_control(_node(contact=False), [0.0, 0.0, -3.0], 10)
    assert path.completed
    assert 1.0 + path.displacement[-1, 2] == pytest.approx(-2.0, abs=1e-9)


def test_a_mass_dropped_on_the_floor_rests_on_it_carrying_its_weight():
    # A 1 g mass (1e-3 t) 2 mm above the floor, held sideways by springs, falls under
    # gravity with damping: it comes to rest within d_hat of the floor, the barrier's force
    # equal to its weight (9.81 N), and never below the floor on the way.
    model = _node(z=2.0, k=(1.0, 1.0, 0.0), d_hat=0.5, kappa=1e3)
    h = solve_dynamics(model, [1e-3], 2e-3, 1.5, gravity=(0.0, 0.0, -9810.0),
                       mass_damping=40.0, tolerance=1e-10)
    assert h.completed, h.path.message
    z = 2.0 + h.path.displacement[:, 2]
    assert z.min() > 0.0
    assert 0.0 < z[-1] < 0.5
    floor_force = -assemble(model, h.path.displacement[-1]).force[2]
    assert floor_force == pytest.approx(9.81, rel=1e-6)  # upwards, the weight
    assert h.kinetic[-1] < 1e-9


def test_a_time_step_whose_predictor_would_jump_the_floor_stops_above_it():
    # The node 1 mm above the floor moving down at 5,000 mm/s: each time step's predictor
    # (u + dt v + ...) would put it 4 mm below. The predictor is shortened by the same
    # collision check as Newton's corrections, so the node stops above the floor; started
    # on its far side, Newton would settle there (the barrier is of the distance's square).
    model = _node(z=1.0, k=(1.0, 1.0, 0.0), d_hat=0.5, kappa=1e3)
    h = solve_dynamics(model, [1e-3], 1e-3, 0.05, initial_velocity=[0.0, 0.0, -5000.0],
                       mass_damping=40.0, tolerance=1e-10)
    assert h.completed, h.path.message
    z = 1.0 + h.path.displacement[:, 2]
    assert z.min() > 0.0
    assert z[0] < 1.0  # it did move toward the floor


SHEET = {"vertices": [[0, 0, 1], [10, 0, 1], [10, 10, 1], [0, 10, 1]], "panels": [[0, 1, 2, 3]]}


def _problem(contact):
    data = {"pattern": dict(SHEET, split="N4B5"),
            "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                         "fold_stiffness": 0.1, "bend_stiffness": 0.1},
            "support": [{"nodes": [0, 1], "fix": "xyz"}, {"node": 3, "fix": "x"}],
            "load": [{"node": 2, "displacement": [0.0, 0.0, -3.0]}],
            "analysis": {"method": "displacement_control", "steps": 10}}
    if contact:
        data["contact"] = contact
    return data


def test_a_problem_file_floor_reports_min_gap_and_contact_energy():
    # The sheet 1 mm above a floor, its corner 3 mm down: the panel's free corner (node 3)
    # follows it down until the floor stops it.
    sim = simulate(_problem({"distance": 0.3, "planes": [{"point": [0, 0, 0],
                                                           "normal": [0, 0, 1]}]}),
                   progress=False)
    columns = sim.history_columns()
    assert "min_gap" in columns and "energy_contact" in columns
    assert (columns["min_gap"] > 0).all()
    assert columns["energy_contact"][-1] > 0


@pytest.mark.parametrize("contact, message", [
    ({"planes": [{"point": [0, 0, 0], "normal": [0, 0, 1]}]}, "'distance' is missing"),
    ({"distance": 0.3}, "'planes' is missing"),
    ({"distance": 0.3, "planes": []}, "non-empty"),
    ({"distance": 0.3, "planes": [{"point": [0, 0, 0], "normal": [0, 0, 0]}]}, "not be zero"),
    ({"distance": 0.3, "self": "yes", "planes": [{"point": [0, 0, 0], "normal": [0, 0, 1]}]},
     "'self'"),
    ({"distance": -1.0, "planes": [{"point": [0, 0, 0], "normal": [0, 0, 1]}]}, "must be > 0"),
    ({"distance": 0.3, "stiffness": "soft", "planes": [{"point": [0, 0, 0],
                                                        "normal": [0, 0, 1]}]}, "stiffness"),
])
def test_bad_contact_tables_name_the_key(contact, message):
    with pytest.raises(ValueError, match=message):
        load_problem(_problem(contact))


def test_the_auto_stiffness_matches_the_structure_at_half_the_distance():
    # kappa d2/dd2 b(d^2) at d = d_hat / 2 equals the stiffness it is given.
    d_hat, k = 0.4, 250.0
    kappa = auto_barrier_stiffness(k, d_hat)
    b = lambda d: -(d**2 - d_hat**2) ** 2 * np.log(d**2 / d_hat**2)  # noqa: E731
    h, d = 1e-5, d_hat / 2
    second = (b(d + h) - 2 * b(d) + b(d - h)) / h**2
    assert kappa * second == pytest.approx(k, rel=1e-5)
