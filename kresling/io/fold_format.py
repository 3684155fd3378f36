"""The FOLD format (JSON) of a crease pattern and its folded states: read and write.

FOLD (Demaine, Ku, Lang; specification 1.1 and 1.2) stores the pattern in the *key frame*:
``vertices_coords`` (2D or 3D), ``edges_vertices``, ``edges_assignment``,
``edges_foldAngle`` and ``faces_vertices`` (0-based indices); further configurations of the
same vertices go in ``file_frames``. Lengths are in the file's ``frame_unit``: the reader
(:mod:`kresling.io.fold_reading`) converts them to mm, this writer writes mm. Fold angles are in degrees in [-180, 180]: positive for a valley,
negative for a mountain, 0 flat; with faces counter-clockwise about +z in the flat pattern,
a valley folds the faces' +z sides towards each other.

Assignments ``C`` (cut) and ``J`` (join) are FOLD 1.2; a file holding them is written as
``file_spec`` 1.2, any other as 1.1.
"""

from __future__ import annotations

import json
import logging
from itertools import chain
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from kresling.io.fold_reading import pattern_from_fold, read_fold
from kresling.io.pattern import (ASSIGNMENTS, Pattern, checked_coordinates, argument_fail,
                                 pattern_from_arrays)
from kresling.io.units import mm_per_unit
from kresling.io.vertex_neighbours import vertices_neighbours

__all__ = ["ASSIGNMENTS", "fold_angles", "fold_document", "pattern_from_fold", "read_fold",
           "write_fold", "write_fold_document", "forget_frame_texts"]

logger = logging.getLogger(__name__)

#: Keys :func:`write_fold` computes from the pattern, which ``metadata`` cannot set.
GEOMETRY_KEYS = ("vertices_coords", "faces_vertices", "edges_vertices", "edges_assignment",
                 "edges_foldAngle", "file_frames", "vertices_vertices", "vertices_edges")


# -- writing -------------------------------------------------------------------------------

def write_fold(path, pattern_or_vertices, faces=None, *, edges=None, edges_assignment=None,
               edges_fold_angle=None, frames=None, frame_title=None, frame_fold_angles=None,
               metadata=None) -> Path:
    """Write a pattern, and optionally further configurations of it, as a FOLD file.

    Parameters
    ----------
    path : str or Path
    pattern_or_vertices : Pattern or array_like, shape (N, 3) or (N, 2)
        A :class:`~kresling.io.Pattern` (faces, edges, assignments, fold angles and frames
        come from it), or the key frame's coordinates [mm].
    faces : sequence of sequence of int, optional
        With coordinates: the panels (0-based; required). Not with a Pattern.
    edges : array_like of int, shape (E, 2), optional
        With coordinates: edges in this order; the faces' missing sides are appended.
    edges_assignment : sequence of str, optional
        One letter of :data:`ASSIGNMENTS` per edge (replaces a Pattern's); default ``"B"``
        on one face, else ``"U"``.
    edges_fold_angle : array_like, shape (E,), optional
        Fold angles [degrees], valley positive, NaN where unknown (replaces a Pattern's).
    frames : sequence of array_like, each of shape (N, 3), optional
        Further configurations [mm] of the vertices (say the deformed states along a path,
        one per increment), written as ``file_frames`` with ``frame_parent: 0``,
        ``frame_inherit: true`` and ``frame_classes: ["foldedForm"]``. Default: a Pattern's
        ``frames``, none for arrays.
    frame_title : str or sequence of str, optional
        The key frame's title, or one title per frame, key frame first (default ``""`` and
        ``"frame 1"``, ``"frame 2"``, ...).
    frame_fold_angles : sequence of array_like, each of shape (E,), optional
        Fold angles [degrees, valley positive, NaN unknown] of each frame, written as the
        frame's ``edges_foldAngle``.
    metadata : dict, optional
        More top-level properties, written last: ``frame_unit`` (default ``"mm"``; one of
        :data:`~kresling.io.units.UNITS`: the coordinates, given in mm, are written in
        it), ``file_title``, ``file_author``, ``frame_classes``, custom ``"prefix:name"``
        keys. Not the geometry keys (:data:`GEOMETRY_KEYS`).

    Returns
    -------
    Path

    Notes
    -----
    ``file_spec`` is 1.2 if an edge is ``"C"`` or ``"J"``, else 1.1. With a ``"C"`` edge,
    ``vertices_vertices`` and ``vertices_edges`` (counter-clockwise round each vertex,
    :func:`~kresling.io.vertex_neighbours.vertices_neighbours`) are written too: readers
    that separate faces along cuts need them. The key frame is written
    2D (``frame_classes: ["creasePattern"]``) when every z is 0, else 3D (``"foldedForm"``).
    FOLD has no "unknown" fold angle: unknown angles of ``"B"`` and ``"F"`` edges are
    written 0, others ``null`` (read back as NaN); ``edges_foldAngle`` is left out if no
    angle is known.

    Raises
    ------
    ValueError
        If the arrays are inconsistent (as :func:`~kresling.io.pattern_from_arrays`, which
        checks arrays), a frame has the wrong shape, or ``metadata`` sets a geometry key or
        is not JSON.
    """
    if isinstance(pattern_or_vertices, Pattern):
        pattern = pattern_or_vertices
        if faces is not None or edges is not None:
            raise ValueError("faces and edges are invalid with a Pattern, which has its own: "
                             "pass vertices and faces to write arrays")
        if edges_assignment is not None or edges_fold_angle is not None:
            pattern = Pattern(
                pattern.vertices, pattern.faces, pattern.edges,
                pattern.edges_assignment if edges_assignment is None else edges_assignment,
                pattern.edges_fold_angle if edges_fold_angle is None else edges_fold_angle,
                pattern.frames, pattern.source)
    else:
        if faces is None:
            raise ValueError("faces is missing: write_fold needs a Pattern, or vertices and "
                             "faces")
        # No faces but edges: a structure of bars alone (FOLD allows it).
        pattern = pattern_from_arrays(pattern_or_vertices, faces, edges=edges,
                                      edges_assignment=edges_assignment,
                                      edges_fold_angle=edges_fold_angle,
                                      panels_required=edges is None or len(edges) == 0)
    if frames is None:
        frames = pattern.frames
    else:
        fail = argument_fail("frames")
        if isinstance(frames, (str, bytes)) or not hasattr(frames, "__len__"):
            raise fail(None, "must be a sequence of (N, 3) arrays", value=frames)
        frames = [checked_coordinates(frame, f"frames[{k}]", count=pattern.num_vertices)
                  for k, frame in enumerate(frames)]
    titles = _titles(frame_title, len(frames))
    metadata = _metadata(metadata)
    per_mm = 1.0 / mm_per_unit(metadata.get("frame_unit", "mm"), name="metadata frame_unit")
    frame_angles = _frame_angles(frame_fold_angles, len(frames))
    flat = not np.any(pattern.vertices[:, 2])
    angles = np.array(pattern.edges_fold_angle)
    unknown = np.isnan(angles)
    if unknown.all():
        angles = None
    else:
        angles[unknown & np.isin(pattern.edges_assignment, ("B", "F"))] = 0.0
    given = [{"title": title, "vertices_coords": np.asarray(frame) * per_mm}
             | ({} if frame_angles is None else {"edges_foldAngle": frame_angles[k]})
             for k, (title, frame) in enumerate(zip(titles[1:], frames))]
    document = fold_document(
        (pattern.vertices[:, :2] if flat else pattern.vertices) * per_mm, pattern.edges,
        pattern.edges_assignment, pattern.faces, edges_fold_angle=angles, frames=given,
        title=titles[0], extra={"frame_classes": ["creasePattern" if flat else "foldedForm"]})
    if given:   # each frame's text formatted once over the rewrites of a growing path
        document["file_frames"] = [_keyed_frame(written, frame) for written, frame
                                   in zip(document["file_frames"], given)]
    if "C" in pattern.edges_assignment:
        # Readers that separate the faces along cuts walk round each vertex in this order.
        document["vertices_vertices"], document["vertices_edges"] = vertices_neighbours(
            pattern.faces, pattern.edges, pattern.num_vertices)
    document.update(metadata)
    return write_fold_document(path, document)


def _frame_angles(values, count: int):
    if values is None:
        return None
    if isinstance(values, (str, bytes)) or not hasattr(values, "__len__") or \
            len(values) != count:
        raise ValueError(f"frame_fold_angles is invalid: must be one array of fold angles "
                         f"[degrees] per frame ({count})")
    return list(values)


def _titles(frame_title, count: int) -> list:
    if frame_title is None or isinstance(frame_title, str):
        return [frame_title or ""] + [f"frame {k}" for k in range(1, count + 1)]
    titles = list(frame_title) if hasattr(frame_title, "__iter__") else None
    if titles is None or len(titles) != count + 1 or not all(isinstance(t, str) for t in titles):
        raise ValueError(f"frame_title = {frame_title!r} is invalid: must be a str (the key "
                         f"frame's title) or {count + 1} str, one per frame, key frame first")
    return titles


def _metadata(metadata) -> dict:
    if metadata is None:
        return {}
    if not isinstance(metadata, Mapping):
        raise ValueError(f"metadata = {metadata!r} is invalid: must be a dict of top-level "
                         "FOLD properties")
    for key in metadata:
        if not isinstance(key, str):
            raise ValueError(f"metadata key {key!r} is invalid: FOLD keys are str")
        if key in GEOMETRY_KEYS:
            raise ValueError(f"metadata key {key!r} is invalid: write_fold computes it from "
                             f"the pattern (geometry keys: {', '.join(GEOMETRY_KEYS)})")
    try:
        json.dumps(dict(metadata), allow_nan=False)
    except (TypeError, ValueError) as error:
        raise ValueError(f"metadata is invalid: not JSON ({error})") from None
    return dict(metadata)


def write_fold_document(path, document: dict) -> Path:
    """Write a FOLD document (a ``dict``, see :func:`fold_document`) as JSON; returns the path.

    Raises
    ------
    ValueError
        If the document holds something JSON cannot (NaN, inf, an object).
    """
    path = Path(path)
    path.write_text(_dumps(document) + "\n", encoding="utf-8")
    logger.info("wrote %s (%d vertices, %d edges)", path, len(document["vertices_coords"]),
                len(document.get("edges_vertices", ())))
    return path


#: Values ``_dumps`` writes as ``json.dumps`` does, without looking inside.
_SCALARS = (str, float, int, bool, type(None))
_SCALAR_KINDS = set(_SCALARS)


def _dumps(value, indent: str = "") -> str:
    """JSON with one line per vertex, edge and face: lists of scalars are not broken up."""
    if type(value) in _SCALARS:   # the most frequent, and no container (checked fast)
        return json.dumps(value, allow_nan=False)
    inner = indent + " "
    if type(value) is _Frame and value.key is not None:   # a path's frame: written once
        key = (indent, value.key)
        text = _frame_texts.get(key)
        if text is None:
            text = _dumps(dict(value), indent)
            if _frame_text_size[0] + len(text) <= _FRAME_TEXT_LIMIT:
                _frame_texts[key] = text
                _frame_text_size[0] += len(text)
        return text
    if isinstance(value, Mapping) and value:
        items = [f"{inner}{json.dumps(str(k))}: {_dumps(v, inner)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + indent + "}"
    if isinstance(value, (list, tuple)) and value:
        # The common cases first, each in one call of json's encoder (a path's frames hold
        # thousands): a flat list of scalars (fold angles) on one line, rows of numbers
        # (coordinates) one per line.
        kinds = set(map(type, value))
        if kinds <= _SCALAR_KINDS:
            return json.dumps(value, allow_nan=False)
        rows = _number_rows(value, inner) if kinds <= {list, tuple} else None
        if rows is not None:
            return "[\n" + rows + "\n" + indent + "]"
        if any(type(v) not in _SCALARS and isinstance(v, (Mapping, list, tuple))
               for v in value):
            return ("[\n" + ",\n".join(inner + _dumps(v, inner) for v in value) + "\n" + indent
                    + "]")
    return json.dumps(value, allow_nan=False)


def _number_rows(value, inner: str):
    """The rows of ``value``, lists (or tuples) of Python floats and ints (no bools), as
    ``json.dumps`` writes each, one per line after ``inner`` and joined by ",\\n"; or None
    when ``value`` holds anything else. json's own encoder writes them all in one call (each
    float's ``repr``), and a NaN or an infinity is refused as json.dumps(...,
    allow_nan=False) refuses it. Rows hold numbers only, so "], [" is found between rows
    alone."""
    if not set(map(type, chain.from_iterable(value))) <= {float, int}:
        return None
    return inner + json.dumps(value, allow_nan=False)[1:-1].replace("], [", "],\n" + inner + "[")


def fold_angles(faces, edges, coordinates) -> np.ndarray:
    """Signed fold angle of every edge of a folded mesh, from its face normals.

    Parameters
    ----------
    faces : sequence of sequence of int
        Planar faces, counter-clockwise in the flat pattern (normals towards +z flat).
    edges : array_like of int, shape (E, 2)
    coordinates : array_like, shape (V, 3)
        Folded positions [mm].

    Returns
    -------
    ndarray, shape (E,)
        Fold angle [rad] in [-pi, pi]: pi minus the dihedral angle, positive for a valley
        (the faces' normal sides turn towards each other), 0 for an edge of one face. Where
        two faces are folded flat onto each other the geometry cannot tell valley from
        mountain and the sign is arbitrary; the caller's assignment decides it. FOLD's
        ``edges_foldAngle`` is this in degrees.
    """
    coordinates = np.asarray(coordinates, dtype=float)
    left_of = {}                       # directed edge (u, v) -> the face on its left
    normals = []
    for index, face in enumerate(faces):
        corners = coordinates[list(face)]
        # Newell's normal: exact for planar faces, robust for any corner order.
        normal = np.cross(corners, np.roll(corners, -1, axis=0)).sum(axis=0)
        normals.append(normal / np.linalg.norm(normal))
        for u, v in zip(face, list(face[1:]) + [face[0]]):
            left_of[(int(u), int(v))] = index
    angles = np.zeros(len(edges))
    for k, (u, v) in enumerate(np.asarray(edges, dtype=int)):
        left, right = left_of.get((u, v)), left_of.get((v, u))
        if left is None or right is None:
            continue
        axis = coordinates[v] - coordinates[u]
        axis /= np.linalg.norm(axis)
        n_left, n_right = normals[left], normals[right]
        angles[k] = np.arctan2(np.dot(np.cross(n_right, n_left), axis), np.dot(n_left, n_right))
    return angles


def fold_document(vertices_coords, edges_vertices, edges_assignment, faces_vertices, *,
                  edges_fold_angle=None, frames=(), title: str = "", unit: str = "mm",
                  creator: str = "kresling", extra: dict | None = None) -> dict:
    """A FOLD document (a ``dict`` ready for ``json.dump``).

    Parameters
    ----------
    vertices_coords : array_like, shape (V, 2) or (V, 3)
        Key frame (the crease pattern) [``unit``].
    edges_vertices : array_like of int, shape (E, 2)
    edges_assignment : sequence of str, length E
        Letters of :data:`ASSIGNMENTS`.
    faces_vertices : sequence of sequence of int
        Counter-clockwise faces.
    edges_fold_angle : array_like, shape (E,), optional
        Fold angles of the key frame [degrees], valley positive; NaN (unknown) is written
        ``null``.
    frames : sequence of dict
        Further frames, each with ``"title"``, ``"vertices_coords"`` (shape (V, 3)) and
        optionally ``"edges_foldAngle"`` (degrees) and ``"classes"`` (default
        ``["foldedForm"]``); each inherits the key frame's edges and faces.
    title, unit, creator : str
    extra : dict, optional
        More top-level properties; custom ones should have a ``"prefix:"`` namespace.

    Returns
    -------
    dict
        ``file_spec`` 1.2 if an assignment is ``"C"`` or ``"J"`` (FOLD 1.2), else 1.1.

    Raises
    ------
    ValueError
        If the arrays disagree in size, an index is out of range or an assignment unknown.
    """
    vertices = np.asarray(vertices_coords, dtype=float)
    count = len(vertices)
    edges = np.asarray(edges_vertices, dtype=int).reshape(-1, 2)
    _check_indices("edges_vertices", edges, count)
    for index, face in enumerate(faces_vertices):
        _check_indices(f"faces_vertices[{index}]", np.asarray(face), count)
    assignments = list(edges_assignment)
    _check_length("edges_assignment", assignments, len(edges))
    unknown = sorted(set(assignments) - set(ASSIGNMENTS))
    if unknown:
        raise ValueError(f"edges_assignment has {unknown}: each must be one of {ASSIGNMENTS}")
    document = {
        "file_spec": 1.2 if {"C", "J"} & set(assignments) else 1.1,
        "file_creator": creator,
        "file_classes": ["singleModel"],
        "frame_title": title,
        "frame_classes": ["creasePattern"],
        "frame_attributes": ["2D" if vertices.shape[1] == 2 else "3D"],
        "frame_unit": unit,
        "vertices_coords": vertices.tolist(),
        "edges_vertices": edges.tolist(),
        "edges_assignment": assignments,
        "faces_vertices": [[int(i) for i in face] for face in faces_vertices],
    }
    if edges_fold_angle is not None:
        document["edges_foldAngle"] = _angles("edges_fold_angle", edges_fold_angle, len(edges))
    if frames:
        document["file_frames"] = [_frame(frame, count, len(edges)) for frame in frames]
    document.update(extra or {})
    return document


def _frame(frame: dict, vertex_count: int, edge_count: int) -> dict:
    coordinates = np.asarray(frame["vertices_coords"], dtype=float)
    if coordinates.shape != (vertex_count, 3):
        raise ValueError(f"frame {frame.get('title', '')!r}: vertices_coords has shape "
                         f"{coordinates.shape}: must be ({vertex_count}, 3)")
    if not np.isfinite(coordinates).all():
        raise ValueError(f"frame {frame.get('title', '')!r}: vertices_coords has a non-finite "
                         "coordinate")
    out = {
        "frame_title": frame.get("title", ""),
        "frame_classes": list(frame.get("classes", ["foldedForm"])),
        "frame_attributes": ["3D"],
        "frame_parent": 0,
        "frame_inherit": True,
        "vertices_coords": coordinates.tolist(),
    }
    if "edges_foldAngle" in frame:
        out["edges_foldAngle"] = _angles("edges_foldAngle", frame["edges_foldAngle"], edge_count)
    return out


class _Frame(dict):
    """A frame of a document :func:`write_fold` made and writes at once (so never changed
    in between), with ``key``: what its JSON text depends on (title, classes, the
    coordinates' and fold angles' bytes)."""

    key = None


def _keyed_frame(written: dict, given: dict) -> _Frame:
    """The frame ``written`` (of :func:`_frame`) with the key of the arrays it was made
    from (``given``)."""
    frame = _Frame(written)
    angles = given.get("edges_foldAngle")
    frame.key = (json.dumps([written["frame_title"], written["frame_classes"]]),
                 np.asarray(given["vertices_coords"], dtype=float).tobytes(),
                 None if angles is None else np.asarray(angles, dtype=float).tobytes())
    return frame


#: The JSON text of frames written so far, by indent and frame key: a path's file is
#: rewritten as the path goes (every frame so far, each time) and whole at its end, with
#: the same frames; each frame's floats are formatted once. Bounded by
#: :data:`_FRAME_TEXT_LIMIT` characters; :func:`forget_frame_texts` lets them go.
_frame_texts: dict = {}
_FRAME_TEXT_LIMIT = 64_000_000
_frame_text_size = [0]


def forget_frame_texts() -> None:
    """Let go of the frames' texts kept by :func:`write_fold` (a new path starts)."""
    _frame_texts.clear()
    _frame_text_size[0] = 0


def _angles(name: str, values, count: int) -> list:
    angles = np.asarray(values, dtype=float)
    _check_length(name, angles, count)
    known = angles[~np.isnan(angles)]
    if not np.all(np.isfinite(known)) or np.any(np.abs(known) > 180.0):
        raise ValueError(f"{name} must hold angles in [-180, 180] degrees (NaN where unknown)")
    return [None if a != a else a for a in angles.tolist()]   # a != a: NaN, at list speed


def _check_length(name: str, values, count: int) -> None:
    if len(values) != count:
        raise ValueError(f"{name} has {len(values)} entries: must have one per edge ({count})")


def _check_indices(name: str, indices: np.ndarray, count: int) -> None:
    bad = indices[(indices < 0) | (indices >= count)]
    if bad.size:
        raise ValueError(f"{name} refers to vertex {int(bad[0])}: must be in [0, {count})")
