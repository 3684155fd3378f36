"""Where a run starts when it is not the first of a problem's stages: the state the previous
stage ended in (docs/simulate.md, '[[stage]]')."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

# The package, its sensitivities read when first used (a run from rest needs none).
from kresling import solvers

__all__ = ["StartState"]


@dataclass(frozen=True)
class StartState:
    """The end of a stage, where the next one starts.

    Attributes
    ----------
    rest_angle : ndarray, shape (H,)
        Every hinge's rest angle [rad] (a fold's driven creases where it left them).
    displacement : ndarray, shape (3N,)
        The displacement of every node [mm].
    velocity : ndarray, shape (3N,), or None
        After a motion in time, the velocities [mm/s]; None: at rest.
    forces : ndarray, shape (3N,)
        The loads applied so far and held [N]: the forces of the stages before (a force's
        value where its stage ended, a displacement drive's reaction).
    """

    rest_angle: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray | None
    forces: np.ndarray

    @property
    def loaded(self) -> bool:
        return bool(np.any(self.forces))

    def applied_to(self, pattern_model):
        """``pattern_model`` with its hinges at the rest angles this state holds, and its
        loads held on it (the model's ``forces`` family: constant forces, whatever the
        stage's own method applies besides)."""
        model = solvers.with_parameter(pattern_model.model, "hinges.rest_angle", self.rest_angle)
        if self.loaded:
            per_node = self.forces.reshape(-1, 3)
            nodes = np.flatnonzero(np.any(per_node != 0.0, axis=1))
            model = model.with_families({"forces": {"nodes": nodes.astype(np.int64),
                                                    "force": per_node[nodes]}})
        return dataclasses.replace(pattern_model, model=model)
