"""The limit point of a load-controlled path and its load's derivative
(kresling.solvers.limit_points), against the closed form of the von Mises two-bar truss.

Two bars of the linear law S = C0 E (Green-Lagrange strain) and area A from the supports
(-+a, 0, 0) meet at an apex free in x and z, loaded by P downwards. With rest length L and
c^2 = L^2 - a^2 (the height at which the bars are unstretched; c = h, the rise, when they are
stress-free in the reference), symmetric states with the apex at height w carry

    P(w) = A C0 w (c^2 - w^2) / L^3,

whose maximum, at w = c / sqrt(3), is the limit load P_c = 2 A C0 c^3 / (3 sqrt(3) L^3).
The apex's sideways stiffness there is A C0 (2 a^2 + w^2 - c^2) / L^3 > 0 for a shallow
truss (c < sqrt(3) a), so the symmetric mode is the critical one: a limit point, with
phi . f = 1. A steep truss (c > sqrt(3) a) loses its sideways stiffness first, at
w^2 = c^2 - 2 a^2, a bifurcation whose mode is orthogonal to the load.
"""

import numpy as np
import pytest

from kresling import Design
from kresling.model import Model, kresling_specimen
from kresling.solvers import (Direction, Parameter, energy_derivative, equilibrium_sensitivity,
                              limit_point, solve_displacement_control, solve_force_control,
                              solve_mgdcm, with_parameter)

A_HALF, RISE, C0, AREA = 10.0, 1.0, 1000.0, 1.0
K = 2 / (3 * np.sqrt(3))   # P_c = K A C0 c^3 / L^3
APEX_X, APEX_Z = 6, 8      # DOFs of node 2


def truss(a=A_HALF, h=RISE, rest_length=None):
    nodes = [[-a, 0, 0], [a, 0, 0], [0, 0, h]]
    fixed = [[1, 1, 1], [1, 1, 1], [0, 1, 0]]
    return Model(nodes, [[0, 2], [1, 2]], np.zeros((0, 4), int), bar_modulus=C0,
                 bar_area=AREA, bar_law="linear", hinge_stiffness=np.zeros(0), fixed=fixed,
                 bar_rest_length=rest_length)


def load(model):
    f = np.zeros(model.num_dofs)
    f[APEX_Z] = -1.0   # [N]: the load factor is P
    return f


def closed_form(a=A_HALF, h=RISE, length=None):
    """P_c and its derivatives in C0, A, the bars' rest length L (at fixed a), the rise h
    and the half-span a (both with L following, stress-free)."""
    L = np.hypot(a, h) if length is None else length
    c = np.sqrt(L**2 - a**2)
    Lg = np.hypot(a, h)
    p = K * AREA * C0 * c**3 / L**3
    return p, {"bars.modulus": p / C0, "bars.area": p / AREA,
               "bars.rest_length": 3 * K * AREA * C0 * c * a**2 / L**4,
               "rise": 3 * K * AREA * C0 * h**2 * a**2 / Lg**5,
               "span": -3 * K * AREA * C0 * h**3 * a / Lg**5}


def directions(model):
    """The rise (the apex's z) and the half-span (the supports' x, apart), as moves of the
    reference positions whose rest lengths follow."""
    rise = np.zeros(model.num_dofs)
    rise[APEX_Z] = 1.0
    span = np.zeros(model.num_dofs)
    span[0], span[3] = -1.0, 1.0
    return [Direction("rise", positions=rise), Direction("span", positions=span)]


PARAMETERS = ["bars.modulus", "bars.area", "bars.rest_length"]


@pytest.fixture(scope="module")
def path():
    model = truss()
    # Through the limit point in increments of ~1 % of the rise.
    result = solve_mgdcm(model, load(model), initial_load_factor=0.02, max_step_factor=0.02,
                         max_increments=400, monitor_dof=APEX_Z, max_displacement=0.8 * RISE)
    assert result.completed, result.message
    return model, result


@pytest.fixture(scope="module")
def point(path):
    model, result = path
    return limit_point(model, load(model), result, PARAMETERS + directions(model))


def test_the_limit_point_is_the_closed_forms(point):
    p_c, _ = closed_form()
    # Newton converged to a 1e-10 mm correction in 4 iterations from the path's largest
    # sample (6e-5 below P_c): the load factor is left with the rounding of the bars' force
    # (~5 N) in 1e-16, ~1e-14 of P_c (measured 7e-15); asserted 1e-12.
    assert point.load_factor == pytest.approx(p_c, rel=1e-12)
    assert RISE + point.displacement[APEX_Z] == pytest.approx(RISE / np.sqrt(3), rel=1e-10)
    assert abs(point.displacement[APEX_X]) <= 1e-12
    # The critical mode is the apex going down, the way the load pushes.
    assert point.mode[APEX_Z] == pytest.approx(-1.0, abs=1e-12)
    assert point.load_alignment == pytest.approx(1.0, abs=1e-12)
    assert point.iterations <= 8


def test_the_path_samples_the_limit_load_only_to_its_step(path, point):
    # What the refinement adds: the path's largest sample lies below P_c by O(step^2).
    _, result = path
    p_c, _ = closed_form()
    assert result.load_factor.max() < p_c * (1 - 1e-6)
    assert result.load_factor.max() > p_c * (1 - 1e-2)


def test_the_load_derivative_is_the_closed_forms(point):
    # d lambda_c/dp = phi . dr/dp / phi . f against the closed form's derivatives, to the
    # rounding of the refined state (measured 1e-14 relative; asserted 1e-12).
    _, exact = closed_form()
    for name, value in zip(point.parameters, point.load_factor_derivative):
        assert value == pytest.approx(exact[name], rel=1e-12), name


def _refined(model, start):
    return limit_point(model, load(model), start.displacement,
                       load_factor=start.load_factor, tolerance=1e-13).load_factor


@pytest.mark.parametrize("name, step", [("bars.modulus", 1e-5), ("bars.area", 1e-5),
                                        ("bars.rest_length", 1e-7)])
def test_the_load_derivative_is_the_refined_limit_loads_difference(point, name, step):
    # Central differences of the limit load located again (Newton to a 1e-13 mm
    # correction, the load factor exact to ~1e-14 relative) with the column moved by
    # +-step of its value: rounding ~1e-14 / step, truncation ~step^2 times the load's
    # curvature in p. The rest length enters through c = sqrt(L^2 - a^2), curved by
    # a^2 / c^3 = 100 /mm, so its step is smaller. Measured 1.6e-12 (modulus, area) and
    # 6e-10 (rest length); asserted 1e-7.
    model = truss()
    values = np.asarray(model.family("bars")[name.split(".")[1]], float)
    h = step * values[0]
    plus = _refined(with_parameter(model, name, values + h), point)
    minus = _refined(with_parameter(model, name, values - h), point)
    exact = point.load_factor_derivative[point.parameters.index(name)]
    assert exact == pytest.approx((plus - minus) / (2 * h), rel=1e-7)


@pytest.mark.parametrize("name, moved", [("rise", {"h": 1e-5}), ("span", {"a": 1e-4})])
def test_the_geometric_derivative_is_the_refined_limit_loads_difference(point, name, moved):
    # The same, with the truss rebuilt stress-free with the apex or the supports moved by
    # +-1e-5 of their size (measured 3e-10).
    (key, h), = moved.items()
    base = {"a": A_HALF, "h": RISE}
    plus = _refined(truss(**{**base, key: base[key] + h}), point)
    minus = _refined(truss(**{**base, key: base[key] - h}), point)
    exact = point.load_factor_derivative[point.parameters.index(name)]
    assert exact == pytest.approx((plus - minus) / (2 * h), rel=1e-7)


def test_a_prestressed_truss_limits_at_its_rest_height():
    # Rest lengths 0.5 % longer than the bars: the limit point moves to c / sqrt(3).
    length = 1.005 * np.hypot(A_HALF, RISE)
    model = truss(rest_length=[length, length])
    c = np.sqrt(length**2 - A_HALF**2)
    start = np.zeros(model.num_dofs)
    start[APEX_Z] = 1.05 * c / np.sqrt(3) - RISE   # 5 % above its limit height
    p_c, exact = closed_form(length=length)
    point = limit_point(model, load(model), start, ["bars.rest_length"],
                        load_factor=0.9 * p_c)   # not an equilibrium: Newton needs none
    assert point.load_factor == pytest.approx(p_c, rel=1e-11)
    assert RISE + point.displacement[APEX_Z] == pytest.approx(c / np.sqrt(3), rel=1e-10)
    assert point.load_factor_derivative[0] == pytest.approx(exact["bars.rest_length"],
                                                            rel=1e-10)


def test_a_bifurcation_is_refused():
    # A steep truss (rise 3, half-span 1): the symmetric path loses sideways stiffness at
    # w = sqrt(7) before its load turns at w = sqrt(3); the mode there is the apex moving
    # sideways, orthogonal to the load.
    model = truss(a=1.0, h=3.0)
    path = solve_mgdcm(model, load(model), initial_load_factor=5.0, max_step_factor=5.0,
                       max_increments=400, monitor_dof=APEX_Z, max_displacement=1.0)
    assert path.completed, path.message
    assert (path.negative_eigenvalues > 0).any()
    with pytest.raises(ValueError, match="bifurcation"):
        limit_point(model, load(model), path, ["bars.modulus"])


def test_a_path_without_a_limit_point_is_refused():
    model = truss()
    p_c, _ = closed_form()
    rising = solve_force_control(model, 0.5 * p_c * load(model), 10)
    assert rising.completed
    with pytest.raises(ValueError, match="no limit point"):
        limit_point(model, load(model), rising)
    with pytest.raises(ValueError, match="load_factor = 0.1 is given with a path"):
        limit_point(model, load(model), rising, load_factor=0.1)
    prescribed = np.zeros(model.num_dofs)
    prescribed[APEX_Z] = -0.5
    driven = solve_displacement_control(model, prescribed, 5)
    with pytest.raises(ValueError, match="displacement-controlled path"):
        limit_point(model, load(model), driven)


@pytest.mark.parametrize("kwargs, match", [
    ({"near": np.zeros(9)}, "load_factor is required"),
    ({"near": np.zeros(9), "load_factor": 0.1, "forces": np.zeros(9)}, "forces is zero"),
    ({"near": np.zeros(9), "load_factor": 0.1, "tolerance": 0.0}, "tolerance"),
    ({"near": np.zeros(9), "load_factor": 0.1,
      "parameters": [Direction("d", drive=np.ones(9))]}, "drive"),
])
def test_bad_input_is_named(kwargs, match):
    model = truss()
    arguments = {"forces": load(model), **kwargs}
    with pytest.raises(ValueError, match=match):
        limit_point(model, arguments.pop("forces"), arguments.pop("near"), **arguments)


def test_a_loaded_equilibriums_potential_changes_by_its_partial_derivative():
    # Envelope theorem: along the equilibria under a fixed load the total potential
    # Pi = E - lambda f . u changes by its partial derivative at fixed u alone. For the
    # truss (stress-free, E = A C0 (w^2 - h^2)^2 / (4 L^3)) that is dE/dC0|_u = E / C0.
    # Checked against the closed form, against central differences of Pi over equilibria
    # solved again with C0 moved by +-1e-5 (Newton to 1e-12 mm: error ~1e-9 of the
    # derivative; asserted 1e-7), and against the factorised sensitivity's dE/dp less the
    # load's work on du/dp.
    model = truss()
    p_c, _ = closed_form()
    forces = 0.5 * p_c * load(model)

    def potential(m):
        solved = solve_force_control(m, forces, 4, tolerance=1e-12)
        assert solved.completed
        u = solved.displacement[-1]
        return solved.energy[-1] - forces @ u, u

    _, u = potential(model)
    w = RISE + u[APEX_Z]
    E = AREA * C0 * (w**2 - RISE**2) ** 2 / (4 * np.hypot(A_HALF, RISE) ** 3)
    exact = energy_derivative(model, u, ["bars.modulus"])[0]
    assert exact == pytest.approx(E / C0, rel=1e-10)
    h = 1e-5 * C0
    plus, _ = potential(with_parameter(model, "bars.modulus", [C0 + h] * 2))
    minus, _ = potential(with_parameter(model, "bars.modulus", [C0 - h] * 2))
    assert exact == pytest.approx((plus - minus) / (2 * h), rel=1e-7)
    s = equilibrium_sensitivity(model, u, ["bars.modulus"])
    assert exact == pytest.approx(s.energy[0] - forces @ s.displacement[:, 0], rel=1e-10)
    # The stored energy alone does not obey it: the load's work moves it by a finite part.
    assert abs(s.energy[0] - exact) > 0.1 * abs(exact)


def test_an_unloaded_saddles_energy_derivative():
    # The prestressed truss (rest lengths L longer than the bars) with its apex level with
    # the supports: an unloaded equilibrium with one negative eigenvalue, the saddle between
    # its two stable states, storing E = A C0 c^4 / (4 L^3). Its rest length's derivative
    # dE/dL = A C0 c^2 (L^2 + 3 a^2) / (4 L^4) in closed form and from the factorised
    # sensitivity (the saddle's tangent is regular).
    length = 1.005 * np.hypot(A_HALF, RISE)
    model = truss(rest_length=[length, length])
    c2 = length**2 - A_HALF**2
    u = np.zeros(model.num_dofs)
    u[APEX_Z] = -RISE
    exact = energy_derivative(model, u, ["bars.rest_length"])[0]
    assert exact == pytest.approx(AREA * C0 * c2 * (length**2 + 3 * A_HALF**2)
                                  / (4 * length**4), rel=1e-10)
    s = equilibrium_sensitivity(model, u, ["bars.rest_length"])
    assert s.negative_eigenvalues == 1
    assert exact == pytest.approx(s.energy[0], rel=1e-10)


def test_the_energy_derivative_at_the_limit_point(point):
    # Where the tangent is singular and the factorised sensitivity refuses, the partial
    # derivative is still the closed form's E / C0.
    model = truss()
    w = RISE + point.displacement[APEX_Z]
    E = AREA * C0 * (w**2 - RISE**2) ** 2 / (4 * np.hypot(A_HALF, RISE) ** 3)
    assert energy_derivative(model, point.displacement, ["bars.modulus"])[0] == \
        pytest.approx(E / C0, rel=1e-10)


def test_a_load_derivative_of_the_wrong_shape_is_named():
    model = truss()
    with pytest.raises(ValueError, match="load_derivative has shape"):
        energy_derivative(model, np.zeros(model.num_dofs), ["bars.modulus"],
                          load_derivative=np.zeros((model.num_dofs, 2)))


def test_a_kresling_cells_limit_load_derivative_is_its_difference():
    # One cell (n = 8, lambda = 0.8, Lc = 30 mm) built extended, its base held, its top
    # pushed down by equal forces on its nine nodes: the top's load passes a limit point.
    # The derivatives of the limit load by the hinges' stiffness and the bars' modulus
    # (every entry scaled together) against central differences of the limit point located
    # again (Newton to 1e-12 mm) with each scaled by 1 +- 1e-6: measured 8e-10 relative,
    # asserted 1e-6 (the differences' rounding, 1e-14 / 1e-6, and their truncation).
    design = Design(8, 0.8, 30.0)
    specimen = kresling_specimen(design, ["extended"])
    fixed = np.zeros((specimen.model.num_nodes, 3), bool)
    fixed[specimen.level_nodes(0)] = True
    model = specimen.model.replace(fixed=fixed)
    forces = np.zeros((model.num_nodes, 3))
    forces[specimen.level_nodes(1), 2] = -1.0 / (design.n + 1)
    path = solve_mgdcm(model, forces, initial_load_factor=0.05, max_increments=220)
    assert np.argmax(path.load_factor) < path.num_steps - 1   # the load turned
    names = ["hinges.stiffness", "bars.modulus"]
    columns = [np.asarray(model.family(n.split(".")[0])[n.split(".")[1]], float) for n in names]
    point = limit_point(model, forces, path,
                        [Parameter(*n.split("."), direction=c) for n, c in zip(names, columns)])
    h = 1e-6
    for name, column, exact in zip(names, columns, point.load_factor_derivative):
        moved = [limit_point(with_parameter(model, name, column * (1 + s * h)), forces,
                             point.displacement, load_factor=point.load_factor,
                             tolerance=1e-12).load_factor for s in (1, -1)]
        assert exact == pytest.approx((moved[0] - moved[1]) / (2 * h), rel=1e-6), name


def test_a_large_models_starting_mode_comes_from_sparse_iterations(monkeypatch):
    # Above a size the starting mode is the sparse shift-invert eigenvector nearest zero
    # instead of the dense one's: the same limit point, to Newton's precision.
    import kresling.solvers.limit_points as limit_points

    model = truss()
    start = np.zeros(model.num_dofs)
    start[APEX_Z] = 0.6 - RISE
    dense = limit_point(model, load(model), start, ["bars.modulus"], load_factor=0.37)
    monkeypatch.setattr(limit_points, "_DENSE_EIGEN", 0)
    sparse = limit_point(model, load(model), start, ["bars.modulus"], load_factor=0.37)
    assert sparse.load_factor == pytest.approx(dense.load_factor, rel=1e-13)
    assert sparse.load_factor_derivative == pytest.approx(dense.load_factor_derivative,
                                                          rel=1e-12)
