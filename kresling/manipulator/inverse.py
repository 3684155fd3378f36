"""Inverse kinematics: which configuration and tendon inputs put the tip on a target.

The thesis's future work asks for a configuration planner; this is one. For every
configuration the tendon lengths (l1, l2, l3), shared by the flexible modules and kept
within ``model.tendon_bounds``, are found by projected damped least squares (a plain loop
in the C++ core, started from the nearest samples of a grid over the tendon box). A target
is reachable when some configuration puts the tip within ``tolerance`` of it; among those
the planner prefers the stiffest arm (fewest flexible modules, which the thesis found the
most accurate), then the smallest tendon travel. Otherwise the result says
``reachable=False`` and gives the nearest point any configuration reaches.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, as_integer, as_list, as_real, show
from kresling.manipulator.model import Manipulator, configuration_name

__all__ = ["InverseKinematicsResult", "inverse_kinematics", "solve_configuration"]

logger = logging.getLogger(__name__)


@dataclass(frozen=True)
class InverseKinematicsResult:
    """What the planner chose for one target.

    Attributes
    ----------
    target : ndarray, shape (3,)
        [mm]
    reachable : bool
        Whether the chosen configuration reaches the target within the tolerance.
    configuration : tuple of int
        The chosen configuration; when unreachable, the one whose tip comes nearest.
    tendon_lengths : ndarray, shape (3,)
        (l1, l2, l3) of every flexible module [mm].
    position : ndarray, shape (3,)
        Tip position at those inputs [mm]: the target, or the nearest reachable point.
    distance : float
        ``|position - target|`` [mm].
    candidates : dict
        Per configuration name: ``(distance, tendon_lengths)`` of its best solve.
    """

    target: np.ndarray
    reachable: bool
    configuration: tuple
    tendon_lengths: np.ndarray
    position: np.ndarray
    distance: float
    candidates: dict = field(default_factory=dict)

    @property
    def nearest_reachable_point(self) -> np.ndarray:
        """The reachable point nearest the target [mm] (the target itself when reachable)."""
        return self.position


def solve_configuration(model: Manipulator, configuration, targets, *, tolerance: float = 1e-10,
                        max_iterations: int = 100, grid_points: int = 7, starts: int = 3) -> dict:
    """Damped-least-squares solves of one configuration for many targets (C++, no GIL).

    Parameters
    ----------
    model : Manipulator
    configuration : str or sequence of int
    targets : array_like, shape (3,) or (n, 3)
        [mm]
    tolerance : float
        Convergence threshold on the distance [mm].
    max_iterations, grid_points, starts : int
        Iterations per start; seed grid per tendon; starts from the nearest seeds.

    Returns
    -------
    dict of ndarray
        ``tendon_lengths`` (n, 3), ``position`` (n, 3), ``distance`` (n,),
        ``iterations`` (n,), ``converged`` (n,).
    """
    configuration = model.configuration(configuration)
    targets = np.atleast_2d(as_float_array("targets", targets))
    if targets.ndim != 2 or targets.shape[1] != 3 or not np.isfinite(targets).all():
        raise ValueError(f"targets = {show(targets.tolist())} is invalid: must be finite points "
                         "of shape (3,) or (n, 3) [mm]")
    lower, upper = model.tendon_bounds
    table = _core.kinematics.solve_inverse_kinematics(
        model._chain, configuration, targets, lower, upper, as_real("tolerance", tolerance),
        as_integer("max_iterations", max_iterations), 1.0,
        as_integer("grid_points", grid_points), as_integer("starts", starts))
    # Every field of the core's InverseKinematicsTable, in its order, as an array of its own.
    return {name: np.ascontiguousarray(getattr(table, name))
            for name, value in type(table).__dict__.items() if isinstance(value, property)}


def inverse_kinematics(model: Manipulator, target, *, configurations=None,
                       tolerance: float = 1e-6) -> InverseKinematicsResult:
    """Choose a configuration and tendon inputs that put the tip on ``target``.

    Parameters
    ----------
    model : Manipulator
    target : array_like, shape (3,)
        Target point [mm] in the frame of eqn 26.
    configurations : iterable, optional
        Configurations to consider (default: all ``2**m``).
    tolerance : float, default 1e-6
        Distance [mm] within which a target counts as reached.

    Returns
    -------
    InverseKinematicsResult
        Never raises for an unreachable target: ``reachable`` is False and ``position`` is
        the nearest reachable point found.

    Examples
    --------
    >>> from kresling.manipulator import forward_kinematics
    >>> arm = Manipulator()
    >>> target = forward_kinematics(arm, "101", [22.0, 34.0, 31.0]).tip
    >>> result = inverse_kinematics(arm, target)
    >>> result.reachable, bool(result.distance < 1e-6)
    (True, True)
    >>> far = inverse_kinematics(arm, [0.0, 0.0, 1000.0])
    >>> far.reachable, configuration_name(far.configuration), far.position.round(2).tolist()
    (False, '111', [0.0, 0.0, 334.92])
    """
    target = as_float_array("target", target)
    if target.shape != (3,) or not np.isfinite(target).all():
        raise ValueError(f"target = {show(target.tolist())} is invalid: must be 3 finite numbers "
                         "(mm)")
    tolerance = as_real("tolerance", tolerance)
    if configurations is None:
        configurations = model.configurations
    configurations = as_list("configurations", configurations, "configurations (e.g. '101')")
    if not configurations:
        raise ValueError("configurations is empty: name at least one (e.g. '101')")
    rest = model.rest_tendon_length
    candidates, ranked = {}, []
    for configuration in (model.configuration(c) for c in configurations):
        solved = solve_configuration(model, configuration, target)
        lengths, distance = solved["tendon_lengths"][0], float(solved["distance"][0])
        candidates[configuration_name(configuration)] = (distance, lengths)
        flexible = sum(1 for s in configuration if s == 0)
        travel = float(np.abs(lengths - rest).max()) if flexible else 0.0
        # Reachable first: fewest flexible modules, then least tendon travel.
        # Unreachable after: nearest first.
        key = (0, flexible, travel) if distance <= tolerance else (1, distance, 0.0)
        ranked.append((key, configuration, lengths, solved["position"][0], distance))
    if not ranked:
        raise ValueError("configurations is empty: give at least one configuration")
    key, configuration, lengths, position, distance = min(ranked, key=lambda r: r[0])
    logger.debug("IK target %s: %s at %.3g mm", target, configuration_name(configuration), distance)
    return InverseKinematicsResult(target, key[0] == 0, configuration, lengths, position,
                                   distance, candidates)
