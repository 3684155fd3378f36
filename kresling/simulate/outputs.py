"""The files a simulation writes: the history, every displacement, the path as FOLD frames
and an interactive view."""

from __future__ import annotations

import csv
import json
import logging
from pathlib import Path

import numpy as np

from kresling.io import write_fold
from kresling.io.frame_angles import fold_angle_frames
from kresling.model.pattern_model import FAMILY_OF_ASSIGNMENT

__all__ = ["write_outputs", "path_fold_edges", "oriented_triangles"]

logger = logging.getLogger(__name__)

#: FOLD assignment of each model hinge family: the fold families' own letters, and "J" (a
#: join within a face) for the bend hinges, inside panels and on joins.
_ASSIGNMENT = {family: letter for letter, family in FAMILY_OF_ASSIGNMENT.items()} | {"bend": "J"}


def _write_csv(path: Path, header, rows):
    tmp = path.with_name(path.name + ".part")
    with tmp.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerows(rows)
    tmp.replace(path)  # never a half-written file under the final name


def oriented_triangles(elements) -> list:
    """The model's triangles, each turned the way of its panel (counter-clockwise in the
    pattern), as FOLD's faces_vertices: ``elements.triangles`` lists them sorted.

    Returns
    -------
    list of tuple of int, length T
    """
    nodes = elements.nodes
    centre_panel = {c: p for p, c in enumerate(elements.panel_centre.tolist()) if c >= 0}
    panels_at = {}
    normals = []
    for p, panel in enumerate(elements.panels):
        for v in panel:
            panels_at.setdefault(v, set()).add(p)
        corners = nodes[list(panel)]
        normals.append(np.cross(corners, np.roll(corners, -1, axis=0)).sum(axis=0))
    out = []
    for a, b, c in elements.triangles.tolist():
        centre = [v for v in (a, b, c) if v in centre_panel]
        panel = (centre_panel[centre[0]] if centre
                 else min(panels_at[a] & panels_at[b] & panels_at[c]))
        turn = np.cross(nodes[b] - nodes[a], nodes[c] - nodes[a])
        out.append((a, b, c) if np.dot(turn, normals[panel]) >= 0 else (a, c, b))
    return out


def path_fold_edges(pattern_model):
    """Edges of the model's triangles with their FOLD assignments.

    Fold hinges keep their family's letter (M, V, F, U), a cut keeps "C", bend hinges
    (edges inside panels, and joins) are "J" (FOLD 1.2: a join within one face, which
    reading the file back turns into bend hinges again), edges of one triangle "B"; a bar
    without a hinge between two triangles (Origami Simulator's undriven crease) "U".

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
    - ``path.fold``: the model's triangles (``faces_vertices``) with the reference state as
      key frame and one frame per increment, ``edges_assignment`` in FOLD's letters and
      ``edges_foldAngle`` [degrees, valley positive] in every frame, in mm;
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
    triangles = oriented_triangles(simulation.pattern_model.elements)
    angles = fold_angle_frames(triangles, edges, [model.nodes] + frames)
    written["fold"] = directory / "path.fold"
    write_fold(written["fold"], model.nodes, triangles, edges=edges, edges_assignment=assignment,
               edges_fold_angle=angles[0], frames=frames, frame_fold_angles=list(angles[1:]),
               frame_title=f"{Path(simulation.problem.source).name}: reference state",
               metadata={"file_description": "equilibrium path computed by kresling simulate; "
                                             "one frame per converged increment",
                         "frame_unit": "mm"})

    written["summary"] = directory / "summary.json"
    written["summary"].write_text(json.dumps(simulation.summary(), indent=2) + "\n")

    if view:
        try:
            from kresling.view import view_path, write_html
        except ImportError as error:  # plotly missing: the other files still stand
            logger.warning("view.html not written: %s", error)
        else:
            figure = view_path(simulation.pattern_model, path,
                               title=Path(simulation.problem.source).name)
            written["view"] = write_html(figure, directory / "view.html")
    return written
