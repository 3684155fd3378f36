"""A Kresling cell dropped on a rigid floor (examples/cell_on_floor/problem.toml): the
contact family's plane under time integration, with the cell's mass from its laminate.

References, each independent of the contact family's code: the cell's mass is the
laminate's areal density times its triangles' area; before it touches, the cell falls as a
rigid body under gravity and linear drag (closed form); the floor's reaction is the barrier's
closed-form force ``-kappa d/dd b(d^2)`` summed over the nodes within d_hat; at rest it is
the weight, less what the remaining motion still takes (``M a + C v``, from the recorded
velocities)."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling.model.masses import lumped_masses
from kresling.simulate import load_problem, simulate

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "cell_on_floor" / "problem.toml"
GRAVITY = 9810.0  # mm/s^2


@pytest.fixture(scope="module")
def drop():
    return simulate(EXAMPLE, progress=False)


@pytest.fixture(scope="module")
def columns(drop):
    return drop.history_columns()


def _floor(drop):
    """The floor's height [mm] and the contact table's d_hat [mm] and kappa [N/mm^3]."""
    table = drop.model.family("contact")
    return (float(table["origin"][0, 2]), float(table["distance"][0]),
            float(table["stiffness"][0]))


def _heights(drop):
    """Every node's height at every step [mm], shape (S, N)."""
    return drop.model.nodes[:, 2][None, :] + drop.path.displacement[:, 2::3]


def test_the_cell_weighs_its_laminate(drop):
    # rho t times the area of the model's triangles: 0.30 mm of PET (1.38e-9 t/mm^3).
    problem = load_problem(EXAMPLE)
    nodes = drop.model.nodes
    tri = np.asarray(drop.pattern_model.elements.triangles)
    area = 0.5 * np.linalg.norm(np.cross(nodes[tri[:, 1]] - nodes[tri[:, 0]],
                                         nodes[tri[:, 2]] - nodes[tri[:, 0]]), axis=1).sum()
    assert drop.masses.sum() == pytest.approx(1.38e-9 * 0.30 * area, rel=1e-12)
    np.testing.assert_allclose(drop.masses, lumped_masses(drop.pattern_model, 0.30, 1.38e-9),
                               rtol=1e-12)
    assert problem.dynamics.gravity == pytest.approx((0.0, 0.0, -GRAVITY))
    assert drop.model.fixed.sum() == 0  # unsupported: only the floor holds it


def test_no_node_ever_passes_the_floor_and_min_gap_is_the_nearest_node(drop, columns):
    assert drop.completed, drop.path.message
    floor, d_hat, _ = _floor(drop)
    gap = _heights(drop) - floor
    assert (gap > 0).all()
    assert (columns["min_gap"] > 0).all()
    # Every node against one plane: min_gap is the lowest node's height above it (1e-12 mm:
    # the same subtraction in another order).
    np.testing.assert_allclose(columns["min_gap"], gap.min(axis=1), rtol=0, atol=1e-12)
    # It did touch: the nearest node went well inside d_hat.
    assert columns["min_gap"].min() < 0.5 * d_hat


def test_before_it_touches_the_cell_falls_as_a_body_under_drag(drop, columns):
    # z(t) = -(g / alpha) (t - (1 - exp(-alpha t)) / alpha) for a body released at rest
    # with mass-proportional damping alpha. The cell's mean displacement follows it to
    # 1e-3 mm (HHT-alpha's O(dt^2) error over the 68 ms fall in 0.5 ms steps: measured
    # 1.2e-4 mm), while the reaction is zero.
    alpha, t = load_problem(EXAMPLE).dynamics.alpha, drop.history.time
    touch = int(np.argmax(columns["reaction_planes_z"] > 0))
    assert touch > 0 and (columns["reaction_planes_z"][:touch] == 0).all()
    closed = -(GRAVITY / alpha) * (t - (1 - np.exp(-alpha * t)) / alpha)
    mean = drop.path.displacement[:touch, 2::3] @ drop.masses / drop.masses.sum()
    np.testing.assert_allclose(mean, closed[:touch], rtol=0, atol=1e-3)


def test_the_reaction_is_the_barriers_closed_form_force(drop, columns):
    # -kappa d/dd [-(d^2 - d_hat^2)^2 ln(d^2 / d_hat^2)] at each node within d_hat, summed;
    # to 1e-10 of the peak (the same formula, evaluated in another order).
    floor, d_hat, kappa = _floor(drop)
    d = _heights(drop) - floor
    s, s_hat = d ** 2, d_hat ** 2
    near = d < d_hat
    db_ds = np.where(near, -2 * (s - s_hat) * np.log(np.where(near, s / s_hat, 1.0))
                     - (s - s_hat) ** 2 / s, 0.0)
    closed = (-kappa * db_ds * 2 * d).sum(axis=1)
    reaction = columns["reaction_planes_z"]
    np.testing.assert_allclose(reaction, closed, rtol=0, atol=1e-10 * reaction.max())
    # A floor pushes up, never sideways.
    assert (reaction >= 0).all()
    assert np.abs(columns["reaction_planes_x"]).max() == 0.0
    assert np.abs(columns["reaction_planes_y"]).max() == 0.0


def test_at_rest_the_floor_carries_the_weight(drop, columns):
    # At the last step the cell rests on the floor: the floor's force is m g less the force
    # its remaining motion takes, sum_z M (a + alpha v), a from the last two velocities:
    # below 2e-6 of the weight (measured 6.3e-7). HHT-alpha balances the forces at a point
    # between the last two steps, so the reaction is m g to a few times that: 1e-5 m g
    # asserted (measured 1.0e-6).
    floor, d_hat, _ = _floor(drop)
    h, masses = drop.history, drop.masses
    weight = masses.sum() * GRAVITY
    alpha = load_problem(EXAMPLE).dynamics.alpha
    v = h.velocity[:, 2::3]
    a = (v[-1] - v[-2]) / (h.time[-1] - h.time[-2])
    assert abs(masses @ (a + alpha * v[-1])) < 2e-6 * weight
    assert columns["reaction_planes_z"][-1] == pytest.approx(weight, rel=1e-5)
    assert h.kinetic[-1] < 1e-10
    assert 0 < columns["min_gap"][-1] < d_hat
    # Upright: the top polygon still 55.8 mm above the bottom, level to 1e-3 mm.
    z = _heights(drop)[-1]
    assert np.ptp(z[:10]) < 1e-3 and np.ptp(z[10:20]) < 1e-3
    assert z[10:20].mean() - z[:10].mean() == pytest.approx(55.82, abs=0.02)


def test_without_the_floor_the_cell_falls_through_it():
    problem = load_problem(EXAMPLE)
    problem = problem.replace(contact=None)
    free = simulate(problem, progress=False)
    assert free.completed
    z = free.model.nodes[:, 2] + free.path.displacement[-1, 2::3]
    assert z.max() < -10.0  # the whole cell below where the floor was


def test_kresling_simulate_writes_the_reaction_column(tmp_path, columns):
    result = run_kresling("simulate", str(EXAMPLE), "--out", str(tmp_path), "--quiet",
                          "--no-view", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    with (tmp_path / "history.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 1200
    for name in ("min_gap", "reaction_planes_z", "energy_contact"):
        written = np.array([float(row[name]) for row in rows])
        np.testing.assert_allclose(written, columns[name], rtol=1e-12)
