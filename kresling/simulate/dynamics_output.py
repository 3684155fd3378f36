"""``method = "dynamic"``: a problem's motion in time, and its files.

A dynamic run builds the problem's model with its supports and node masses (the sheet's
density and ``[[mass]]``, :mod:`kresling.simulate.problem_keys.mass`), and integrates it over
``[dynamics] duration`` (:func:`kresling.solvers.solve_dynamics`) under its ``[[load]]``
forces, each with its time function, and gravity, its ``[[actuation]]`` driving creases' rest
angles in time (:mod:`kresling.simulate.driven_creases`). It writes what a path writes
(:func:`kresling.simulate.outputs.write_outputs`: history.csv, displacements.csv,
path.fold, summary.json, view.html) with

- ``history.csv``: ``step``, ``time`` [s], ``energy_kinetic``, ``energy_strain``,
  ``energy_damping`` (dissipated so far) and ``work_external`` (the loads' and gravity's
  work so far) [N*mm], the energy by element family and Newton's iterations; with an
  actuation also ``work_actuation`` (the driven rest angles' work on the sheet so far
  [N*mm]) and, per entry i, ``actuation_<i>_factor`` (its time function's factor);
- ``velocities.csv``: the velocities [mm/s], laid out as displacements.csv;
- ``view.html`` played in real time scaled so the run lasts :data:`PLAYBACK_SECONDS`, the
  scale in its title; path.fold's frames titled with their time.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.simulate.driven_creases import crease_drives, rest_angles_at
from kresling.simulate.outputs import kept_rows, write_float_csv
from kresling.simulate.problem_keys.mass import problem_masses
from kresling.simulate.simulation import Simulation
from kresling.solvers import solve_dynamics, with_parameter

__all__ = ["DynamicRun", "run_dynamics", "PLAYBACK_SECONDS"]

#: How long the view's playback of a whole run lasts [s of wall time].
PLAYBACK_SECONDS = 5.0


@dataclass(frozen=True)
class DynamicRun(Simulation):
    """A problem, its model, masses and motion in time.

    Attributes
    ----------
    history : kresling.solvers.TimeHistory
        ``history.path`` is :attr:`Simulation.path` (its load factor is the time [s]).
    masses : ndarray, shape (N,)
        Node masses [t].
    drives : tuple of CreaseDrive
        The ``[[actuation]]`` entries driving creases in time (empty: none).
    """

    history: object = None
    masses: np.ndarray = None
    drives: tuple = ()

    def model_at(self, step: int = -1):
        """The model at the path's ``step`` (0-based, negative from the end): its driven
        creases at the rest angles of that step's time."""
        time = float(self.path.load_factor[step])  # an IndexError names a bad step
        if not self.drives:
            return self.model
        return with_parameter(self.model, "hinges.rest_angle",
                              rest_angles_at(self.model, self.drives, time))

    def history_columns(self) -> dict:
        h = self.history
        columns = {"step": np.arange(1, self.path.num_steps + 1), "time": h.time,
                   "energy_kinetic": h.kinetic, "energy_strain": h.strain,
                   "energy_damping": h.dissipated, "work_external": h.work}
        if self.drives:
            columns["work_actuation"] = h.actuation_work
            for drive in self.drives:
                columns[f"actuation_{drive.entry}_factor"] = drive.factor(h.time)
        stop = self.problem.analysis.stop
        if stop is not None:
            columns[f"u_{stop.node}_{stop.axis}"] = self.path.displacement[:, stop.dof]
        families = super().history_columns()
        for name, values in families.items():
            if name.startswith(("energy_", "reaction_planes_")) or name in ("min_gap",
                                                                             "iterations"):
                columns[name] = values
        return columns

    def playback(self):
        """``(times [s] of the path's rows, wall seconds per simulated second)`` of the view."""
        duration = self.problem.dynamics.duration
        return np.asarray(self.history.time, dtype=float), PLAYBACK_SECONDS / duration

    def summary(self) -> dict:
        h, d = self.history, self.problem.dynamics
        out = super().summary()
        out.pop("final_load_factor", None)
        last = self.path.num_steps - 1
        out.update({
            "scheme": d.scheme, "time_step": float(h.time_step), "duration": d.duration,
            "stable_time_step": None if np.isnan(h.stable_time_step)
            else float(h.stable_time_step),
            "total_mass_t": float(self.masses.sum()),
            "final_time": float(h.time[-1]) if last >= 0 else None,
            "final_energy": ({"kinetic": float(h.kinetic[last]), "strain": float(h.strain[last]),
                              "damping": float(h.dissipated[last]),
                              "work_external": float(h.work[last]),
                              **({"work_actuation": float(h.actuation_work[last])}
                                 if self.drives else {})} if last >= 0 else None),
            "playback_scale": PLAYBACK_SECONDS / d.duration})
        return out

    def write(self, directory, *, view=True, every=None) -> dict:
        """Write history.csv, displacements.csv, velocities.csv, path.fold, summary.json
        (and view.html) into ``directory``; returns the paths by name."""
        from pathlib import Path

        from kresling.simulate.outputs import write_outputs

        written = write_outputs(self, directory, view=view, every=every)
        every = self.problem.output.every if every is None else every
        rows = kept_rows(self.path.num_steps, every)
        header = [f"{axis}{node}" for node in range(self.model.num_nodes) for axis in "xyz"]
        written["velocities"] = Path(directory) / "velocities.csv"
        write_float_csv(written["velocities"], header, np.asarray(self.history.velocity)[rows])
        return written


def run_dynamics(problem, pattern_model, *, stop=None, start=None) -> DynamicRun:
    """Integrate the problem's model in time (``[dynamics]``, the loads' times, gravity).

    ``stop(time, displacement) -> bool`` (optional) ends the motion early; ``start`` (a
    :class:`~kresling.simulate.start_state.StartState`) is where the stage before ended:
    the motion starts from its displacement and velocity (its loads are the model's)."""
    masses = problem_masses(problem, pattern_model)
    model, d = pattern_model.model, problem.dynamics
    drives = crease_drives(problem, pattern_model) if problem.actuations else ()
    loads = []
    for load in problem.loads:
        vector = np.zeros(model.num_dofs)
        for node in load.nodes:
            vector[3 * node:3 * node + 3] += load.vector
        loads.append((vector, None if load.time is None else load.time.for_solver()))
    initial = velocity = None
    if start is not None:   # (its loads are held by the model's forces family)
        initial, velocity = start.displacement, start.velocity
    try:
        history = solve_dynamics(
            model, masses, d.time_step, d.duration, gravity=d.gravity, loads=loads,
            scheme=d.scheme, hht_alpha=d.hht_alpha, mass_damping=d.alpha,
            stiffness_damping=d.beta, damping_tangent=d.damping_tangent,
            actuation=[drive.for_solver() for drive in drives], tolerance=problem.analysis.tolerance,
            max_iterations=problem.analysis.max_iterations, record_every=d.record_every,
            initial=initial, initial_velocity=velocity, stop=stop)
    except ValueError as error:
        raise ValueError(f"{problem.source}: [dynamics]: {error}") from None
    driven = np.flatnonzero(sum((v for v, _ in loads), np.zeros(model.num_dofs)))
    return DynamicRun(problem, pattern_model, history.path, driven.astype(np.int64), None,
                      history=history, masses=masses, drives=drives)
