"""Zero-length springs to fixed points: the family through the Python Model, the assembly,
the solvers and problem files ([[spring]]).

Tolerances: the springs are linear and exact; 1e-9 covers Newton's 1e-6 mm tolerance on
models whose stiffness is O(1-1000) N/mm only where a solve is involved (1e-6 mm times
1e3 N/mm = 1e-3 N is the worst force error; every check below is on an equilibrium of
stiffer terms or states its bound)."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.assembly import assemble
from kresling.model import Model, family_kinds
from kresling.simulate import load_problem, simulate
from kresling.solvers import solve_force_control


def _one_node(k=(10.0, 20.0, 40.0), anchor=(0.0, 0.0, 0.0)):
    return Model([[0.0, 0.0, 0.0]], [], [], bar_modulus=1.0, hinge_stiffness=1.0,
                 families={"springs": {"nodes": [0], "stiffness": [list(k)],
                                       "anchor": [list(anchor)]}})


def test_the_family_is_registered_and_read_back():
    assert "springs" in family_kinds()
    model = _one_node()
    assert model.families == ("bars", "hinges", "cables", "springs")
    springs = model.family("springs")
    np.testing.assert_array_equal(springs["stiffness"], [[10.0, 20.0, 40.0]])
    # replace() keeps the family.
    assert model.replace(fixed=np.zeros((1, 3), bool)).family("springs")["nodes"].tolist() == [0]


def test_energy_force_and_tangent_are_the_closed_form():
    model = _one_node(anchor=(1.0, -1.0, 0.5))
    u = np.array([2.0, 1.0, 0.0])
    a = assemble(model, u)
    d = u - np.array([1.0, -1.0, 0.5])
    k = np.array([10.0, 20.0, 40.0])
    assert a.energies["springs"] == pytest.approx(0.5 * np.dot(k * d, d), rel=1e-15)
    np.testing.assert_allclose(a.force, k * d, rtol=1e-15)
    np.testing.assert_allclose(a.stiffness.toarray(), np.diag(k), rtol=1e-15)


def test_a_node_on_springs_deflects_by_force_over_stiffness():
    path = solve_force_control(_one_node(), [1.0, -2.0, 4.0], 1)
    assert path.completed
    np.testing.assert_allclose(path.displacement[-1], [0.1, -0.1, 0.1], atol=1e-12)
    assert path.families[-1] == "springs"
    assert path.energy_of("springs")[-1] == pytest.approx(0.5 * (0.1 + 0.2 + 0.4), rel=1e-12)


def test_bad_springs_are_refused_naming_the_column():
    with pytest.raises(ValueError, match="springs.stiffness"):
        Model([[0.0, 0.0, 0.0]], [], [], bar_modulus=1.0, hinge_stiffness=1.0,
              families={"springs": {"nodes": [0], "stiffness": [1.0], "anchor": [[0, 0, 0]]}})
    with pytest.raises(ValueError, match="spring 0 .* stiffness"):
        _one_node(k=(1.0, -1.0, 1.0))
    with pytest.raises(ValueError, match="unknown"):
        Model([[0.0, 0.0, 0.0]], [], [], bar_modulus=1.0, hinge_stiffness=1.0,
              families={"dampers": {"nodes": [0]}})


TRIANGLE = {
    "pattern": {"vertices": [[0, 0, 0], [10, 0, 0], [0, 10, 0]], "panels": [[0, 1, 2]]},
    "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0},
    "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"}, {"node": 2, "fix": "z"}],
    "analysis": {"method": "force_control", "steps": 2},
}


def test_a_problem_file_spring_pulls_the_pattern_and_the_forces_balance():
    # Node 2 is pulled by a spring towards a point 1 mm to its right (+x); the supports take
    # the pull. At equilibrium the support reactions in x balance the spring's force.
    data = dict(TRIANGLE, spring=[{"node": 2, "stiffness": [5.0, 0.0, 0.0],
                                   "anchor": [1.0, 10.0, 0.0]}],
                load=[{"node": 2, "force": [0.0, 0.1, 0.0]}])
    problem = load_problem(data)
    assert problem.springs[0].stiffness == (5.0, 0.0, 0.0)
    sim = simulate(problem, progress=False)
    assert sim.completed
    u = sim.path.displacement[-1].reshape(-1, 3)
    spring_force = 5.0 * (1.0 - u[2, 0])  # on node 2, +x
    assert 0.0 < u[2, 0] < 1.0
    reactions = sim.path.constraint_force[-1]
    x_rows = [k for k, dof in enumerate(sim.path.constraint_dofs) if dof % 3 == 0]
    # The support reactions (f_int there) hold the sheet against the pull: with no other
    # force along x, they and the spring's pull sum to zero.
    assert reactions[x_rows].sum() == pytest.approx(-spring_force, rel=1e-9)


def test_a_spring_without_an_anchor_ties_the_node_where_it_is():
    data = dict(TRIANGLE, spring=[{"nodes": [2], "stiffness": 3.0}],
                load=[{"node": 2, "force": [0.0, 0.3, 0.0]}])
    sim = simulate(data, progress=False)
    np.testing.assert_array_equal(sim.model.family("springs")["anchor"], [[0.0, 10.0, 0.0]])
    assert sim.completed


@pytest.mark.parametrize("entry, message", [
    ({"node": 2, "stiffness": [1.0, -1.0, 0.0]}, "must be >= 0"),
    ({"node": 7, "stiffness": 1.0}, "out of range"),
    ({"node": 2}, "'stiffness' is missing"),
    ({"node": 2, "stiffness": 1.0, "anchor": [0, 0]}, "must be 3 numbers"),
    ({"node": 2, "stiffness": 1.0, "colour": "red"}, "'colour' is unknown"),
])
def test_bad_spring_entries_name_the_key(entry, message):
    data = dict(TRIANGLE, spring=[entry], load=[{"node": 2, "force": [0.0, 0.3, 0.0]}])
    with pytest.raises(ValueError, match=message):
        load_problem(data)


def test_the_history_reports_the_springs_energy_in_the_total():
    data = dict(TRIANGLE, spring=[{"node": 2, "stiffness": [5.0, 0.0, 0.0],
                                   "anchor": [1.0, 10.0, 0.0]}],
                load=[{"node": 2, "force": [0.0, 0.1, 0.0]}])
    columns = simulate(data, progress=False).history_columns()
    names = [k for k in columns if k.startswith("energy_")]
    assert names[-2:] == ["energy_springs", "energy_total"]
    parts = sum(columns[k] for k in names[:-1])
    np.testing.assert_allclose(columns["energy_total"], parts, rtol=1e-14)
    assert columns["energy_springs"][-1] > 0
