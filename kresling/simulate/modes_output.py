"""``method = "modes"``: a problem's vibration modes about its rest state (or the loaded
equilibrium an ``[analysis.about]`` table names), and their files.

A modes run builds the problem's model with its supports, its node masses (the sheet's
density and ``[[mass]]``, :mod:`kresling.simulate.problem_keys.mass`) and the lowest
``[analysis] modes`` modes (:func:`kresling.analyses.modes.vibration_modes`). It writes

- ``modes.csv``: one row per mode: ``mode`` (1-based), ``frequency_hz``, ``participation_x``,
  ``_y``, ``_z`` (``phi^T M r`` [t^0.5], mass-normalised shapes), ``effective_mass_x``,
  ``_y``, ``_z`` (fractions of the free mass along each axis) and ``rigid`` (1 for a
  rigid-body or mechanism mode);
- ``path.fold``: the model's triangles, the rest state as key frame and one frame per mode,
  the shape scaled so its largest node displacement is :data:`SHAPE_SCALE` of the model's
  size (its bounding box's largest side);
- ``summary.json``: sizes, masses and the frequencies.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kresling.analyses.modes import Modes, vibration_modes
from kresling.io import write_fold
from kresling.simulate.outputs import path_fold_edges, write_csv
from kresling.simulate.problem_keys.mass import problem_masses
from kresling.solvers import solve_force_control

__all__ = ["ModesRun", "run_modes", "SHAPE_SCALE"]

#: Largest node displacement of a mode's frame in path.fold, over the model's size.
SHAPE_SCALE = 0.1


@dataclass(frozen=True)
class ModesRun:
    """A problem, its model and masses, and the modes about its rest (or loaded) state.

    Attributes
    ----------
    problem : Problem
    pattern_model : PatternModel
    masses : ndarray, shape (N,)
        Node masses [t].
    modes : Modes
    """

    problem: object
    pattern_model: object
    masses: np.ndarray
    modes: Modes
    #: A modes run has no path that may stop early.
    completed: bool = True
    #: The displacement of the state the modes are about (all DOFs [mm]; None: the rest).
    state: np.ndarray | None = None

    @property
    def model(self):
        return self.pattern_model.model

    def summary(self) -> dict:
        model, modes = self.model, self.modes
        about = self.problem.analysis.about
        about = about if isinstance(about, str) else about.describe()
        return {"source": self.problem.source, "method": "modes",
                "about": about, "nodes": model.num_nodes,
                "bars": len(model.bars), "hinges": len(model.hinges),
                "supported_dofs": int(model.fixed.sum()), "modes": modes.count,
                "total_mass_t": float(self.masses.sum()),
                "rigid_modes": int(modes.rigid.sum()),
                "frequencies_hz": modes.frequencies_hz.tolist(), "completed": True}

    def write(self, directory, *, view=True, every=None) -> dict:
        """Write modes.csv, path.fold and summary.json into ``directory``; returns the paths
        by name (``view`` and ``every`` apply to paths and are ignored here)."""
        directory = Path(directory)
        directory.mkdir(parents=True, exist_ok=True)
        m = self.modes
        header = ["mode", "frequency_hz", "participation_x", "participation_y",
                  "participation_z", "effective_mass_x", "effective_mass_y",
                  "effective_mass_z", "rigid"]
        rows = [[j + 1, float(m.frequencies_hz[j]), *m.participation[j].tolist(),
                 *m.effective_mass_fraction[j].tolist(), int(m.rigid[j])]
                for j in range(m.count)]
        written = {"modes": directory / "modes.csv"}
        write_csv(written["modes"], header, rows)
        written["fold"] = directory / "path.fold"
        self._write_fold(written["fold"])
        written["summary"] = directory / "summary.json"
        written["summary"].write_text(json.dumps(self.summary(), indent=2) + "\n")
        return written

    def _write_fold(self, path):
        model, m = self.model, self.modes
        nodes = np.asarray(model.nodes)
        if self.state is not None:       # the shapes about the loaded state
            nodes = nodes + self.state.reshape(-1, 3)
        size = float(np.ptp(nodes, axis=0).max())
        shapes = m.shapes.reshape(m.count, model.num_nodes, 3)
        largest = np.linalg.norm(shapes, axis=2).max(axis=1)
        scale = np.where(largest > 0, SHAPE_SCALE * size / np.where(largest > 0, largest, 1), 0)
        frames = nodes[None] + scale[:, None, None] * shapes
        edges, assignment = path_fold_edges(self.pattern_model)
        state = "rest state" if self.state is None else "loaded state"
        titles = [f"{Path(self.problem.source).name}: {state}"] + [
            f"mode {j + 1}: {m.frequencies_hz[j]:.6g} Hz" for j in range(m.count)]
        write_fold(path, nodes, [tuple(t) for t in self.pattern_model.elements.triangles],
                   edges=edges, edges_assignment=assignment, frames=frames, frame_title=titles,
                   metadata={"file_description": "vibration modes computed by kresling "
                                                 "simulate; one frame per mode"})


def _loaded_state(problem, model):
    """The equilibrium an [analysis.about] table names: force control under its load
    factor times the [[load]] forces (all DOFs [mm])."""
    about, analysis = problem.analysis.about, problem.analysis
    forces = np.zeros(model.num_dofs)
    for load in problem.loads:
        for node in load.nodes:
            forces[3 * node:3 * node + 3] += load.vector
    try:
        path = solve_force_control(model, about.load_factor * forces, about.steps,
                                   tolerance=analysis.tolerance,
                                   max_iterations=analysis.max_iterations)
    except ValueError as error:
        raise ValueError(f"{problem.source}: [analysis.about]: {error}") from None
    if not path.completed:
        raise ValueError(f"{problem.source}: [analysis.about]: force control did not reach "
                         f"load factor {about.load_factor:g} ({path.message}): the modes "
                         "need an equilibrium")
    return np.asarray(path.displacement[-1])


def run_modes(problem, pattern_model, *, state=None) -> ModesRun:
    """The lowest ``problem.analysis.modes`` modes of the problem's model at rest, about the
    loaded equilibrium its ``[analysis.about]`` names, or about ``state`` (a displacement
    of every DOF [mm]: where the stage before ended)."""
    masses = problem_masses(problem, pattern_model)
    model = pattern_model.model
    if state is None and problem.analysis.about != "rest":
        state = _loaded_state(problem, model)
    try:
        modes = vibration_modes(model, masses, k=problem.analysis.modes, u=state)
    except ValueError as error:
        raise ValueError(f"{problem.source}: [analysis] method = 'modes': {error}") from None
    return ModesRun(problem, pattern_model, masses, modes, state=state)
