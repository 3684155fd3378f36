"""Sensitivities along a fold (crease actuation, :func:`~kresling.solvers.solve_fold`).

A fold has no history either: step k is the equilibrium of the model whose driven hinges
rest at the angles the stages have reached at that step (the load, if any, at its ramp's
value). Its derivative at a fixed fraction of the fold is that equilibrium's, with the
model's parameters as they are at the step. The targets are parameters too: a driven
hinge's rest angle at step k moves with its stage's target by the fraction the stage has
covered (1 once it is done, until a later stage drives the hinge again, from that target:
then by 1 minus that stage's fraction).
"""

from __future__ import annotations

import numpy as np

from kresling.solvers.fold import fold_stages
from kresling.solvers.path import PathResult
from kresling.solvers.sensitivity import (Direction, Parameter, PathSensitivity,
                                          equilibrium_sensitivity, with_parameter)

__all__ = ["fold_sensitivity", "fold_model_at"]


def _stages(stages) -> list:
    out = fold_stages(stages)
    for k, (hinges, targets) in enumerate(out):
        if hinges.shape != targets.shape:
            raise ValueError(f"stages[{k}]: {hinges.size} hinges but {targets.size} targets")
    if not out:
        raise ValueError("stages is empty: give the fold's stages")
    return out


def _rest_angles_at(rest, stages, t):
    """The hinges' rest angles at the fold's load factor t, and d(rest)/d(target) for every
    (stage, hinge) pair in stage order (H, T)."""
    rest = rest.copy()
    pairs = [(s, i) for s, (hinges, _) in enumerate(stages) for i in range(hinges.size)]
    weights = np.zeros((rest.size, len(pairs)))
    column = {pair: j for j, pair in enumerate(pairs)}
    driven_by = {}  # hinge -> the column of the target it rests at (or moves from)
    for s, (hinges, targets) in enumerate(stages):
        fraction = min(max(t - s, 0.0), 1.0)
        if fraction == 0.0 and s > 0:
            break
        for i, (h, target) in enumerate(zip(hinges, targets)):
            start = rest[h]
            rest[h] = start + fraction * (target - start)
            # The start is the previous target (if any): it keeps 1 - fraction of its weight.
            previous = driven_by.get(int(h))
            weights[h, :] *= 0.0
            if previous is not None:
                weights[h, previous] = 1.0 - fraction
            weights[h, column[(s, i)]] = fraction
            driven_by[int(h)] = column[(s, i)]
    return rest, weights, pairs


def fold_model_at(model, stages, load_factor: float):
    """The model as a fold has made it at ``load_factor`` (stage k runs over (k - 1, k]):
    its driven hinges at the rest angles the stages have reached there, the rest as built.
    The equilibrium of a fold's step is this model's; its tangent, energies and vibration
    modes are this model's at the step's displacement. ``model`` is the one the fold
    started from, ``stages`` as given to :func:`~kresling.solvers.solve_fold`,
    ``load_factor`` the step's (``path.load_factor[k]``)."""
    rest, _, _ = _rest_angles_at(np.asarray(model.hinge_rest_angle, dtype=float),
                                 _stages(stages), float(load_factor))
    return with_parameter(model, "hinges.rest_angle", rest)


def fold_sensitivity(model, stages, path: PathResult, parameters=(), *,
                     targets=False) -> PathSensitivity:
    """The derivatives of every step of a fold by the model's parameters and (``targets``)
    by the stages' targets.

    Parameters
    ----------
    model : kresling.model.Model
        The model the fold started from.
    stages : sequence of (hinges, targets)
        As given to :func:`~kresling.solvers.solve_fold`.
    path : PathResult
        Its result; it must have completed.
    parameters : sequence of str, Parameter or Direction
        Columns of the model's tables (a driven hinge's ``hinges.rest_angle`` entry is its
        actuated value at each step).
    targets : bool, default False
        Also the derivative by every stage's target, one column per (stage, hinge), named
        ``"stage s target[i]"`` [per rad].

    Returns
    -------
    PathSensitivity
        ``constraint_force``: the support reactions' derivatives.

    Raises
    ------
    ValueError
        For a path that did not complete or bad stages, and at a step whose tangent is
        singular.
    """
    if not path.completed:
        raise ValueError(f"path did not complete ({path.message}): its derivatives are refused "
                         "(they would be those of a fold that stopped early)")
    stages = _stages(stages)
    parameters = tuple(p if isinstance(p, Direction) else Parameter.parse(p) for p in parameters)
    base = np.asarray(model.hinge_rest_angle, dtype=float)
    dofs = np.asarray(path.constraint_dofs, dtype=np.int64)
    out_du, out_dc, out_de = [], [], []
    names = None
    for k, t in enumerate(path.load_factor):
        rest, weights, pairs = _rest_angles_at(base, stages, float(t))
        step_model = with_parameter(model, "hinges.rest_angle", rest)
        extra = ([Direction(f"stage {s} target[{i}]",
                            columns={"hinges.rest_angle": weights[:, j]})
                  for j, (s, i) in enumerate(pairs)] if targets else [])
        everything = parameters + tuple(extra)
        if names is None:
            names = tuple(p.label for p in everything)
        # An external load is at its ramp's value for this fraction: it does not depend on
        # the parameters, and the derivative needs only the tangent and df_int/dp.
        try:
            sens = equilibrium_sensitivity(step_model, path.displacement[k], everything)
        except ValueError as error:
            raise ValueError(f"step {k} of the fold: {error}") from None
        order = {int(d): i for i, d in enumerate(sens.held_dofs)}
        out_du.append(sens.displacement)
        out_dc.append(sens.held_force[[order[int(d)] for d in dofs]])
        out_de.append(sens.energy)
    return PathSensitivity(parameters=names, displacement=np.array(out_du),
                           constraint_force=np.array(out_dc), energy=np.array(out_de))
