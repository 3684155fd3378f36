"""Vibration modes about any state of a run: a step of a path (a fold's with the rest angles
it has reached there), with the problem's masses.

>>> # modes = modes_at(simulate("fold.toml"), step=-1, k=6)   # about the folded state
"""

from __future__ import annotations

import numpy as np

from kresling._validation import as_integer
from kresling.analyses.modes import Modes, vibration_modes
from kresling.simulate.problem_keys.mass import problem_masses

__all__ = ["modes_at"]


def modes_at(simulation, step: int = -1, *, k: int = 10) -> Modes:
    """The ``k`` lowest vibration modes about step ``step`` of a run's path.

    The tangent is that of the model the step is an equilibrium of
    (:meth:`~kresling.simulate.Simulation.model_at`: a fold's hinges at the rest angles the
    step has reached, not the as-built ones, which would leave the folded state loaded), at
    the step's displacement, its stress stiffness included; the masses are the problem's
    (``[material] density`` and ``[[mass]]``).

    Parameters
    ----------
    simulation : kresling.simulate.Simulation
        A run along a path (any method but modes and a motion in time).
    step : int, default -1
        The step, 0-based (negative: from the end; -1 the end state).
    k : int, default 10
        How many of the lowest modes.

    Returns
    -------
    kresling.analyses.modes.Modes

    Raises
    ------
    ValueError
        For a step out of range, a run with no step, or a problem without masses.
    """
    path = simulation.path
    step = as_integer("step", step)
    if not -path.num_steps <= step < path.num_steps:
        raise ValueError(f"step = {step} is out of range: the path has {path.num_steps} steps "
                         f"(0 to {path.num_steps - 1}, or -1 for the last)")
    problem = simulation.problem
    if problem.sheet_mass.density is None and not problem.masses:
        raise ValueError(f"{problem.source}: the modes need masses: [material] density "
                         "[t/mm^3] (with the sheet's thickness) or [[mass]] entries")
    masses = problem_masses(problem, simulation.pattern_model)
    return vibration_modes(simulation.model_at(step), masses, k=k,
                           u=np.asarray(path.displacement[step]))
