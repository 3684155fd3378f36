"""Why a fold's path ended before its targets, measured where it ended.

A fold's path ends where no increment, however small, finds an equilibrium. On a sheet that
cannot fold rigidly with its creases at their targets' ratio, the panels give way: the path
squashes some panel triangle further at every increment, and the tangent's smallest
eigenvalue falls to zero, a limit point of the rest angles. Past it the potential energy
leads into that triangle's collapse to a line, where the bar-and-hinge model is singular:
a hinge measures its angle by the planes of its two wing triangles, and a wing flattened to
a line has no plane, so the hinges beside it can turn freely, at an energy that falls
towards (and jumps at) the collapse. Neither Newton nor the relaxation finds a stable
state there (docs/folding.md, 'Where a fold stops: the crane and the flapping bird').

:func:`fold_stall` measures each step of that account on the path's last equilibrium (its
stability and smallest eigenvalue against those an increment before, the panel triangle
squashed furthest from its flat shape) and, on models of up to
:data:`MAX_MEASURED_DOFS` free DOFs, where a descent of the energy at the next increment's
rest angles ends where the last equilibrium is a limit point (its most squashed triangle),
and says it in words.
"""

from __future__ import annotations

import numpy as np

from kresling import solvers

__all__ = ["fold_stall", "squashed_triangle", "MAX_MEASURED_DOFS", "SQUASHED", "COLLAPSED"]

#: Free DOFs up to which the smallest eigenvalues are computed densely and the energy is
#: descended past the path's end; beyond, the eigenvalue nearest zero of a stable state is
#: found by sparse shift-invert Lanczos, and no descent is made.
MAX_MEASURED_DOFS = 3000
#: A panel triangle below this fraction of its flat height is named as squashed.
SQUASHED = 0.5
#: A panel triangle below this fraction of its flat height has collapsed to a line.
COLLAPSED = 0.01
#: Iterations of the descent past the path's end (L-BFGS; the crane's ends in about 1,000).
_DESCENT_ITERATIONS = 5000


def _heights(x, triangles):
    """Each triangle's height over its longest side [mm], (T,)."""
    a, b, c = (x[triangles[:, k]] for k in range(3))
    area2 = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    longest = np.max([np.linalg.norm(b - a, axis=1), np.linalg.norm(c - b, axis=1),
                      np.linalg.norm(a - c, axis=1)], axis=0)
    return area2 / longest


def _corners_deg(x, triangle):
    """The triangle's three interior angles [deg], at its corners in order."""
    out = []
    for k in range(3):
        p, q, r = x[triangle[k]], x[triangle[(k + 1) % 3]], x[triangle[(k + 2) % 3]]
        u, w = q - p, r - p
        out.append(np.degrees(np.arctan2(np.linalg.norm(np.cross(u, w)), u @ w)))
    return np.array(out)


def squashed_triangle(pattern_model, displacement):
    """The panel triangle squashed furthest from its flat shape.

    Parameters
    ----------
    pattern_model : PatternModel
    displacement : array_like, shape (3N,)
        Every node's displacement [mm].

    Returns
    -------
    triangle : ndarray of int, shape (3,)
        Its nodes (``pattern_model.elements.triangles``' row).
    ratio : float
        Its height over its longest side, as a fraction of the same in the flat pattern.
    corners_deg : ndarray, shape (3,)
        Its interior angles there [deg]; ``flat_deg`` (3,) the same in the flat pattern.
    """
    elements = pattern_model.elements
    triangles = np.asarray(elements.triangles)
    flat = np.asarray(elements.nodes, dtype=float)
    x = flat + np.asarray(displacement, dtype=float).reshape(-1, 3)
    ratio = _heights(x, triangles) / _heights(flat, triangles)
    k = int(np.argmin(ratio))
    return triangles[k], float(ratio[k]), _corners_deg(x, triangles[k]), \
        _corners_deg(flat, triangles[k])


def _node_name(pattern_model, node) -> str:
    """A node as the pattern numbers it: a vertex, or a split panel's centre."""
    centre = np.flatnonzero(np.asarray(pattern_model.elements.panel_centre) == node)
    return f"the centre of panel {int(centre[0])}" if centre.size else str(int(node))


def _triangle_words(pattern_model, triangle) -> str:
    names = [_node_name(pattern_model, n) for n in triangle]
    return f"the panel triangle of nodes {names[0]}, {names[1]} and {names[2]}"


def _smallest_eigenvalue(model, u, free) -> float | None:
    """The smallest eigenvalue of the tangent on the free DOFs at ``u`` [N/mm]: dense up to
    :data:`MAX_MEASURED_DOFS` free DOFs; beyond, the one nearest zero, by shift-invert
    Lanczos on the sparse tangent (ARPACK), which is the smallest where the tangent is
    positive definite; None where that finds none (a tangent singular to rounding)."""
    from kresling.assembly import assemble

    stiffness = assemble(model, u).stiffness
    if len(free) <= MAX_MEASURED_DOFS:
        from scipy.linalg import eigh

        dense = stiffness.toarray()[np.ix_(free, free)]
        return float(eigh(dense, eigvals_only=True, subset_by_index=[0, 0])[0])
    from scipy.sparse.linalg import ArpackError, eigsh

    try:
        nearest = eigsh(stiffness.tocsc()[free][:, free], k=1, sigma=0.0, which="LM",
                        return_eigenvectors=False)
    except (ArpackError, RuntimeError):   # RuntimeError: the shifted factor is singular
        return None
    return float(nearest[0])


def _descend(model, u, free):
    """Where a descent of ``model``'s energy from ``u`` ends (L-BFGS on the free DOFs; a
    state whose energy cannot be evaluated counts as infinitely high). Returns the
    displacement (3N,)."""
    from scipy.optimize import minimize

    from kresling.assembly import Workspace, assemble

    workspace = Workspace(model)
    start = np.asarray(u, dtype=float)

    def energy(z):
        trial = start.copy()
        trial[free] = z
        try:
            a = assemble(model, trial, stiffness=False, workspace=workspace)
        except ValueError:  # an element degenerated past what its energy can say
            return np.inf, np.zeros_like(z)
        return a.energy, a.force[free]

    result = minimize(energy, start[free], jac=True, method="L-BFGS-B",
                      options={"maxiter": _DESCENT_ITERATIONS, "maxfun": 2 * _DESCENT_ITERATIONS,
                               "gtol": 1e-10, "ftol": 1e-15})
    out = start.copy()
    out[free] = result.x
    return out


def fold_stall(simulation) -> str:
    """Why a fold's path ended early, measured at its last equilibrium, in words ("" for a
    path that completed, was interrupted, or is no fold).

    Parameters
    ----------
    simulation : Simulation
        A fold's run (``simulation.fold`` its plan).

    Returns
    -------
    str
        Where the path ended (the fold fraction); whether the last equilibrium is stable and
        its tangent's smallest eigenvalue against that one increment before (a limit point:
        stable, and fallen below half of it); the panel triangle squashed furthest (when
        below :data:`SQUASHED` of its flat height); and, past a limit point, where a descent
        of the energy at the next increment's rest angles, from the last equilibrium, leaves
        that triangle (or another squashed further). The descent needs at most
        :data:`MAX_MEASURED_DOFS` free DOFs; beyond them the eigenvalues are found sparse, of
        stable states only (an unstable one is said so, with its negative eigenvalues).
    """
    path = simulation.path
    if (simulation.fold is None or path.completed or simulation.interrupted
            or path.num_steps < 2):
        return ""
    pm = simulation.pattern_model
    free = np.asarray(simulation.model.free_dofs)
    reached = float(path.load_factor[-1])
    increment = 1.0 / simulation.problem.analysis.steps
    u = path.displacement[-1]
    parts = []
    measured = free.size <= MAX_MEASURED_DOFS
    # Beyond the dense size the eigenvalue found is the one nearest zero: the smallest only
    # where the factorisation counted no negative one.
    unstable_there = (not measured and len(path.negative_eigenvalues)
                      and path.negative_eigenvalues[-1] > 0)
    lowest = None if unstable_there else _smallest_eigenvalue(simulation.model_at(-1), u, free)
    limit = False
    if lowest is not None:
        # The equilibrium a whole increment before the last one (before any halving).
        before = int(np.searchsorted(path.load_factor, reached - increment * (1 - 1e-9),
                                     side="right")) - 1
        earlier = None
        if 0 <= before < path.num_steps - 1 and (measured
                                                 or path.negative_eigenvalues[before] == 0):
            earlier = _smallest_eigenvalue(simulation.model_at(before),
                                           path.displacement[before], free)
        limit = lowest > 0 and earlier is not None and lowest < 0.5 * earlier
        state = ("stable" if lowest > 0 else "unstable")
        words = (f"its last equilibrium (at {reached:.4g} of the crease actuation) is {state}, "
                 f"the tangent's smallest eigenvalue {lowest:.3g} N/mm")
        if earlier is not None:
            words += (f" against {earlier:.3g} N/mm at "
                      f"{float(path.load_factor[before]):.4g}")
        if limit:
            words += (": a limit point of the rest angles, past which no equilibrium "
                      "continues the path")
        parts.append(words)
    triangle, ratio, corners, flat = squashed_triangle(pm, u)
    named = ratio < SQUASHED
    if named:
        parts.append(f"there {_triangle_words(pm, triangle)} is squashed to "
                     f"{100 * ratio:.3g} % of its flat height (its corners "
                     f"{', '.join(f'{c:.3g}' for c in corners)} deg; flat "
                     f"{', '.join(f'{c:.3g}' for c in flat)})")
    if unstable_there:
        parts.insert(0, f"its last equilibrium (at {reached:.4g} of the crease actuation) is "
                        f"unstable ({int(path.negative_eigenvalues[-1])} negative eigenvalues "
                        "of its tangent)")
    if limit and measured:  # past a limit point: where the sheet would go
        # One increment on, within the stage the path stopped in ((k - 1, k] is stage k).
        ahead = min(reached + increment, float(np.floor(reached + 1e-12)) + 1.0)
        model = solvers.fold_model_at(simulation.model, simulation.fold.stages, ahead)
        further, ratio_end, _, _ = squashed_triangle(pm, _descend(model, u, free))
        who = ("that triangle" if named and set(further.tolist()) == set(triangle.tolist())
               else _triangle_words(pm, further))
        if ratio_end < COLLAPSED:
            parts.append(f"descending the energy at {ahead:.4g} from there collapses {who} "
                         f"to a line ({100 * ratio_end:.2g} % of its flat height), where the "
                         "hinges beside it have no angle (a wing without a plane): the panels "
                         "cannot follow the creases past this point in this model")
        else:
            parts.append(f"descending the energy at {ahead:.4g} from there leaves its panel "
                         f"triangles at {100 * ratio_end:.3g} % of their flat height or more")
    return "; ".join(parts)
