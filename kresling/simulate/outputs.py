"""The files a simulation writes: the history, every displacement, the path as FOLD frames
and an interactive view."""

from __future__ import annotations

import csv
import json
import logging
from pathlib import Path

import numpy as np

from kresling._validation import as_integer
from kresling.io import write_fold
from kresling.io.frame_angles import newell_normals
from kresling.io.frame_angles import fold_angle_frames
from kresling.model.pattern_model import FAMILY_OF_ASSIGNMENT, MEMBER
from kresling.simulate.problem_keys import problem_keys
from kresling.simulate.row_lines import float_row, row_lines

__all__ = ["write_outputs", "path_fold_edges", "oriented_triangles", "kept_rows", "view_title",
           "write_csv", "write_float_csv", "float_row", "LARGE_OUTPUT"]

logger = logging.getLogger(__name__)

#: FOLD assignment of each model hinge family: the fold families' own letters, and "J" (a
#: join within a face) for the bend hinges, inside panels and on joins.
_ASSIGNMENT = {family: letter for letter, family in FAMILY_OF_ASSIGNMENT.items()} | {
    "bend": "J", MEMBER: "U"}


def write_csv(path: Path, header, rows):
    """A CSV file of ``header`` and ``rows``, written whole under a temporary name first."""
    tmp = path.with_name(path.name + ".part")
    with tmp.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerows(rows)
    tmp.replace(path)  # never a half-written file under the final name


def write_float_csv(path: Path, header, array):
    """:func:`write_csv` of a header and rows of floats (``array``, shape (R, C)), each row
    as :func:`float_row` writes it (taken ready from :mod:`kresling.simulate.row_lines`
    where the run's stream formatted it already)."""
    tmp = path.with_name(path.name + ".part")
    with tmp.open("w", newline="") as handle:
        csv.writer(handle).writerow(header)
        handle.writelines(row_lines(array))
    tmp.replace(path)  # never a half-written file under the final name


def oriented_triangles(elements) -> list:
    """The model's triangles, each turned the way of its panel (counter-clockwise in the
    pattern), as FOLD's faces_vertices: ``elements.triangles`` lists them sorted.

    Returns
    -------
    list of tuple of int, length T
    """
    nodes = np.asarray(elements.nodes, dtype=float)
    normals = newell_normals(nodes[None], elements.panels)[0]
    centre_panel = {c: p for p, c in enumerate(elements.panel_centre.tolist()) if c >= 0}
    panels_at = {}
    for p, panel in enumerate(elements.panels):
        for v in panel:
            panels_at.setdefault(v, set()).add(p)
    triangles = np.asarray(elements.triangles, dtype=np.int64).reshape(-1, 3)
    panel_of = []
    for a, b, c in triangles.tolist():
        centre = [v for v in (a, b, c) if v in centre_panel]
        panel_of.append(centre_panel[centre[0]] if centre
                        else min(panels_at[a] & panels_at[b] & panels_at[c]))
    a, b, c = nodes[triangles[:, 0]], nodes[triangles[:, 1]], nodes[triangles[:, 2]]
    turn = np.cross(b - a, c - a)
    agrees = np.einsum("ij,ij->i", turn, normals[np.array(panel_of, dtype=np.int64)]) >= 0
    return [tuple(t) for t in np.where(agrees[:, None], triangles,
                                       triangles[:, [0, 2, 1]]).tolist()]


def path_fold_edges(pattern_model):
    """Edges of the model's triangles (and its member bars) with their FOLD assignments.

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
    edges = {(min(t[i], t[(i + 1) % 3]), max(t[i], t[(i + 1) % 3]))
             for t in elements.triangles.tolist() for i in range(3)}
    # Member bars (a linkage's, a brace) are edges of no face.
    edges = sorted(edges | {(min(a, b), max(a, b)) for (a, b), family in zip(
        pattern_model.model.bars.tolist(), pattern_model.bar_family) if family == MEMBER})
    return np.array(edges, dtype=np.int64).reshape(-1, 2), [letters.get(e, "U") for e in edges]


#: Outputs larger than this are announced (with their size and how to thin them) before
#: they are written [bytes].
LARGE_OUTPUT = 100e6

#: Characters per value of displacements.csv and path.fold, as estimated for the warning
#: (a double's shortest repr, 17-19 characters, and its separator).
_CHARACTERS_PER_VALUE = 20


def kept_rows(num_steps: int, every: int) -> np.ndarray:
    """The increments (0-based rows) the files keep: every ``every``-th, the last always."""
    if num_steps == 0:
        return np.zeros(0, dtype=np.int64)
    rows = np.arange(every - 1, num_steps, every)
    return rows if len(rows) and rows[-1] == num_steps - 1 else np.append(rows, num_steps - 1)


def _warn_if_large(simulation, rows, every):
    values = 2 * len(rows) * 3 * simulation.model.num_nodes   # displacements.csv, path.fold
    size = values * _CHARACTERS_PER_VALUE
    if size > LARGE_OUTPUT:
        logger.warning("%s: writing about %.3g MB of outputs (%d increments of %d nodes); "
                       "[output] every = k in the problem file, or --every k, keeps every "
                       "k-th increment (now %d)", simulation.problem.source, size / 1e6,
                       len(rows), simulation.model.num_nodes, every)


def write_outputs(simulation, directory, *, view=True, every=None) -> dict:
    """Write a simulation's files into ``directory`` (created if needed).

    - ``history.csv``: one row per kept increment (see
      :meth:`Simulation.history_columns`);
    - ``displacements.csv``: one row per kept increment, the 3N displacements ``x0, y0, z0,
      x1, ...`` [mm] of every node (pattern vertices, then N5B8 centre nodes);
    - ``path.fold``: the model's triangles (``faces_vertices``) with the reference state as
      key frame and one frame per kept increment, ``edges_assignment`` in FOLD's letters and
      ``edges_foldAngle`` [degrees, valley positive] in every frame, in mm;
    - ``summary.json``: sizes, outcome and message (of the whole run);
    - ``folded.stl``, ``folded.obj``: the last increment's triangles [mm], as the
      problem's ``[output] formats`` ask;
    - ``view.html``: an interactive view of the path, the curve of
      :func:`kresling.simulate.curve.path_curve` (when ``view`` and plotly is installed).

    Parameters
    ----------
    simulation : Simulation
    directory : str or os.PathLike
    view : bool, default True
    every : int, optional
        Keep every ``every``-th increment in the files (the last always); default: the
        problem's ``[output] every`` (1: every increment).

    Returns
    -------
    dict
        Paths written, by name.
    """
    every = simulation.problem.output.every if every is None else \
        as_integer("every", every, minimum=1)
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    path = simulation.path
    rows = kept_rows(path.num_steps, every)
    _warn_if_large(simulation, rows, every)
    written = {}
    columns = simulation.history_columns()
    names = list(columns)
    kept = {n: np.asarray(columns[n])[rows] for n in names}
    written["history"] = directory / "history.csv"
    write_csv(written["history"], names, zip(*(kept[n].tolist() for n in names)))

    model = simulation.model
    displacement = np.asarray(path.displacement)[rows]
    header = [f"{axis}{node}" for node in range(model.num_nodes) for axis in "xyz"]
    written["displacements"] = directory / "displacements.csv"
    write_float_csv(written["displacements"], header, displacement)

    edges, assignment = path_fold_edges(simulation.pattern_model)
    frames = list(model.nodes[None] + displacement.reshape(len(rows), model.num_nodes, 3))
    triangles = oriented_triangles(simulation.pattern_model.elements)
    angles = fold_angle_frames(triangles, edges, [model.nodes] + frames)
    written["fold"] = directory / "path.fold"
    write_fold(written["fold"], model.nodes, triangles, edges=edges, edges_assignment=assignment,
               edges_fold_angle=angles[0], frames=frames, frame_fold_angles=list(angles[1:]),
               frame_title=_frame_titles(simulation, rows),
               metadata={"file_description": "equilibrium path computed by kresling simulate; "
                                             "one frame per converged increment",
                         "frame_unit": "mm"})

    written["summary"] = directory / "summary.json"
    written["summary"].write_text(json.dumps(simulation.summary(), indent=2) + "\n")
    if path.num_steps:
        written.update(_write_end_state(simulation, directory, triangles, frames[-1]))
    for key in problem_keys():  # the files of keys such as [sensitivity]
        if key.outputs is not None:
            written.update(key.outputs(simulation, directory, rows))

    if view and not path.num_steps:  # no increment converged: no path to show
        logger.warning("view.html not written: the path has no converged increment")
    elif view:
        written.update(_write_view(simulation, directory, rows, columns))
    return written


def _write_end_state(simulation, directory, triangles, positions) -> dict:
    """The end state's triangles as the ``[output] formats`` ask: folded.stl, folded.obj
    (for a slicer, a CAD tool or a renderer) [mm]."""
    from kresling.io import write_obj, write_stl

    written = {}
    for name in simulation.problem.output.formats:
        target = directory / f"folded.{name}"
        if name == "stl":
            write_stl(target, positions, triangles, name="folded")
        else:
            write_obj(target, positions, triangles)
        written[name] = target
    return written


def _frame_titles(simulation, rows):
    """The reference state's title, and (a motion in time) each kept frame's time."""
    first = f"{Path(simulation.problem.source).name}: reference state"
    playback = getattr(simulation, "playback", None)
    if playback is None:
        return first
    times = playback()[0][rows]
    return [first] + [f"t = {t:.6g} s" for t in times]


class _Kept:
    """A path's kept rows, as the view reads a path."""

    def __init__(self, path, rows):
        self.displacement = np.asarray(path.displacement)[rows]
        self.load_factor = np.asarray(path.load_factor)[rows]
        self.completed, self.message = path.completed, path.message


def _write_view(simulation, directory, rows, columns) -> dict:
    from kresling.simulate.curve import path_curve
    from kresling.view import write_path_page

    curve = None
    if len(rows):   # (a path without increments: the page says there is nothing to show)
        x, y, x_label, y_label = path_curve(simulation, columns)
        curve = (np.asarray(x)[rows], np.asarray(y)[rows], x_label, y_label)
    timing = {}
    if getattr(simulation, "playback", None) is not None:   # a motion: played in time
        times, scale = simulation.playback()
        timing = {"times": times[rows], "time_scale": scale}
    try:
        page = write_path_page(simulation.pattern_model, _Kept(simulation.path, rows),
                               directory / "view.html", curve=curve, increments=rows + 1,
                               total=simulation.path.num_steps, title=view_title(simulation),
                               **timing,
                               contact_pairs=_contact_pairs(simulation, rows))
    except ImportError as error:  # plotly missing: the other files still stand
        logger.warning("view.html not written: %s", error)
        return {}
    return {"view": page}


def _contact_pairs(simulation, rows):
    """The panel-panel pairs within d_hat at each kept row (segments between their closest
    points, (K, 6) [mm] each), or None without self contact."""
    if "self_contact" not in simulation.path.families:
        return None
    model = simulation.model
    return [model.element_state(u)["self_contact_segments"].reshape(-1, 6)
            for u in np.asarray(simulation.path.displacement)[rows]]


def view_title(simulation) -> str:
    """The view's title: the problem, the method and how far the path went."""
    source = Path(simulation.problem.source)
    where = f"{source.parent.name}/{source.name}" if source.parent.name else source.name
    model = simulation.model
    method = simulation.problem.analysis.method.replace("_", " ")
    sizes = f"{model.num_nodes} nodes, {len(model.bars)} bars, {len(model.hinges)} hinges"
    if getattr(simulation, "playback", None) is not None:
        scale = simulation.playback()[1]
        duration = simulation.problem.dynamics.duration
        return (f"kresling simulate {where}: {method} ({simulation.problem.dynamics.scheme}), "
                f"{simulation.path.num_steps} steps<br>{sizes}; played in real time scaled "
                f"by {scale:.3g} (its {duration:g} s in {duration * scale:.3g} s)")
    return (f"kresling simulate {where}: {method}, {simulation.path.num_steps} increments"
            f"<br>{sizes}")
