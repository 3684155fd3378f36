"""Per-element histories along a path: what each bar and hinge did at every increment, and
the stored energy split into bars, folds and bends."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["ElementHistories", "element_histories"]


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
    names = ("bar_strain", "bar_stress", "bar_energy", "hinge_angle", "hinge_moment",
             "hinge_energy")
    rows = {name: [] for name in names}
    for u in path.displacement:
        state = model.element_state(u)
        for name in names:
            rows[name].append(state[name])
    sizes = {"bar": len(model.bars), "hinge": len(model.hinges)}
    arrays = {name: (np.array(rows[name]) if rows[name]
                     else np.zeros((0, sizes[name.split("_")[0]]))) for name in names}
    return ElementHistories(**arrays, hinge_family=tuple(family))
