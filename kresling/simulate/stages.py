"""A problem in stages: ``[[stage]]`` tables, each with its own method, loads and actuation,
each starting where the one before ended (docs/simulate.md, '[[stage]]').

A stage table holds what ``[analysis]`` holds for a problem of one stage (``method`` and its
settings), its ``load``, ``actuation`` and ``dynamics`` (as ``[[load]]``, ``[[actuation]]``
and ``[dynamics]`` would be), and an optional ``name``; the problem's other tables
(``[pattern]``, ``[material]``, ``[[support]]``, ``[[mass]]``, ``[contact]``, ...) hold for
every stage. Each stage is read and checked as a problem of its own, so its refusals name it.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kresling.simulate.outputs import write_csv
from kresling.simulate.start_state import StartState

__all__ = ["StagedProblem", "StagedRun", "read_stages", "STAGE_KEYS"]

#: The keys of a stage table that are top-level tables in a problem of one stage.
STAGE_KEYS = ("load", "actuation", "dynamics")
#: Top-level keys a problem in stages gives per stage instead.
_PER_STAGE = ("analysis",) + STAGE_KEYS


@dataclass(frozen=True)
class StagedProblem:
    """A problem in stages: ``stages`` is a tuple of (name, Problem), in order."""

    stages: tuple
    source: str


def read_stages(data: dict, source: str, base: Path, load_problem) -> StagedProblem:
    """The ``[[stage]]`` tables of a problem's ``data``, each read as a problem of its own
    (``load_problem``, with the problem's shared tables)."""
    entries = data["stage"]
    if not isinstance(entries, list) or not entries or not all(isinstance(e, dict)
                                                              for e in entries):
        raise ValueError(f"{source}: [[stage]] must be an array of tables, each a stage "
                         "(method, its settings, load, actuation, dynamics, name)")
    given = [key for key in _PER_STAGE if key in data]
    if given:
        raise ValueError(f"{source}: [{given[0]}] is given per stage in a problem with "
                         "[[stage]]: move it into the stages it belongs to")
    shared = {key: value for key, value in data.items() if key != "stage"}
    names, stages = set(), []
    for i, entry in enumerate(entries):
        name = entry.get("name", f"stage {i + 1}")
        if not isinstance(name, str) or not re.fullmatch(r"[\w .-]{1,60}", name):
            raise ValueError(f"{source}: stage[{i}] key 'name' = {name!r} is invalid: must be "
                             "1 to 60 letters, digits, spaces, '.', '-' or '_'")
        if name in names:
            raise ValueError(f"{source}: stage[{i}] key 'name' = {name!r} names two stages")
        names.add(name)
        problem = {**shared, "analysis": {k: v for k, v in entry.items()
                                          if k != "name" and k not in STAGE_KEYS}}
        problem.update({k: v for k, v in entry.items() if k in STAGE_KEYS})
        where = f"{source}: stage '{name}'"
        # Read as a problem of its own: relative paths from the problem's folder.
        if isinstance(shared.get("pattern"), dict) and "file" in shared["pattern"]:
            file = Path(shared["pattern"]["file"])
            problem["pattern"] = {**shared["pattern"],
                                  "file": str(file if file.is_absolute() else base / file)}
        checked = load_problem(problem, source=where)
        if checked.held and "support" not in shared:
            # The free sheet's hold, chosen by the first stage that needs one, holds every
            # stage: the same nodes throughout.
            shared["support"] = [{"node": s.node, "fix": s.axes} for s in checked.held]
        stages.append((name, checked))
    return StagedProblem(tuple(stages), source)


def end_state(run, start: StartState | None) -> StartState:
    """Where a stage's run ended: the next stage's start."""
    carried = np.zeros(run.model.num_dofs) if start is None else start.forces
    if not hasattr(run, "path"):   # modes: the state they were about, unchanged
        return start if start is not None else StartState(
            np.asarray(run.model.hinge_rest_angle, dtype=float), np.zeros(run.model.num_dofs),
            None, carried)
    path = run.path
    model = run.model_at(-1)
    forces = carried + _applied(run)
    velocity = (np.asarray(run.history.velocity[-1]) if hasattr(run, "history") else None)
    return StartState(np.asarray(model.hinge_rest_angle, dtype=float),
                      np.asarray(path.displacement[-1], dtype=float), velocity, forces)


def _applied(run) -> np.ndarray:
    """The loads a stage leaves applied [N]: its forces at the end (force control and MGDCM
    at the final load factor, a fold's in full, a motion's at its final time), or a
    displacement drive's reactions (the drive holds its force)."""
    problem, path = run.problem, run.path
    n = run.model.num_dofs
    applied = np.zeros(n)
    if problem.method.drives_displacements:
        applied[np.asarray(path.constraint_dofs)] = -np.asarray(path.constraint_force[-1])
        return applied
    end = float(path.load_factor[-1])   # a motion's: its final time [s]
    for load in problem.loads:
        if problem.method.in_time:
            scale = 1.0 if load.time is None else load.time.factor_at(end)
        else:   # a fold's forces are in full after its first stage
            scale = 1.0 if problem.method.drives_creases else end
        for node in load.nodes:
            applied[3 * node:3 * node + 3] += scale * np.asarray(load.vector)
    gravity = getattr(problem, "dynamics", None) and problem.dynamics.gravity
    if problem.method.in_time and gravity is not None:   # the weight, as a held load
        applied += np.repeat(np.asarray(run.masses, dtype=float), 3) * np.tile(gravity,
                                                                                len(run.masses))
    return applied


class StagedRun:
    """The runs of a problem's stages, in order, and what they record together.

    Attributes
    ----------
    problem : StagedProblem
    runs : list of (name, run)
        Each stage's run: a :class:`~kresling.simulate.Simulation`, ``ModesRun`` or
        ``DynamicRun``. A stage that did not complete ends the list.
    """

    def __init__(self, problem: StagedProblem, runs: list):
        self.problem, self.runs = problem, runs

    @property
    def completed(self) -> bool:
        return (len(self.runs) == len(self.problem.stages)
                and all(run.completed for _, run in self.runs))

    @property
    def interrupted(self) -> str:
        return next((getattr(run, "interrupted", "") for _, run in self.runs
                     if getattr(run, "interrupted", "")), "")

    @property
    def path(self):
        """The last path stage's path (the one that stopped, if one did); None when every
        stage is a modes stage."""
        return next((run.path for _, run in reversed(self.runs) if hasattr(run, "path")), None)

    @property
    def message(self) -> str:
        """Which stage stopped and why ("" when every stage completed)."""
        for name, run in self.runs:
            if not run.completed:
                return f"stage '{name}' stopped: {run.message}"
        return ""

    def history_columns(self) -> dict:
        """Every path stage's history.csv columns, one row per increment, with ``stage``
        (the stage's name) first; a column a stage does not have is empty in its rows (a
        fold's own stage number is ``fold_stage``)."""
        parts = []
        for name, run in self.runs:
            if hasattr(run, "path"):
                columns = dict(run.history_columns())
                if "stage" in columns:
                    columns["fold_stage"] = columns.pop("stage")
                parts.append((name, columns, run.path.num_steps))
        names = ["stage"] + list(dict.fromkeys(k for _, c, _ in parts for k in c))
        out = {key: [] for key in names}
        for name, columns, rows in parts:
            out["stage"] += [name] * rows
            for key in names[1:]:
                values = columns.get(key)
                out[key] += ([""] * rows if values is None else np.asarray(values).tolist())
        return out

    def summary(self) -> dict:
        return {"source": self.problem.source, "method": "stages",
                "stages": [{"name": name, **run.summary()} for name, run in self.runs],
                "completed": self.completed, "interrupted": bool(self.interrupted),
                "message": self.message}

    def write(self, directory, *, view=True, every=None) -> dict:
        """Each stage's files in ``directory/<k>_<name>/`` (k from 1), the stages' history
        in ``directory/history.csv`` and their summary in ``directory/summary.json``."""
        directory = Path(directory)
        directory.mkdir(parents=True, exist_ok=True)
        written = {}
        for k, (name, run) in enumerate(self.runs, 1):
            folder = directory / f"{k}_{name.replace(' ', '_')}"
            for key, path in run.write(folder, view=view, every=every).items():
                written[f"{name}: {key}"] = path
        columns = self.history_columns()
        written["history"] = directory / "history.csv"
        write_csv(written["history"], list(columns), zip(*columns.values()))
        written["summary"] = directory / "summary.json"
        written["summary"].write_text(json.dumps(self.summary(), indent=2) + "\n")
        return written
