"""Per-element histories along a path: what each bar and hinge did at every increment, and
the stored energy split into bars, folds and bends."""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import numpy as np

__all__ = ["ElementHistories", "element_histories", "keep_element_states"]


@dataclass(frozen=True)
class ElementHistories:
    """Element states at every increment of a path (S increments, B bars, H hinges).

    Attributes
    ----------
    bar_strain : ndarray, shape (S, B)
        Green-Lagrange strain.
    bar_stress : ndarray, shape (S, B)
        Second Piola-Kirchhoff stress [N/mm^2].
    bar_energy : ndarray, shape (S, B)
        [N*mm]
    hinge_angle : ndarray, shape (S, H)
        Dihedral angle [rad] (pi when flat).
    hinge_moment : ndarray, shape (S, H)
        Moment [N*mm] (the law's moment per unit length times the hinge length).
    hinge_energy : ndarray, shape (S, H)
        [N*mm]
    hinge_family : tuple of str, length H
        Family of each hinge ("bend" or a fold family: "mountain", "valley", ...).
    """

    bar_strain: np.ndarray
    bar_stress: np.ndarray
    bar_energy: np.ndarray
    hinge_angle: np.ndarray
    hinge_moment: np.ndarray
    hinge_energy: np.ndarray
    hinge_family: tuple

    def energy_by_family(self) -> dict:
        """Stored energy per increment [N*mm]: ``bars``, ``folds`` (every fold family),
        ``bends`` and ``total``, each of shape (S,)."""
        bend = np.array([f == "bend" for f in self.hinge_family], dtype=bool)
        bars = self.bar_energy.sum(axis=1)
        folds = self.hinge_energy[:, ~bend].sum(axis=1)
        bends = self.hinge_energy[:, bend].sum(axis=1)
        return {"bars": bars, "folds": folds, "bends": bends, "total": bars + folds + bends}

    def angle_change(self, rest_angle) -> np.ndarray:
        """Hinge angle minus its rest angle (S, H) [rad]."""
        return self.hinge_angle - np.asarray(rest_angle)[None, :]


_NAMES = ("bar_strain", "bar_stress", "bar_energy", "hinge_angle", "hinge_moment",
          "hinge_energy")

#: The element states of the model of a run that writes its history row by row as its path
#: goes (:func:`keep_element_states`), by the displacement's bytes: each increment is
#: evaluated once for its row, and the history written whole at the run's end takes them
#: (and lets them go) instead of evaluating them again. One model at a time, at most
#: :data:`_KEPT_VALUES` values.
_kept_states = weakref.WeakKeyDictionary()
_KEPT_VALUES = 8_000_000


def keep_element_states(model) -> None:
    """Keep the element states of ``model`` evaluated from now on (for one later evaluation
    of each), letting go of those kept for any other model."""
    _kept_states.clear()
    _kept_states[model] = {"values": 0, "states": {}}


def _element_state(model, u) -> tuple:
    """The arrays of :data:`_NAMES` of ``model.element_state(u)``; a state kept by
    :func:`keep_element_states` is taken instead of evaluated again."""
    kept = _kept_states.get(model)
    if kept is None:
        values = model.element_state(u)
        return tuple(values[name] for name in _NAMES)
    key = np.asarray(u, dtype=float).tobytes()
    state = kept["states"].pop(key, None)
    if state is not None:
        kept["values"] -= sum(len(a) for a in state)
        return state
    values = model.element_state(u)
    state = tuple(values[name] for name in _NAMES)
    size = sum(len(a) for a in state)
    if kept["values"] + size <= _KEPT_VALUES:
        kept["states"][key] = state
        kept["values"] += size
    return state


def element_histories(pattern_model, path) -> ElementHistories:
    """Evaluate every element at every increment of ``path``.

    Parameters
    ----------
    pattern_model : PatternModel or Model
        A Model's hinges all count as folds.
    path : kresling.solvers.PathResult

    Returns
    -------
    ElementHistories
    """
    model = getattr(pattern_model, "model", pattern_model)
    family = getattr(pattern_model, "hinge_family", ("unassigned",) * len(model.hinges))
    rows = {name: [] for name in _NAMES}
    for u in path.displacement:
        for name, values in zip(_NAMES, _element_state(model, u)):
            rows[name].append(values)
    sizes = {"bar": len(model.bars), "hinge": len(model.hinges)}
    arrays = {name: (np.array(rows[name]) if rows[name]
                     else np.zeros((0, sizes[name.split("_")[0]]))) for name in _NAMES}
    return ElementHistories(**arrays, hinge_family=tuple(family))
