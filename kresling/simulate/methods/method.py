"""What an analysis method is: the settings it reads, the checks it makes of a problem, how
it runs and what it records. :class:`Method` is the interface; :class:`PathMethod` the
methods that follow an equilibrium path increment by increment (their run is
:func:`kresling.simulate.run.simulate`'s)."""

from __future__ import annotations

import numpy as np

from kresling.simulate.curve import moving_dof
from kresling.simulate.problem_table import count

__all__ = ["Method", "PathMethod", "STEPS_REQUIRED"]

#: The words of a required ``steps`` key.
STEPS_REQUIRED = "the number of increments (an integer >= 1)"


class Method:
    """An analysis method. Subclasses set the class attributes that differ and override
    what they do differently.

    Attributes
    ----------
    name : str
        ``[analysis] method``'s value.
    follows_path : bool
        Follows an equilibrium path (:class:`PathMethod`); otherwise :meth:`run` runs it.
    monitors : bool
        Reads ``[analysis.stop]`` (a node's displacement that ends the run).
    in_time : bool
        A motion in time: loads may vary in time, ``[dynamics]`` applies.
    drives_creases : bool
        Drives creases (``[[actuation]]`` applies, and is needed).
    drives_displacements : bool
        The loads are prescribed displacements (reactions are recorded).
    holds_free_sheet : bool
        Without ``[[support]]``, the free sheet's rigid-body motions are held.
    default_preset : str or None
        The material preset used when the problem gives no ``[material]``.
    """

    name = ""
    follows_path = False
    monitors = True
    in_time = False
    drives_creases = False
    drives_displacements = False
    holds_free_sheet = False
    default_preset = None

    def read_settings(self, t) -> dict:
        """This method's own keys of ``[analysis]`` (``t``), as Analysis fields."""
        return {}

    def check(self, problem, t) -> None:
        """Refuse what the whole problem asks that this method cannot do (``t``: the
        ``[analysis]`` table, to name its keys)."""

    def finalize(self, problem, t):
        """The problem with any setting that depends on other keys settled (default:
        unchanged)."""
        return problem

    def stepping(self, problem) -> str:
        """How the run steps, in words (the summary's record of it)."""
        raise NotImplementedError

    def history_columns(self, simulation) -> dict:
        """history.csv's columns of this method (after step and load_factor): the
        monitored DOF's displacement."""
        stop = simulation.problem.analysis.stop
        if stop is None:
            return {}
        return {f"u_{stop.node}_{stop.axis}": simulation.path.displacement[:, stop.dof]}

    def run(self, problem, pattern_model, *, stop=None, start=None):
        """Run a method that does not follow a path; returns its run object (``start``: a
        :class:`~kresling.simulate.start_state.StartState`, the stage before's end)."""
        raise NotImplementedError(f"method {self.name!r} follows a path")


class PathMethod(Method):
    """A method that follows an equilibrium path increment by increment."""

    follows_path = True
    #: Whether the path may be bounded by ``max_load_factor`` by the run's stopping rule.
    bounded = False
    #: Whether the core checks the monitor itself (MGDCM).
    checks_own_monitor = False

    def read_steps(self, t, default=None) -> dict:
        """``steps``: required without a default."""
        if default is None:
            return {"steps": t.get("steps", count, required=True, allowed=STEPS_REQUIRED)}
        return {"steps": t.get("steps", count, default)}

    def plan(self, problem, pattern_model):
        """What the solve needs beyond the loads (a fold's stages), or None."""
        return None

    def solve(self, problem, pattern_model, vector, common, plan):
        """The path (:class:`kresling.solvers.PathResult`): ``vector`` the loads summed
        per DOF, ``common`` the solvers' shared options, ``plan`` from :meth:`plan`."""
        raise NotImplementedError

    def recorded_dofs(self, vector, model) -> np.ndarray:
        """The DOFs whose reactions the path records (the solver's constraint DOFs)."""
        return np.flatnonzero(model.fixed.ravel())

    def driven_dofs(self, path, vector) -> np.ndarray:
        """The DOFs that carry the drive: those with a force."""
        return np.flatnonzero(vector)

    def curve(self, simulation, columns) -> tuple:
        """The view's default curve ``(x, y, x_label, y_label)``: the monitored (or
        busiest) DOF's displacement against the load factor."""
        u, label = moving_dof(simulation, simulation.problem.analysis.stop)
        return u, np.asarray(simulation.path.load_factor, dtype=float), label, "load factor [-]"

    def progress_total(self, analysis) -> int:
        """The progress bar's length."""
        return analysis.steps

    def progress_done(self, analysis, count, load_factor, u) -> float:
        """Where the progress bar is after ``count`` increments (the load factor runs
        from 0 to 1 over the steps)."""
        return load_factor * analysis.steps

    def advice(self, problem, path, interrupted) -> str:
        """A word on a path that stopped early, appended to its message ("" for none)."""
        return ""
