"""Origami Simulator's model, written again from its equations: the reference the tests of
public folds and studies/origami_simulator_fold.py compare the model's folds with.

Origami Simulator (Ghassaei, Demaine and Gershenfeld, "Fast, Interactive Origami Simulation
using GPU Computation", 7OSME 2018) folds a triangulated sheet by damped explicit dynamics.
Its model, in the units it works in (the sheet scaled so its bounding sphere has radius 1,
mass 1 at every node), is the sum of three energies:

- every edge (boundary, crease, and the facets that triangulate the polygons) a bar of
  stiffness ``k = axial / L0`` (axial 20): ``k (L - L0)^2 / 2``;
- every edge between two triangles a rotational spring of stiffness ``k = c L0`` (``c`` the
  crease stiffness 0.7 for M and V, the panel stiffness 0.7 for facets, target 0):
  ``k (theta - p theta_target)^2 / 2`` with ``p`` the crease percent (0.6 when it opens);
- every corner of every triangle a spring on its interior angle (face stiffness 0.2):
  ``f (alpha - alpha0)^2 / 2``.

Damping acts on the bars: a force ``d (v_other - v_self)`` at each end, ``d = 2 zeta
sqrt(k m)`` (zeta 0.45), on the relative velocity (all of it, not only along the bar); the
rotational springs and the face angles are undamped. The integrator is semi-implicit
Euler (the velocity from the forces at the last state, then the position from the new
velocity) with ``dt = 0.9 / (2 pi max sqrt(k / m))`` over the bars, and no node is held.

The functions here take a crease pattern (a :class:`kresling.io.Pattern`: its vertices,
counter-clockwise polygon faces, edges, letters and target angles), triangulate its faces,
and integrate from the flat sheet with every target applied at once, as the simulator does
when it opens a pattern. Any ingredient can be switched (``face_stiffness = 0``, other bar
stiffness, other damping) to see which one decides a fold.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

#: Origami Simulator's defaults (its js/globals.js).
AXIAL_STIFFNESS = 20.0
CREASE_STIFFNESS = 0.7
PANEL_STIFFNESS = 0.7
FACE_STIFFNESS = 0.2
PERCENT_DAMPING = 0.45


def _cross2(a, b):
    return a[0] * b[1] - a[1] * b[0]


def triangulate(polygon, xy):
    """Ear clipping of one counter-clockwise polygon (vertex ids ``polygon``, plane
    coordinates ``xy``): its triangles, counter-clockwise."""
    remaining = [int(v) for v in polygon]
    triangles = []
    while len(remaining) > 3:
        n = len(remaining)
        for i in range(n):
            a, b, c = remaining[i - 1], remaining[i], remaining[(i + 1) % n]
            if _cross2(xy[b] - xy[a], xy[c] - xy[b]) <= 1e-12:
                continue                                   # reflex or straight corner
            inside = False
            for v in remaining:
                if v in (a, b, c):
                    continue
                p = xy[v]
                if (_cross2(xy[b] - xy[a], p - xy[a]) >= 0 and _cross2(xy[c] - xy[b], p - xy[b]) >= 0
                        and _cross2(xy[a] - xy[c], p - xy[c]) >= 0):
                    inside = True
                    break
            if not inside:
                triangles.append((a, b, c))
                del remaining[i]
                break
        else:
            raise ValueError(f"polygon {list(polygon)} could not be triangulated")
    triangles.append(tuple(remaining))
    return triangles


@dataclass
class SimulatorModel:
    """A triangulated sheet in the simulator's units."""
    x0: np.ndarray                     # (N, 3) flat positions, bounding sphere radius 1
    triangles: np.ndarray              # (T, 3) counter-clockwise
    bars: np.ndarray                   # (B, 2)
    bar_length: np.ndarray             # (B,)
    hinges: np.ndarray                 # (H, 4): axis u, v; wing of the left face, of the right
    hinge_target: np.ndarray           # (H,) full target [rad], valley positive
    hinge_is_crease: np.ndarray        # (H,) M or V (the others are facets)
    hinge_edge: np.ndarray             # (H,) the pattern's edge, -1 for a facet
    corner_angle: np.ndarray = field(default=None)   # (T, 3) flat interior angles


def bounding_circle(pattern):
    """The centre (2,) and radius of the circle about the sheet's bounding box's centre
    through its farthest vertex, in the pattern's units: the simulator scales the sheet to
    radius 1 about that centre."""
    xy = np.asarray(pattern.vertices, dtype=float)[:, :2]
    centre = 0.5 * (xy.min(axis=0) + xy.max(axis=0))
    return centre, float(np.max(np.linalg.norm(xy - centre, axis=1)))


def material_in_model_units(pattern, base):
    """This package's ``[material]`` keys for the simulator's three ingredients: ``base``
    (creases of 1 N mm/rad per mm) with bars of EA = 20 / 0.7 N and corner springs of
    0.2 R / 0.7 N mm/rad^2 (R the bounding radius in mm). The simulator's energy times
    R / 0.7 is this model's energy with these keys."""
    _, radius = bounding_circle(pattern)
    return dict(base, bar_modulus=AXIAL_STIFFNESS / CREASE_STIFFNESS,
                face_stiffness=FACE_STIFFNESS * radius / CREASE_STIFFNESS)


def build(pattern, targets_deg=None, triangles=None, rotate=0):
    """The simulator's model of ``pattern``; ``targets_deg`` one per pattern edge (default
    the pattern's ``edges_fold_angle``, unknown as 0). ``triangles`` (in the pattern's
    vertex numbers) replace the ear clipping of its faces, for the simulator's own
    triangulation; ``rotate`` starts the ear clipping that many corners on (another choice
    of diagonals)."""
    xy = np.asarray(pattern.vertices, dtype=float)[:, :2]
    centre, radius = bounding_circle(pattern)
    x0 = np.zeros((len(xy), 3))
    x0[:, :2] = (xy - centre) / radius
    if triangles is None:
        triangles = [t for face in pattern.faces
                     for t in triangulate(list(face)[rotate % len(face):]
                                          + list(face)[:rotate % len(face)], x0[:, :2])]
    else:                              # counter-clockwise seen from +z, as the faces
        triangles = [tuple(t) if _cross2(x0[t[1], :2] - x0[t[0], :2],
                                         x0[t[2], :2] - x0[t[0], :2]) > 0 else tuple(t[::-1])
                     for t in np.asarray(triangles, dtype=int).tolist()]
    targets = (np.nan_to_num(np.asarray(pattern.edges_fold_angle, dtype=float))
               if targets_deg is None else np.asarray(targets_deg, dtype=float))
    edge_index = {}
    for k, (u, v) in enumerate(np.asarray(pattern.edges, dtype=int)):
        edge_index[(u, v)] = edge_index[(v, u)] = k
    left_of = {}                       # directed edge -> (triangle's third vertex)
    for a, b, c in triangles:
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            left_of[(u, v)] = w
    bars, hinges, target, is_crease, hinge_edge = [], [], [], [], []
    seen = set()
    for (u, v), w_left in left_of.items():
        key = (min(u, v), max(u, v))
        if key in seen:
            continue
        seen.add(key)
        bars.append(key)
        w_right = left_of.get((v, u))
        if w_right is None:
            continue                                       # a boundary edge: a bar only
        k = edge_index.get((u, v), -1)
        letter = pattern.edges_assignment[k] if k >= 0 else "F"
        hinges.append((u, v, w_left, w_right))
        is_crease.append(letter in "MV")
        target.append(np.radians(targets[k]) if letter in "MV" else 0.0)
        hinge_edge.append(k)
    bars = np.array(bars)
    model = SimulatorModel(x0=x0, triangles=np.array(triangles), bars=bars,
                           bar_length=np.linalg.norm(x0[bars[:, 1]] - x0[bars[:, 0]], axis=1),
                           hinges=np.array(hinges), hinge_target=np.array(target),
                           hinge_is_crease=np.array(is_crease), hinge_edge=np.array(hinge_edge))
    model.corner_angle = corner_angles(model, x0)
    return model


def corner_angles(model, x):
    """Interior angles of every triangle, (T, 3), at its corners a, b, c."""
    a, b, c = (x[model.triangles[:, i]] for i in range(3))
    def angle(p, q, r):               # at p, between p->q and p->r
        u, w = q - p, r - p
        return np.arctan2(np.linalg.norm(np.cross(u, w), axis=1), np.sum(u * w, axis=1))
    return np.stack([angle(a, b, c), angle(b, c, a), angle(c, a, b)], axis=1)


def hinge_angles(model, x):
    """Fold angle of every hinge [rad] in (-pi, pi], valley positive (the left and right
    triangles' normals, as :func:`kresling.io.fold_angles` measures them)."""
    u, v, i, j = (x[model.hinges[:, k]] for k in range(4))
    axis = v - u
    n_left = np.cross(axis, i - u)      # the left triangle (u, v, i) counter-clockwise
    n_right = np.cross(j - u, axis)     # the right triangle (v, u, j)
    n_left /= np.linalg.norm(n_left, axis=1)[:, None]
    n_right /= np.linalg.norm(n_right, axis=1)[:, None]
    axis_unit = axis / np.linalg.norm(axis, axis=1)[:, None]
    return np.arctan2(np.sum(np.cross(n_right, n_left) * axis_unit, axis=1),
                      np.sum(n_left * n_right, axis=1))


def _hinge_gradient(model, x):
    """d theta / d x of every hinge's four nodes, (H, 4, 3) (the dihedral's closed form:
    the wings move along their face's normal over their distance from the axis, the axis
    nodes take the reaction in proportion to where the wings' feet lie)."""
    u, v, i, j = (x[model.hinges[:, k]] for k in range(4))
    e = v - u
    e2 = np.sum(e * e, axis=1)
    le = np.sqrt(e2)
    m_left = np.cross(e, i - u)         # |m| = le * (distance of i from the axis)
    m_right = np.cross(j - u, e)
    ml2 = np.sum(m_left * m_left, axis=1)
    mr2 = np.sum(m_right * m_right, axis=1)
    # Valley positive: closing the left wing along its normal raises theta.
    g_i = (le / ml2)[:, None] * m_left
    g_j = (le / mr2)[:, None] * m_right
    s_i = np.sum((i - u) * e, axis=1) / e2   # where the wings' feet lie along the axis
    s_j = np.sum((j - u) * e, axis=1) / e2
    g_u = -(1 - s_i)[:, None] * g_i - (1 - s_j)[:, None] * g_j
    g_v = -s_i[:, None] * g_i - s_j[:, None] * g_j
    return np.stack([g_u, g_v, g_i, g_j], axis=1)


@dataclass
class Stiffness:
    """The simulator's parameters; change one to switch an ingredient."""
    axial: float = AXIAL_STIFFNESS
    crease: float = CREASE_STIFFNESS
    panel: float = PANEL_STIFFNESS
    face: float = FACE_STIFFNESS
    damping: float = PERCENT_DAMPING


def energy(model, x, percent, s=Stiffness(), theta=None):
    """The model's stored energy at ``x`` with the targets at ``percent`` (``theta`` the
    hinges' angles followed through +-180 deg, default as measured)."""
    bars = model.bars
    length = np.linalg.norm(x[bars[:, 1]] - x[bars[:, 0]], axis=1)
    k_bar = s.axial / model.bar_length
    theta = hinge_angles(model, x) if theta is None else theta
    k_hinge = np.where(model.hinge_is_crease, s.crease, s.panel) * _hinge_length(model)
    alpha = corner_angles(model, x)
    return (0.5 * np.sum(k_bar * (length - model.bar_length) ** 2)
            + 0.5 * np.sum(k_hinge * (theta - percent * model.hinge_target) ** 2)
            + 0.5 * s.face * np.sum((alpha - model.corner_angle) ** 2))


def _hinge_length(model):
    u, v = model.hinges[:, 0], model.hinges[:, 1]
    return np.linalg.norm(model.x0[v] - model.x0[u], axis=1)


def forces(model, x, velocity, percent, s=Stiffness(), theta=None):
    """Every node's force: minus the energy's gradient, plus the bars' damping."""
    f = np.zeros_like(x)
    bars = model.bars
    d = x[bars[:, 1]] - x[bars[:, 0]]
    length = np.linalg.norm(d, axis=1)
    k_bar = s.axial / model.bar_length
    pull = (k_bar * (length - model.bar_length) / length)[:, None] * d
    pull += (s.damping * 2.0 * np.sqrt(k_bar))[:, None] * (velocity[bars[:, 1]]
                                                           - velocity[bars[:, 0]])
    _scatter(model, f, 'bars', np.concatenate([pull, -pull]))
    if theta is None:
        theta = hinge_angles(model, x)
    k_hinge = np.where(model.hinge_is_crease, s.crease, s.panel) * _hinge_length(model)
    moment = k_hinge * (theta - percent * model.hinge_target)
    grad = _hinge_gradient(model, x)
    _scatter(model, f, 'hinges', -(moment[:, None, None] * grad).transpose(1, 0, 2).reshape(-1, 3))
    if s.face:
        _add_face_forces(model, x, f, s.face)
    return f


def _add_face_forces(model, x, f, stiffness):
    """Minus the gradient of the face-angle energy."""
    t = model.triangles
    a, b, c = x[t[:, 0]], x[t[:, 1]], x[t[:, 2]]
    normal = np.cross(b - a, c - a)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    alpha = corner_angles(model, x)
    excess = stiffness * (alpha - model.corner_angle)        # dE / d alpha
    for corner, (p, q, r) in enumerate(((0, 1, 2), (1, 2, 0), (2, 0, 1))):
        xp, xq, xr = x[t[:, p]], x[t[:, q]], x[t[:, r]]
        uq, ur = xq - xp, xr - xp
        # The angle at p grows as q turns away from r (about the normal) and r from q.
        d_q = -np.cross(normal, uq) / np.sum(uq * uq, axis=1)[:, None]
        d_r = np.cross(normal, ur) / np.sum(ur * ur, axis=1)[:, None]
        w = excess[:, corner][:, None]
        _scatter(model, f, f"corner{corner}",
                 np.concatenate([w * (d_q + d_r), -w * d_q, -w * d_r]))


def _scatters(model):
    """Sparse matrices that add per-element forces into the nodes (built once)."""
    if getattr(model, "_scatter", None) is not None:
        return model._scatter
    from scipy.sparse import csr_matrix
    n = len(model.x0)
    def matrix(nodes):
        nodes = np.asarray(nodes).reshape(-1)
        return csr_matrix((np.ones(len(nodes)), (nodes, np.arange(len(nodes)))),
                          shape=(n, len(nodes)))
    t = model.triangles
    model._scatter = {"bars": matrix(np.concatenate([model.bars[:, 0], model.bars[:, 1]])),
                      "hinges": matrix(model.hinges.T.reshape(-1))}
    for corner, (p, q, r) in enumerate(((0, 1, 2), (1, 2, 0), (2, 0, 1))):
        model._scatter[f"corner{corner}"] = matrix(np.concatenate([t[:, p], t[:, q], t[:, r]]))
    return model._scatter


def _scatter(model, f, name, values):
    f += _scatters(model)[name] @ values


def time_step(model, s=Stiffness()):
    """The simulator's step: 0.9 of the stability limit of the stiffest bar, mass 1."""
    return 0.9 / (2.0 * np.pi * np.sqrt(np.max(s.axial / model.bar_length)))


@dataclass
class Run:
    x: np.ndarray
    velocity: np.ndarray
    theta: np.ndarray
    steps: int
    kinetic: float
    settled: bool


def integrate(model, percent, *, s=Stiffness(), steps=200_000, ramp_steps=0,
              tolerance=1e-10, check_every=500, x=None, velocity=None, theta=None):
    """Semi-implicit Euler from the flat sheet (or ``x``), the targets at ``percent`` at once
    (or reached linearly over ``ramp_steps``), until the kinetic energy per node stays under
    ``tolerance`` over ``check_every`` steps or ``steps`` ran out."""
    x = model.x0.copy() if x is None else x.copy()
    _scatters(model)
    velocity = np.zeros_like(x) if velocity is None else velocity.copy()
    dt = time_step(model, s)
    theta = hinge_angles(model, x) if theta is None else theta.copy()
    quiet = 0
    n = len(x)
    for step in range(1, steps + 1):
        p = percent * min(1.0, step / ramp_steps) if ramp_steps else percent
        # The simulator follows each hinge's angle from step to step, so a hinge folded
        # past +-180 deg keeps its sense (a jump of more than 5 rad is a turn past it).
        measured = hinge_angles(model, x)
        jump = measured - theta
        theta = theta + jump - 2 * np.pi * np.round(jump / (2 * np.pi)) * (np.abs(jump) > 5.0)
        velocity += dt * forces(model, x, velocity, p, s, theta=theta)
        x += dt * velocity
        kinetic = 0.5 * np.sum(velocity * velocity) / n
        if not np.all(np.isfinite(x)):
            return Run(x, velocity, theta, step, np.inf, False)
        quiet = quiet + 1 if (kinetic < tolerance and step > ramp_steps) else 0
        if quiet >= check_every:
            return Run(x, velocity, theta, step, kinetic, True)
    return Run(x, velocity, theta, steps, kinetic, False)
