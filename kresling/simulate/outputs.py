"""The files a simulation writes: the history, every displacement, the path as FOLD frames
and an interactive view."""

from __future__ import annotations

import csv
import json
import logging
from pathlib import Path

import numpy as np

from kresling.io import write_fold
from kresling.model.pattern_model import FAMILY_OF_ASSIGNMENT

__all__ = ["write_outputs", "path_fold_edges"]

logger = logging.getLogger(__name__)

#: FOLD assignment of each model hinge family: the fold families' own letters, and "J" (a
#: join within a face) for the bend hinges inside panels.
_ASSIGNMENT = {family: letter for letter, family in FAMILY_OF_ASSIGNMENT.items()} | {"bend": "J"}


def _write_csv(path: Path, header, rows):
    tmp = path.with_name(path.name + ".part")
    with tmp.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerows(rows)
    tmp.replace(path)  # never a half-written file under the final name


def path_fold_edges(pattern_model):
    """Edges of the model's triangles with their FOLD assignments.

    Fold hinges keep their family's letter (M, V, F, U, J), a cut keeps "C", edges inside
    panels (bend hinges) are "J" (FOLD 1.2: a join within a face), edges of one triangle
    "B".

    Returns
    -------
    edges : ndarray of int, shape (E, 2)
    assignment : list of str, length E
    """
    letters = {}
    elements = pattern_model.elements
    for (a, b), family in zip(pattern_model.model.bars.tolist(), pattern_model.bar_family):
        key = (min(a, b), max(a, b))
        letters.setdefault(key, {"cut": "C", "boundary": "B", "bend": "J"}.get(family, "U"))
    for hinge, family in zip(pattern_model.model.hinges.tolist(), pattern_model.hinge_family):
        letters[(min(hinge[:2]), max(hinge[:2]))] = _ASSIGNMENT[family]
    edges = sorted({(min(t[i], t[(i + 1) % 3]), max(t[i], t[(i + 1) % 3]))
                    for t in elements.triangles.tolist() for i in range(3)})
    return np.array(edges, dtype=np.int64).reshape(-1, 2), [letters.get(e, "U") for e in edges]


def write_outputs(simulation, directory, *, view=True) -> dict:
    """Write a simulation's files into ``directory`` (created if needed).

    - ``history.csv``: one row per converged increment (see
      :meth:`Simulation.history_columns`);
    - ``displacements.csv``: one row per increment, the 3N displacements ``x0, y0, z0, x1,
      ...`` [mm] of every node (pattern vertices, then N5B8 centre nodes);
    - ``path.fold``: the model's triangles with the reference state as key frame and one
      frame per increment;
    - ``summary.json``: sizes, outcome and message;
    - ``view.html``: an interactive view of the path (when ``view`` and plotly is installed).

    Returns
    -------
    dict
        Paths written, by name.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    written = {}
    columns = simulation.history_columns()
    names = list(columns)
    rows = zip(*(np.asarray(columns[n]).tolist() for n in names))
    written["history"] = directory / "history.csv"
    _write_csv(written["history"], names, rows)

    path = simulation.path
    model = simulation.model
    header = [f"{axis}{node}" for node in range(model.num_nodes) for axis in "xyz"]
    written["displacements"] = directory / "displacements.csv"
    _write_csv(written["displacements"], header,
               (np.asarray(u).tolist() for u in path.displacement))

    edges, assignment = path_fold_edges(simulation.pattern_model)
    frames = [model.nodes + u.reshape(-1, 3) for u in path.displacement]
    written["fold"] = directory / "path.fold"
    write_fold(written["fold"], model.nodes, [tuple(t) for t in
                                              simulation.pattern_model.elements.triangles],
               edges=edges, edges_assignment=assignment, frames=frames,
               frame_title=f"{Path(simulation.problem.source).name}: reference state",
               metadata={"file_description": "equilibrium path computed by kresling simulate; "
                                             "one frame per converged increment"})

    written["summary"] = directory / "summary.json"
    written["summary"].write_text(json.dumps(simulation.summary(), indent=2) + "\n")

    if view and not path.num_steps:  # no increment converged: no path to show
        logger.warning("view.html not written: the path has no converged increment")
    elif view:
        try:
            from kresling.view import view_path, write_html
        except ImportError as error:  # plotly missing: the other files still stand
            logger.warning("view.html not written: %s", error)
        else:
            figure = view_path(simulation.pattern_model, path,
                               title=Path(simulation.problem.source).name)
            written["view"] = write_html(figure, directory / "view.html")
    return written
