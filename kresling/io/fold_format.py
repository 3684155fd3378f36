"""The FOLD format (JSON) of a crease pattern and its folded states: read and write.

FOLD (Demaine, Ku, Lang; specification 1.1 and 1.2) stores the pattern in the *key frame*:
``vertices_coords`` (2D or 3D), ``edges_vertices``, ``edges_assignment``,
``edges_foldAngle`` and ``faces_vertices`` (0-based indices); further configurations of the
same vertices go in ``file_frames``. Lengths are in the file's ``frame_unit`` (this package
writes and assumes mm). Fold angles are in degrees in [-180, 180]: positive for a valley,
negative for a mountain, 0 flat; with faces counter-clockwise about +z in the flat pattern,
a valley folds the faces' +z sides towards each other.

Assignments ``C`` (cut) and ``J`` (join) are FOLD 1.2; a file holding them is written as
``file_spec`` 1.2, any other as 1.1.
"""

from __future__ import annotations

import json
import logging
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from kresling._validation import read_input_file
from kresling.io.errors import MISSING, PatternFileError, file_error, key_error, line_error
from kresling.io.pattern import (ASSIGNMENTS, Pattern, _as_assignments, _as_coordinates,
                                 _as_edges, _as_faces, _as_fold_angles, argument_fail,
                                 check_panels, complete_edges, is_number, pattern_from_arrays)

__all__ = ["ASSIGNMENTS", "fold_angles", "fold_document", "pattern_from_fold", "read_fold",
           "write_fold", "write_fold_document"]

logger = logging.getLogger(__name__)

#: Keys :func:`write_fold` computes from the pattern, which ``metadata`` cannot set.
GEOMETRY_KEYS = ("vertices_coords", "faces_vertices", "edges_vertices", "edges_assignment",
                 "edges_foldAngle", "file_frames")

_REQUIRED = "a FOLD file needs vertices_coords and faces_vertices"


# -- reading -------------------------------------------------------------------------------

def read_fold(path, *, planarity_tolerance=1e-3) -> Pattern:
    """Read a FOLD file (spec 1.1 or 1.2) as a :class:`~kresling.io.Pattern`.

    Parameters
    ----------
    path : str or Path
    planarity_tolerance : float or None, default 1e-3
        Largest distance of a panel's corner from its best-fit plane, as a fraction of the
        panel's diameter; ``None`` skips the check.

    Returns
    -------
    Pattern
        ``vertices`` from the key frame's ``vertices_coords`` [mm] (2D gets ``z = 0``),
        ``faces`` from ``faces_vertices``; ``edges`` are ``edges_vertices`` in file order,
        then the faces' sides missing from it (``"B"`` on one face, else ``"U"``);
        assignments are upper-cased; ``edges_foldAngle`` [degrees, valley positive] with
        NaN for ``null`` and for derived edges; ``frames`` are the ``vertices_coords`` of
        ``file_frames`` that have them (shape (N, 3) each). Other keys are ignored.

    Raises
    ------
    ValueError
        Bad content, naming the file and the element: ``FILE:LINE:COL: not valid JSON: ...``,
        ``FILE: key 'faces_vertices' is missing: ...``,
        ``FILE: key 'vertices_coords'[4] = [1, 'a'] is invalid: must be 2 or 3 numbers``,
        ``FILE: key 'faces_vertices'[3]: face 3 has vertex 40 out of range [0, 39]``,
        ``FILE: face 7 is not planar: ...``.
    OSError
        If the file cannot be read (the message names it).
    """
    source = str(path)
    text = read_input_file(path).decode("utf-8-sig", errors="replace")
    try:
        document = json.loads(text)
    except json.JSONDecodeError as error:
        raise line_error(source, error.lineno, error.colno,
                         f"not valid JSON: {error.msg}") from None
    except RecursionError:
        raise file_error(source, "not valid JSON: nested too deeply") from None
    return pattern_from_fold(document, source=source, planarity_tolerance=planarity_tolerance)


def pattern_from_fold(document, *, source: str = "", planarity_tolerance=1e-3) -> Pattern:
    """A :class:`~kresling.io.Pattern` from a FOLD document already parsed (a ``dict``).

    As :func:`read_fold`, which calls it; ``source`` names the document in messages and
    becomes the pattern's ``source``.
    """
    source = str(source)
    if not isinstance(document, Mapping):
        raise file_error(source or "FOLD document",
                         f"not a FOLD document: the top level is a JSON {_json_type(document)}, "
                         "must be an object")
    fail = _key_fail(source)
    for key in ("vertices_coords", "faces_vertices"):
        if key not in document:
            hint = (" (this one has edges only: panels must be given as faces)"
                    if key == "faces_vertices" and "edges_vertices" in document else "")
            raise key_error(source, key, f"is missing: {_REQUIRED}{hint}")
    vertices = _fold_coordinates(document["vertices_coords"], fail("vertices_coords"))
    count = len(vertices)
    faces = _as_faces(_json_list(document["faces_vertices"], fail("faces_vertices")), count,
                      fail("faces_vertices"))
    edges = np.zeros((0, 2), dtype=np.int64)
    if "edges_vertices" in document:
        edges = _as_edges(_json_list(document["edges_vertices"], fail("edges_vertices")), count,
                          fail("edges_vertices"))
    assignments = angles = None
    for key in ("edges_assignment", "edges_foldAngle"):
        if key in document and "edges_vertices" not in document:
            raise key_error(source, key, "is given without edges_vertices: it has one entry "
                                         "per edge of edges_vertices")
    if "edges_assignment" in document:
        assignments = _as_assignments(
            _json_list(document["edges_assignment"], fail("edges_assignment")), len(edges),
            fail("edges_assignment"))
    if "edges_foldAngle" in document:
        angles = _as_fold_angles(
            _json_list(document["edges_foldAngle"], fail("edges_foldAngle")), len(edges),
            fail("edges_foldAngle"))
    frames = []
    if "file_frames" in document:
        for k, frame in enumerate(_json_list(document["file_frames"], fail("file_frames"))):
            if not isinstance(frame, Mapping):
                raise fail("file_frames")(k, "must be an object (a frame)", value=frame)
            if "vertices_coords" in frame:
                frames.append(_fold_coordinates(frame["vertices_coords"],
                                                _frame_fail(source, k), count=count))
    check_panels(vertices, faces, planarity_tolerance,
                 lambda index, message: _face_error(source, index, message))
    edges, assignments, angles = complete_edges(faces, edges, assignments, angles)
    return Pattern(vertices, faces, edges, assignments, angles, tuple(frames), source)


def _json_type(value) -> str:
    names = {dict: "object", list: "array", str: "string", bool: "boolean", type(None): "null"}
    return names.get(type(value), "number")


def _key_fail(source: str):
    def for_key(key: str):
        return lambda index, message, value=MISSING: key_error(source, key, message, index,
                                                               value=value)
    return for_key


def _frame_fail(source: str, frame: int):
    def fail(index, message, value=MISSING):
        sub = "['vertices_coords']" + (f"[{index}]" if index is not None else "")
        return key_error(source, "file_frames", message, frame, value=value, sub=sub)
    return fail


def _face_error(source: str, index: int, message: str) -> PatternFileError:
    error = file_error(source, message)
    error.key, error.index = "faces_vertices", index
    return error


def _json_list(value, fail) -> list:
    if not isinstance(value, list):
        raise fail(None, f"must be a JSON array, not {_json_type(value)}", value=value)
    return value


def _fold_coordinates(values, fail, *, count: int | None = None) -> np.ndarray:
    """(N, 3) coordinates from a FOLD ``vertices_coords`` list (2D entries get z = 0)."""
    values = _json_list(values, fail)
    array = np.zeros((len(values), 3))
    for index, entry in enumerate(values):
        if not (isinstance(entry, list) and len(entry) in (2, 3)
                and all(is_number(x) for x in entry)):
            raise fail(index, "must be 2 or 3 numbers", value=entry)
        array[index, :len(entry)] = entry
        if not np.isfinite(array[index]).all():
            raise fail(index, f"vertex {index} has a non-finite coordinate")
    if count is not None and len(values) != count:
        raise fail(None, f"has {len(values)} {'vertex' if len(values) == 1 else 'vertices'}: "
                         f"must have {count}, one per vertex of the key frame")
    return array


# -- writing -------------------------------------------------------------------------------

def write_fold(path, pattern_or_vertices, faces=None, *, edges=None, edges_assignment=None,
               edges_fold_angle=None, frames=None, frame_title=None, metadata=None) -> Path:
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
    metadata : dict, optional
        More top-level properties, written last: ``frame_unit`` (default ``"mm"``),
        ``file_title``, ``file_author``, ``frame_classes``, custom ``"prefix:name"`` keys.
        Not the geometry keys (:data:`GEOMETRY_KEYS`).

    Returns
    -------
    Path

    Notes
    -----
    ``file_spec`` is 1.2 if an edge is ``"C"`` or ``"J"``, else 1.1. The key frame is written
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
        pattern = pattern_from_arrays(pattern_or_vertices, faces, edges=edges,
                                      edges_assignment=edges_assignment,
                                      edges_fold_angle=edges_fold_angle)
    if frames is None:
        frames = pattern.frames
    else:
        fail = argument_fail("frames")
        if isinstance(frames, (str, bytes)) or not hasattr(frames, "__len__"):
            raise fail(None, "must be a sequence of (N, 3) arrays", value=frames)
        frames = [_as_coordinates(frame, f"frames[{k}]", count=pattern.num_vertices)
                  for k, frame in enumerate(frames)]
    titles = _titles(frame_title, len(frames))
    flat = not np.any(pattern.vertices[:, 2])
    angles = np.array(pattern.edges_fold_angle)
    unknown = np.isnan(angles)
    if unknown.all():
        angles = None
    else:
        angles[unknown & np.isin(pattern.edges_assignment, ("B", "F"))] = 0.0
    document = fold_document(
        pattern.vertices[:, :2] if flat else pattern.vertices, pattern.edges,
        pattern.edges_assignment, pattern.faces, edges_fold_angle=angles,
        frames=[{"title": title, "vertices_coords": frame}
                for title, frame in zip(titles[1:], frames)],
        title=titles[0],
        extra={"frame_classes": ["creasePattern" if flat else "foldedForm"]})
    document.update(_metadata(metadata))
    return write_fold_document(path, document)


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


#: One encoder for every value (json.dumps with an option builds one per call: with the
#: ABC checks of Mapping on every number, that was most of writing a long path's frames).
_ENCODE = json.JSONEncoder(allow_nan=False).encode
_SCALARS = (str, int, float, type(None))


def _dumps(value, indent: str = "") -> str:
    """JSON with one line per vertex, edge and face: lists of scalars are not broken up."""
    inner = indent + " "
    if isinstance(value, Mapping) and value:
        items = [f"{inner}{json.dumps(str(k))}: {_dumps(v, inner)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + indent + "}"
    if isinstance(value, list) and value and all(
            type(v) is list and all(type(x) in (float, int) for x in v) for v in value):
        # Rows of numbers (coordinates, frames): encoded at once, then one row per line.
        text = _ENCODE(value)[1:-1].replace("], [", "],\n" + inner + "[")
        return "[\n" + inner + text + "\n" + indent + "]"
    if isinstance(value, (list, tuple)) and any(
            not isinstance(v, _SCALARS) and isinstance(v, (Mapping, list, tuple)) for v in value):
        return "[\n" + ",\n".join(inner + _dumps(v, inner) for v in value) + "\n" + indent + "]"
    return _ENCODE(value)


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


def _angles(name: str, values, count: int) -> list:
    angles = np.asarray(values, dtype=float)
    _check_length(name, angles, count)
    known = angles[~np.isnan(angles)]
    if not np.all(np.isfinite(known)) or np.any(np.abs(known) > 180.0):
        raise ValueError(f"{name} must hold angles in [-180, 180] degrees (NaN where unknown)")
    return [None if np.isnan(a) else a for a in angles.tolist()]


def _check_length(name: str, values, count: int) -> None:
    if len(values) != count:
        raise ValueError(f"{name} has {len(values)} entries: must have one per edge ({count})")


def _check_indices(name: str, indices: np.ndarray, count: int) -> None:
    bad = indices[(indices < 0) | (indices >= count)]
    if bad.size:
        raise ValueError(f"{name} refers to vertex {int(bad[0])}: must be in [0, {count})")
