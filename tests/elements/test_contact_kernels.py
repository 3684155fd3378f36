"""The contact kernels of the C++ core (distances, IPC barrier, stiffness, CCD, broad phase)
against an independent implementation (the ``ipctk`` package, IPC Toolkit's Python
bindings) and against finite differences."""

import numpy as np
import pytest

from kresling._core import contact as core

D_HAT = 0.3
KAPPA = 7.0
# Both sides evaluate the same closed forms in double precision, in a different order:
# agreement is expected to ~1e-14 relative; 1e-10 is the bound the comparison is held to.
IPC_RTOL = 1e-10
# Central differences with h = 1e-6 on O(1) geometry: truncation ~h^2 and rounding
# ~1e-16 / h = 1e-10 relative to the derivative's scale, so 1e-6 leaves headroom.
FD_STEP = 1e-6
FD_RTOL = 1e-6


def _ipctk():
    return pytest.importorskip(
        "ipctk", reason="ipctk (IPC Toolkit's Python bindings) is not installed for this "
        "Python: the comparison with an independent implementation is skipped")


def _relative(ours, theirs):
    ours, theirs = np.asarray(ours, float), np.asarray(theirs, float)
    return np.linalg.norm(ours - theirs) / max(np.linalg.norm(theirs), 1e-300)


def _active_pairs(distance2, count, seed):
    """Random four-point configurations whose squared distance lies in (0.05, 0.9) d_hat^2,
    where the barrier acts (the same range the C++ tests use)."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        x = rng.uniform(-1, 1, size=(4, 3))
        if 0.05 < distance2(x) / D_HAT**2 < 0.9:
            out.append(x)
    return out


def _pt_distance2(x):
    return core.point_triangle_distance(*x)[0]


def _ee_distance2(x):
    return core.edge_edge_distance(*x)[0]


def _finite_differences(f, x, h=FD_STEP):
    """Gradient from f's values and Hessian from its gradients, by central differences."""
    x = np.asarray(x, float).ravel()
    gradient, hessian = np.zeros(x.size), np.zeros((x.size, x.size))
    for k in range(x.size):
        step = np.zeros(x.size)
        step[k] = h
        plus, minus = f(x + step), f(x - step)
        gradient[k] = (plus[0] - minus[0]) / (2 * h)
        hessian[:, k] = (plus[1] - minus[1]) / (2 * h)
    return gradient, hessian


def test_distances_agree_with_ipctk():
    ipctk = _ipctk()
    rng = np.random.default_rng(1)
    for _ in range(300):
        x = rng.uniform(-1, 1, size=(4, 3))
        value, gradient, hessian, code = core.point_triangle_distance(*x)
        assert code == int(ipctk.point_triangle_distance_type(*x).value)
        assert value == pytest.approx(ipctk.point_triangle_distance(*x), rel=IPC_RTOL)
        assert _relative(gradient, ipctk.point_triangle_distance_gradient(*x)) < IPC_RTOL
        assert _relative(hessian, ipctk.point_triangle_distance_hessian(*x)) < IPC_RTOL
        value, gradient, hessian, code = core.edge_edge_distance(*x)
        assert code == int(ipctk.edge_edge_distance_type(*x).value)
        assert value == pytest.approx(ipctk.edge_edge_distance(*x), rel=IPC_RTOL)
        assert _relative(gradient, ipctk.edge_edge_distance_gradient(*x)) < IPC_RTOL
        assert _relative(hessian, ipctk.edge_edge_distance_hessian(*x)) < IPC_RTOL


# ipctk keeps a face-vertex collision for the triangle's interior only: a pair whose closest
# features are an edge or a vertex becomes an edge-vertex or vertex-vertex collision, as its
# collision builder makes them. Per type code: the collision and the slots of its stencil's
# nodes among (p, t0, t1, t2).
def _ipc_point_triangle_collision(ipctk, code):
    if code <= 2:  # P_T0, P_T1, P_T2
        return ipctk.VertexVertexNormalCollision(0, 1), [0, code + 1]
    if code <= 5:  # P_E0 (t0 t1), P_E1 (t1 t2), P_E2 (t2 t0)
        return ipctk.EdgeVertexNormalCollision(0, 0), [0] + [[1, 2], [2, 3], [3, 1]][code - 3]
    return ipctk.FaceVertexNormalCollision(0, 0), [0, 1, 2, 3]


def _scatter(slots, gradient, hessian):
    """A stencil's gradient and Hessian placed among the 12 coordinates of (p, t0, t1, t2)."""
    index = np.concatenate([np.arange(3 * s, 3 * s + 3) for s in slots])
    g, h = np.zeros(12), np.zeros((12, 12))
    g[index] = gradient
    h[np.ix_(index, index)] = hessian
    return g, h


@pytest.mark.parametrize("project", [False, True])
def test_point_triangle_barrier_agrees_with_ipctk(project):
    ipctk = _ipctk()
    potential = ipctk.BarrierPotential(D_HAT, KAPPA)
    method = ipctk.PSDProjectionMethod.CLAMP if project else ipctk.PSDProjectionMethod.NONE
    codes = set()
    for x in _active_pairs(_pt_distance2, 300, seed=2):
        energy, gradient, hessian = core.point_triangle_barrier(*x, D_HAT, KAPPA, project)
        code = core.point_triangle_distance(*x)[3]
        codes.add(code)
        collision, slots = _ipc_point_triangle_collision(ipctk, code)
        stencil = x[slots].ravel()
        theirs_g, theirs_h = _scatter(slots, potential.gradient(collision, stencil),
                                      potential.hessian(collision, stencil, method))
        assert energy == pytest.approx(potential(collision, stencil), rel=IPC_RTOL)
        assert _relative(gradient, theirs_g) < IPC_RTOL
        assert _relative(hessian, theirs_h) < IPC_RTOL
    assert codes == set(range(7))  # every kind of closest features was compared


@pytest.mark.parametrize("project", [False, True])
def test_edge_edge_barrier_agrees_with_ipctk(project):
    ipctk = _ipctk()
    potential = ipctk.BarrierPotential(D_HAT, KAPPA)
    method = ipctk.PSDProjectionMethod.CLAMP if project else ipctk.PSDProjectionMethod.NONE
    mollified, codes = 0, set()
    for k, x in enumerate(_active_pairs(_ee_distance2, 400, seed=3)):
        codes.add(core.edge_edge_distance(*x)[3])
        # Thresholds above and below the pair's |ua x ub|^2: half the pairs are mollified.
        cross2 = ipctk.edge_edge_cross_squarednorm(*x)
        eps_x = cross2 * (2.0 if k % 2 == 0 else 0.5)
        mollified += cross2 < eps_x
        collision = ipctk.EdgeEdgeNormalCollision(0, 1, eps_x)
        energy, gradient, hessian = core.edge_edge_barrier(*x, eps_x, D_HAT, KAPPA, project)
        flat = x.ravel()
        assert energy == pytest.approx(potential(collision, flat), rel=IPC_RTOL)
        assert _relative(gradient, potential.gradient(collision, flat)) < IPC_RTOL
        assert _relative(hessian, potential.hessian(collision, flat, method)) < IPC_RTOL
    assert mollified == 200
    assert codes == set(range(9))  # every kind of closest features was compared


def test_point_plane_barrier_agrees_with_ipctk():
    ipctk = _ipctk()
    potential = ipctk.BarrierPotential(D_HAT, KAPPA)
    rng = np.random.default_rng(4)
    for _ in range(100):
        origin, normal = rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3)
        unit = normal / np.linalg.norm(normal)
        side = rng.choice([-1.0, 1.0])  # either side of the plane
        p = origin + np.cross(rng.uniform(-1, 1, 3), unit) + side * rng.uniform(
            0.05, 0.95) * D_HAT * unit
        collision = ipctk.PlaneVertexNormalCollision(ipctk.Hyperplane(unit, origin), 0)
        energy, gradient, hessian = core.point_plane_barrier(p, origin, normal, D_HAT, KAPPA)
        assert energy > 0
        assert energy == pytest.approx(potential(collision, p), rel=IPC_RTOL)
        assert _relative(gradient, potential.gradient(collision, p)) < IPC_RTOL
        assert _relative(hessian, potential.hessian(collision, p)) < IPC_RTOL


def test_mollifier_threshold_and_initial_stiffness_agree_with_ipctk():
    ipctk = _ipctk()
    rng = np.random.default_rng(5)
    for _ in range(20):
        x = rng.uniform(-1, 1, size=(4, 3))
        assert core.edge_edge_mollifier_threshold(*x) == pytest.approx(
            ipctk.edge_edge_mollifier_threshold(*x), rel=IPC_RTOL)
        diagonal, d_hat, mass = rng.uniform(1, 100), rng.uniform(0.01, 1), rng.uniform(0.1, 10)
        grad_barrier = rng.normal(size=30)
        for scale in (1e-3, 1.0, 1e3, -1.0):  # below, inside, above the bounds; opposed
            grad_energy = -scale * rng.uniform(1e-2, 1e2) * grad_barrier + rng.normal(size=30)
            kappa, _, kappa_max = core.initial_barrier_stiffness(
                diagonal, d_hat, mass, grad_energy, grad_barrier)
            theirs, theirs_max = ipctk.initial_barrier_stiffness(
                diagonal, ipctk.ClampedLogBarrier(), d_hat, mass, grad_energy, grad_barrier)
            assert kappa == pytest.approx(theirs, rel=IPC_RTOL)
            assert kappa_max == pytest.approx(theirs_max, rel=IPC_RTOL)


def _barrier_cases(pair):
    """(configuration, energy function of the flat coordinates) for one kind of pair."""
    if pair == "point_triangle":
        return [(x, lambda y: core.point_triangle_barrier(*y.reshape(4, 3), D_HAT, KAPPA))
                for x in _active_pairs(_pt_distance2, 20, seed=7)]
    if pair == "edge_edge":
        # The threshold of each pair's own starting edges (1e-3 |ua|^2 |ub|^2).
        return [(x, lambda y, e=core.edge_edge_mollifier_threshold(*x):
                 core.edge_edge_barrier(*y.reshape(4, 3), e, D_HAT, KAPPA))
                for x in _active_pairs(_ee_distance2, 20, seed=8)]
    rng = np.random.default_rng(6)
    origin, normal = np.array([0.1, -0.2, 0.3]), np.array([1.0, 2.0, 2.0])
    return [(origin + np.cross(rng.uniform(-1, 1, 3), normal)
             + rng.uniform(0.05, 0.9) * D_HAT * normal / 3,
             lambda y: core.point_plane_barrier(y, origin, normal, D_HAT, KAPPA))
            for _ in range(20)]


@pytest.mark.parametrize("pair", ["point_triangle", "edge_edge", "point_plane"])
def test_barriers_match_finite_differences(pair):
    for x, energy in _barrier_cases(pair):
        value, gradient, hessian = energy(np.ravel(x))
        assert value > 0
        fd_gradient, fd_hessian = _finite_differences(lambda y: energy(y)[:2], x)
        assert _relative(gradient, fd_gradient) < FD_RTOL
        assert _relative(hessian, fd_hessian) < FD_RTOL


def test_ccd_and_broad_phase_from_python():
    triangle = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    start = np.vstack([[0.2, 0.2, 1.0], triangle])
    end = np.vstack([[0.2, 0.2, -1.0], triangle])
    impact, toi = core.point_triangle_ccd(start, end)
    assert impact and toi == pytest.approx(0.45, rel=1e-12)  # eta = 0.9 of the crossing at 0.5
    impact, toi = core.edge_edge_ccd(
        np.array([[0.0, 0, 0], [1, 0, 0], [0.5, -1, 1], [0.5, 1, 1]]),
        np.array([[0.0, 0, 0], [1, 0, 0], [0.5, -1, -1], [0.5, 1, -1]]))
    assert impact and 0.25 < toi < 0.5
    # Two panels on the crease 0-1, folded nearly shut.
    nodes = np.array([[0.0, 0, 0], [1, 0, 0], [0.3, 0.5, 0.01], [0.4, 0.4, 0]])
    triangles = np.array([[0, 1, 2], [1, 0, 3]])
    point_triangle, edge_edge, edges = core.contact_candidates(nodes, triangles, 0.15)
    assert point_triangle.tolist() == [[2, 1], [3, 0]]
    assert edges.tolist() == [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3]]
    assert edge_edge.tolist() == [[1, 4], [2, 3]]
    # At d = 0 only corner 3 (in the plane of panel 0's box) is left; a step moving node 3
    # by (0, 0.2, 0.2) sweeps panel 1's box over corner 2 as well.
    still, _, _ = core.contact_candidates(nodes, triangles, 0.0, displacement=np.zeros((4, 3)))
    assert still.tolist() == [[3, 0]]
    lift = np.zeros((4, 3))
    lift[3] = [0.0, 0.2, 0.2]
    swept, _, _ = core.contact_candidates(nodes, triangles, 0.0, displacement=lift)
    assert swept.tolist() == [[2, 1], [3, 0]]


@pytest.mark.parametrize("call, name", [
    (lambda: core.point_triangle_barrier(np.zeros(3), np.zeros(3), np.ones(3), [0, 1, 0],
                                         0.0, 1.0), "d_hat"),
    (lambda: core.point_triangle_barrier(np.zeros(3), np.zeros(3), np.ones(3), [0, 1, 0],
                                         0.1, -1.0), "stiffness"),
    (lambda: core.point_triangle_barrier([np.nan, 0, 0], np.zeros(3), np.ones(3), [0, 1, 0],
                                         0.1, 1.0), "p"),
    (lambda: core.edge_edge_barrier(np.zeros(3), np.ones(3), [0, 1, 0], [1, 0, 0], 0.0, 0.1,
                                    1.0), "eps_x"),
    (lambda: core.point_plane_barrier(np.ones(3), np.zeros(3), np.zeros(3), 0.1, 1.0),
     "normal"),
    (lambda: core.point_triangle_ccd(np.zeros((4, 3)), np.ones((4, 3)), min_distance=-1.0),
     "min_distance"),
    (lambda: core.contact_candidates(np.zeros((3, 3)), np.array([[0, 1, 5]]), 0.1),
     "triangles"),
    (lambda: core.contact_candidates(np.zeros((3, 3)), np.array([[0, 1, 2]]), -0.1),
     "distance"),
    (lambda: core.initial_barrier_stiffness(0.0, 0.1, 1.0, np.ones(3), np.ones(3)),
     "bbox_diagonal"),
])
def test_bad_input_is_a_value_error_naming_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()
