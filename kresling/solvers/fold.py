"""Folding by crease actuation: hinges' rest angles driven to targets, in stages.

:func:`solve_fold` is the solver (rest angles in radians, any :class:`Model`); :func:`fold`
is the verb for a crease pattern's model, with targets as fold angles in FOLD's convention
(degrees, + valley, - mountain). Each increment is a Newton solve of the model with its
supports and loads; no perturbing force is needed. docs/folding.md explains the convention
and how a flat pattern leaves its flat state.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_bool, as_integer, as_positive_real, as_real
from kresling.model.fold_angles import fold_angles_deg, hinge_fold_signs, rest_angles_for
from kresling.solvers._inputs import cholesky_choice, dof_vector
from kresling.solvers.path import PathResult

#: The core's defaults (the options struct declares them once).
_DEFAULTS = _core.solvers.FoldOptions()

__all__ = ["solve_fold", "fold", "FoldResult"]


def fold_stages(stages) -> list:
    """The stages as ``[(hinges (K,) int, targets (K,) float), ...]``; a stage that is not
    a pair is refused naming it (the core checks ranges and sizes)."""
    out = []
    for k, stage in enumerate(stages):
        try:
            hinges, targets = stage
        except (TypeError, ValueError):
            raise ValueError(f"stages[{k}] must be (hinges, targets)") from None
        out.append((np.asarray(hinges, dtype=np.int64).ravel(),
                    np.asarray(targets, dtype=float).ravel()))
    return out


def solve_fold(model, stages, steps, *, forces=None, tolerance=_DEFAULTS.tolerance,
               max_iterations=_DEFAULTS.max_iterations, max_bisections=_DEFAULTS.max_bisections,
               extrapolation=_DEFAULTS.extrapolation, shift=_DEFAULTS.shift, initial=None,
               stop=None, cholesky="auto", adaptive=_DEFAULTS.adaptive,
               adaptive_tolerance=_DEFAULTS.adaptive_tolerance, snap=_DEFAULTS.snap,
               relax=_DEFAULTS.relax, give_up_after=_DEFAULTS.give_up_after) -> PathResult:
    """Drive hinges' rest angles to targets, stage after stage, and follow the equilibrium.

    Parameters
    ----------
    model : kresling.model.Model
    stages : sequence of (hinges, targets)
        Each stage: hinge indices (K,) and their target rest angles (K,) [rad, in
        [0, 2 pi)]. A stage's rest angles move linearly from where the stages before it left
        them (the model's own for the first) to its targets, in ``steps`` equal increments.
    steps : int
        Increments per stage, 1 to 100 000.
    forces : array_like, shape (3N,) or (N, 3), optional
        External load [N], ramped from 0 to full over the first stage and held after it.
    extrapolation : {0, 1, 2, 3}
        Each increment's start: the previous equilibrium, or a linear, quadratic or cubic
        extrapolation along the path.
    stop : callable, optional
        ``stop(fraction, displacement) -> bool`` after every accepted increment (``fraction``
        of the current stage); True ends the fold there.
    adaptive : bool, default False
        Adaptive increments: each stage's ``steps`` equal samples read off cubic Hermite
        curves between increments chosen by an error estimate of the stored energy (0
        iterations for a sample inside an increment), never across a stability change, a
        hinge crossing a limit of its enhanced linear law or a cable going slack; each
        increment starts from its cubic extrapolation. A stage they cannot finish is folded
        again in fixed increments (``extrapolation``'s start).
    adaptive_tolerance : float, default 1e-9
        The samples' estimated energy error relative to the largest stored energy so far,
        in (0, 1e-4].
    snap : bool, default False
        Where the equilibrium path ends (a limit point of the rest angles: an increment
        fails at its smallest size), let the sheet snap as a slowly actuated one would:
        descend the potential energy at that increment's rest angles from the last
        equilibrium to a stable state (saddle-free Newton steps with a line search), record
        it as a step (``PathResult.snapped``) and fold on from there. Up to 3,000 free
        DOFs the descent uses dense eigen-decompositions; beyond, sparse Cholesky
        factorisations of the tangent shifted until positive definite. Where the descent
        finds no stable state the fold ends as without it.
    relax : bool, default False
        Fold through stable states only, as a sheet actuated slowly comes to rest: an
        increment whose Newton solve fails or ends at an unstable equilibrium (a negative
        eigenvalue of the tangent) is relaxed whole instead, from the last equilibrium, to a
        stable state at its rest angles (a trust-region descent of the potential energy on
        sparse Cholesky factorisations of the shifted tangent), recorded as a snapped step;
        only where none is found (in 200 iterations) is the increment halved, its parts
        followed as without ``relax`` until one is accepted. ``snap`` then relaxes too. With
        ``adaptive``, the fixed increments a stage falls back to relax.
    give_up_after : int, default 0
        > 0: an increment whose Newton correction at this iteration or later is still above
        1e-3 of its first is given up there and halved, instead of iterating on to
        ``max_iterations`` (0: never).

    Returns
    -------
    PathResult
        ``load_factor`` runs from 0 to the number of stages: stage k is (k - 1, k];
        ``constraint_force`` holds the support reactions [N].
    """
    o = _core.solvers.FoldOptions()
    o.cholesky = cholesky_choice(cholesky)
    o.tolerance = as_positive_real("tolerance", tolerance)
    o.max_iterations = as_integer("max_iterations", max_iterations, minimum=1)
    o.give_up_after = as_integer("give_up_after", give_up_after, minimum=0)
    o.max_bisections = as_integer("max_bisections", max_bisections, minimum=0)
    o.extrapolation = as_integer("extrapolation", extrapolation, minimum=0, maximum=3)
    o.adaptive = as_bool("adaptive", adaptive)
    o.adaptive_tolerance = as_positive_real("adaptive_tolerance", adaptive_tolerance)
    o.snap = as_bool("snap", snap)
    o.relax = as_bool("relax", relax)
    o.shift = as_real("shift", shift)
    if stop is not None and not callable(stop):
        raise ValueError(f"stop = {stop!r} is invalid: must be None or a callable")
    o.stop = stop
    core_stages = [(hinges.tolist(), targets) for hinges, targets in fold_stages(stages)]
    load = np.zeros(model.num_dofs) if forces is None else dof_vector(model, "forces", forces)
    core = _core.solvers.fold(model._core, core_stages, as_integer("steps", steps, minimum=1),
                              load, o, dof_vector(model, "initial", initial, allow_none=True))
    return PathResult._from_core(core)


@dataclass(frozen=True)
class FoldResult:
    """A crease pattern folded by :func:`fold`.

    Attributes
    ----------
    path : PathResult
        ``load_factor``: the fold fraction (0 to 1).
    hinges : ndarray of int, shape (K,)
        The driven hinges.
    target_deg : ndarray, shape (K,)
        Their target fold angles [deg], FOLD's convention.
    fold_angle_deg : ndarray, shape (S, H)
        Every hinge's fold angle at every increment [deg].
    """

    path: PathResult
    hinges: np.ndarray
    target_deg: np.ndarray
    fold_angle_deg: np.ndarray

    @property
    def completed(self) -> bool:
        return self.path.completed


def fold(pattern_model, targets, steps, **options) -> FoldResult:
    """Fold a crease pattern's model to fold angles, in ``steps`` increments.

    Parameters
    ----------
    pattern_model : kresling.model.PatternModel
    targets : dict or array_like
        ``{hinge: fold angle [deg]}``, or one angle per hinge (H,) with NaN for the hinges
        left free; FOLD's convention: + valley, - mountain, 0 flat, within [-180, 180].
    steps : int
    **options
        As :func:`solve_fold` (``forces``, ``tolerance``, ``extrapolation``, ...).

    Returns
    -------
    FoldResult
    """
    num_hinges = len(pattern_model.model.hinges)
    if isinstance(targets, dict):
        hinges = np.array(sorted(targets), dtype=np.int64)
        angles = np.array([targets[h] for h in sorted(targets)], dtype=float)
    else:
        values = np.asarray(targets, dtype=float).ravel()
        if values.shape != (num_hinges,):
            raise ValueError(f"targets has {values.size} entries: must be a dict or one per "
                             f"hinge ({num_hinges})")
        hinges = np.flatnonzero(~np.isnan(values))
        angles = values[hinges]
    if hinges.size and (hinges.min() < 0 or hinges.max() >= num_hinges):
        raise ValueError(f"targets: hinge {int(hinges.max())} is out of range [0, {num_hinges})")
    if not np.all(np.isfinite(angles)) or np.any(np.abs(angles) > 180.0):
        raise ValueError("targets: fold angles must be finite and within [-180, 180] deg")
    signs = hinge_fold_signs(pattern_model)
    path = solve_fold(pattern_model.model, [(hinges, rest_angles_for(angles, signs[hinges]))],
                      steps, **options)
    folded = np.array([fold_angles_deg(pattern_model, u, signs) for u in path.displacement])
    return FoldResult(path, hinges, angles, folded.reshape(-1, num_hinges))
