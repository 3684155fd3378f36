"""Workspace maps: where the tip of each configuration can go.

The tendon inputs are the three lengths (l1, l2, l3) shared by every flexible module (the
thesis's identical-module assumption), each within the model's ``tendon_bounds``. A map
samples that box on a regular grid and evaluates the tip.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_integer
from kresling.manipulator.model import Manipulator, configuration_name

__all__ = ["Workspace", "workspace", "workspaces"]


@dataclass(frozen=True)
class Workspace:
    """Tip positions of one configuration over a grid of tendon inputs.

    Attributes
    ----------
    configuration : tuple of int
    tendon_lengths : ndarray, shape (n, 3)
        Grid samples of (l1, l2, l3) per flexible module [mm].
    points : ndarray, shape (n, 3)
        Tip positions [mm]; a single row for a configuration without flexible modules.
    """

    configuration: tuple
    tendon_lengths: np.ndarray
    points: np.ndarray

    @property
    def name(self) -> str:
        return configuration_name(self.configuration)

    @property
    def extent(self) -> np.ndarray:
        """Bounding box of the sampled tip positions [mm], shape (2, 3): min and max rows."""
        return np.stack([self.points.min(axis=0), self.points.max(axis=0)])


def workspace(model: Manipulator, configuration, grid_points: int = 9) -> Workspace:
    """Sample the tip of ``configuration`` on a ``grid_points**3`` grid of tendon inputs.

    Parameters
    ----------
    model : Manipulator
    configuration : str or sequence of int
    grid_points : int, default 9
        Samples per tendon, ``>= 2``.

    Returns
    -------
    Workspace
    """
    configuration = model.configuration(configuration)
    grid_points = as_integer("grid_points", grid_points, minimum=2)
    lower, upper = model.tendon_bounds
    lengths, points = _core.kinematics.sample_workspace(model._chain, configuration, lower, upper,
                                                        grid_points)
    return Workspace(configuration, lengths, points)


def workspaces(model: Manipulator, grid_points: int = 9) -> dict:
    """:func:`workspace` of every configuration, keyed by name (``"000"`` ... ``"111"``)."""
    return {configuration_name(c): workspace(model, c, grid_points) for c in model.configurations}
