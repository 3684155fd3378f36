"""A run's files written as its path goes, so that a run stopped by any means (Ctrl-C, a
kill, a crash, a lost machine) leaves the path up to where it got.

- ``history.csv`` and ``displacements.csv`` get their row as each increment is accepted
  (every ``every``-th, as the final files keep them), flushed at once;
- ``summary.json`` and ``path.fold`` (every increment so far as a frame) are rewritten
  whole, each through a temporary file renamed over the old one, so that either file is
  always complete: at the start (summary.json alone, before the first increment), and then
  whenever the time since the last rewrite is ten
  times what that rewrite took (at most about a tenth of the run spent on them, however
  long the path); until the run ends, ``summary.json`` says ``"completed": false``,
  ``"interrupted": true`` and ``"partial": true``, with how many increments the files hold.

The run's own end (:meth:`Simulation.write`) rewrites every file as a run that was not
streamed writes them; a run that ends any other way keeps these.
"""

from __future__ import annotations

import csv
import json
import os
import time
from pathlib import Path

import numpy as np

from kresling.io import pattern_from_arrays, write_fold
from kresling.io.fold_format import forget_frame_texts
from kresling.io.frame_angles import fold_angle_frames
from kresling.simulate.element_histories import keep_element_states
from kresling.simulate.row_lines import forget_rows, remembered_row
from kresling.solvers import PathResult

__all__ = ["PathStream"]

#: A rewrite of summary.json and path.fold waits this many times its own duration.
_REWRITE_SPACING = 10.0


def _replace_text(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file renamed over it."""
    tmp = path.with_name(path.name + ".part")
    tmp.write_text(text)
    os.replace(tmp, path)


class PathStream:
    """The output files of a run, written increment by increment (module docstring).

    Parameters
    ----------
    directory : str or os.PathLike
        Created if needed.
    simulation : Simulation
        The run before its path: its problem, pattern model, driven DOFs and fold plan
        (its ``path`` has no step; :meth:`append` grows it).
    every : int
        Keep every ``every``-th increment in the row files (as the final files do).
    """

    def __init__(self, directory, simulation, every: int = 1):
        from kresling.simulate.outputs import oriented_triangles, path_fold_edges

        self.directory = Path(directory)
        self.directory.mkdir(parents=True, exist_ok=True)
        forget_rows()   # an earlier run's lines and frames
        forget_frame_texts()
        keep_element_states(simulation.model)   # its rows' states, for its final history
        self.simulation = simulation
        self.every = int(every)
        self.model = simulation.model
        self._families = tuple(self.model.families)
        self._constraint_dofs = np.asarray(simulation.path.constraint_dofs, dtype=np.int64)
        self._rows = {"load_factor": [], "displacement": [], "constraint_force": [],
                      "energies": [], "iterations": [], "negative_eigenvalues": [],
                      "snapped": []}
        self._frame_angles = []   # of the frames written so far
        self._triangles = oriented_triangles(simulation.pattern_model.elements)
        self._edges, self._assignment = path_fold_edges(simulation.pattern_model)
        self._rest_angles = fold_angle_frames(self._triangles, self._edges,
                                              [self.model.nodes])[0]
        self._pattern = None   # the key frame's, at the first rewrite with a frame
        self._history_names = list(simulation.history_columns())
        self._history = self._open_rows("history.csv", self._history_names)
        self._displacements = self._open_rows(
            "displacements.csv",
            [f"{axis}{node}" for node in range(self.model.num_nodes) for axis in "xyz"])
        self._next_rewrite = 0.0
        self.rewrite()

    def _open_rows(self, name: str, header):
        handle = (self.directory / name).open("w", newline="")
        writer = csv.writer(handle)
        writer.writerow(header)
        handle.flush()
        return handle, writer

    def path(self, start: int = 0) -> PathResult:
        """The path so far (its steps from ``start``), not completed."""
        rows = {key: value[start:] for key, value in self._rows.items()}
        count = len(rows["load_factor"])
        n = self.model.num_dofs
        stacked = {
            "load_factor": np.array(rows["load_factor"], dtype=float),
            "displacement": np.array(rows["displacement"], dtype=float).reshape(count, n),
            "constraint_force": np.array(rows["constraint_force"], dtype=float).reshape(
                count, len(self._constraint_dofs)),
            "energies": np.array(rows["energies"], dtype=float).reshape(
                count, len(self._families)),
            "iterations": np.array(rows["iterations"], dtype=np.int64),
            "negative_eigenvalues": np.array(rows["negative_eigenvalues"], dtype=np.int64),
            "snapped": np.array(rows["snapped"], dtype=bool)}
        total = len(self._rows["load_factor"])
        return PathResult(constraint_dofs=self._constraint_dofs, families=self._families,
                          completed=False, message=self.message(total), failed_increment=0,
                          attempted_increments=total,
                          newton_iterations=int(sum(self._rows["iterations"])), **stacked)

    @staticmethod
    def message(count: int) -> str:
        return (f"the run stopped after {count} increments or is still running (these files "
                "are rewritten when it ends): the path so far is kept")

    def append(self, load_factor: float, displacement, step: dict) -> None:
        """An accepted increment: ``step`` as the solvers' stopping rule hands it on
        (``iterations``, ``energies``, ``constraint_force``, ...)."""
        rows = self._rows
        rows["load_factor"].append(float(load_factor))
        rows["displacement"].append(np.array(displacement, dtype=float))
        rows["constraint_force"].append(np.asarray(step["constraint_force"], dtype=float))
        rows["energies"].append(np.asarray(step["energies"], dtype=float))
        rows["iterations"].append(int(step["iterations"]))
        rows["negative_eigenvalues"].append(int(step["negative_eigenvalues"]))
        rows["snapped"].append(bool(step["snapped"]))
        count = len(rows["load_factor"])
        if count % self.every == 0:
            self._write_rows(count - 1)
        if time.perf_counter() >= self._next_rewrite:
            self.rewrite()

    def _write_rows(self, index: int) -> None:
        """The history.csv and displacements.csv rows of increment ``index`` (0-based)."""
        from dataclasses import replace

        one = replace(self.simulation, path=self.path(start=index))
        columns = one.history_columns()
        columns["step"] = np.array([index + 1])
        handle, writer = self._history
        writer.writerow([np.asarray(columns[name]).tolist()[0] if name in columns else ""
                         for name in self._history_names])
        handle.flush()
        handle, _ = self._displacements
        handle.write(remembered_row(self._rows["displacement"][index]))
        handle.flush()

    def rewrite(self) -> None:
        """summary.json and path.fold with every increment so far, each replaced whole."""
        from dataclasses import replace

        from kresling.simulate.outputs import LARGE_OUTPUT

        start = time.perf_counter()
        partial = replace(self.simulation, path=self.path(), interrupted="")
        frames = list(self.model.nodes[None] + partial.path.displacement.reshape(
            partial.path.num_steps, self.model.num_nodes, 3))
        if len(frames) > len(self._frame_angles):   # the new frames' angles, all at once
            self._frame_angles.extend(fold_angle_frames(
                self._triangles, self._edges, frames[len(self._frame_angles):]))
        # path.fold first, then summary.json: a kill between the two leaves a summary that
        # counts no more increments than the frames hold. A path too large to rewrite
        # keeps its rows files and summary only; before its first increment the summary
        # alone is written.
        if frames and len(frames) * self.model.num_dofs * 20 <= LARGE_OUTPUT:
            target = self.directory / "path.fold"
            tmp = target.with_name(target.name + ".part")
            if self._pattern is None:   # built (and checked) once, for every rewrite
                self._pattern = pattern_from_arrays(
                    self.model.nodes, self._triangles, edges=self._edges,
                    edges_assignment=self._assignment, edges_fold_angle=self._rest_angles,
                    panels_required=len(self._edges) == 0)
            write_fold(tmp, self._pattern, frames=frames,
                       frame_fold_angles=list(self._frame_angles),
                       frame_title=f"{Path(self.simulation.problem.source).name}: "
                                   "reference state",
                       metadata={"file_description": "equilibrium path computed by kresling "
                                                     "simulate, so far (the run has not "
                                                     "ended); one frame per converged "
                                                     "increment",
                                 "frame_unit": "mm"})
            os.replace(tmp, target)
        summary = partial.summary()
        # The increments tried and their iterations are known at the run's end only.
        summary.update(completed=False, interrupted=True, partial=True,
                       message=partial.path.message, attempted_increments=None,
                       attempted_newton_iterations=None)
        _replace_text(self.directory / "summary.json", json.dumps(summary, indent=2) + "\n")
        took = time.perf_counter() - start
        self._next_rewrite = time.perf_counter() + _REWRITE_SPACING * took

    def close(self) -> None:
        """Close the row files (the run's own end rewrites them whole)."""
        for handle, _ in (self._history, self._displacements):
            handle.close()
