"""Reading FOLD files (spec 1.1 and 1.2): the frame in use, its unit, its faces.

A FOLD file holds a key frame (the top level) and possibly further frames (``file_frames``);
a frame with ``frame_inherit: true`` takes what it does not set from its ``frame_parent``.
The reader builds the pattern from one frame (the key frame unless told otherwise) and
checks only what that frame uses; further frames that move the same mesh become the
pattern's ``frames``, frames with a mesh of their own are left alone. Coordinates are
converted from the frame's ``frame_unit`` to mm. A frame with edges but no
``faces_vertices`` gets the faces its flat edge graph encloses.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from kresling._validation import read_input_file
from kresling.io.coincident_vertices import merge_coincident_vertices
from kresling.io.errors import (MISSING, PatternFileError, describe, file_error, key_error,
                               line_error)
from kresling.io.pattern import (Pattern, checked_assignments, checked_edges, checked_faces,
                                 checked_fold_angles, check_panels, complete_edges, is_integer,
                                 is_number)
from kresling.io.planar_graph import faces_from_edges, plane_coordinates
from kresling.io.units import UNITS, mm_per_unit

__all__ = ["read_fold", "pattern_from_fold"]

_MESH = ("faces_vertices", "edges_vertices")


def read_fold(path, *, planarity_tolerance=1e-3, frame=0, unit=None, scale=None) -> Pattern:
    """Read a FOLD file (spec 1.1 or 1.2) as a :class:`~kresling.io.Pattern`.

    Parameters
    ----------
    path : str or Path
    planarity_tolerance : float or None, default 1e-3
        Largest distance of a panel's corner from its best-fit plane, as a fraction of the
        panel's diameter; ``None`` skips the check.
    frame : int, default 0
        The frame to build the pattern from: 0 is the key frame, ``k`` is
        ``file_frames[k - 1]`` (with what it inherits from its parents).
    unit : str, optional
        The coordinates' unit (one of :data:`~kresling.io.units.UNITS`), replacing the
        frame's ``frame_unit`` (default: that, ``"unit"`` if it has none).
    scale : float, optional
        With ``unit="unit"`` (given or the file's): mm per unit (default 1).

    Returns
    -------
    Pattern
        ``vertices`` from the frame's ``vertices_coords`` in mm (2D gets ``z = 0``);
        ``faces`` from ``faces_vertices``, or, without it, the faces enclosed by the edges
        of a flat frame (counter-clockwise); ``edges`` are ``edges_vertices`` in file
        order, then the faces' sides missing from it (``"B"`` on one face, else ``"U"``);
        assignments upper-cased; ``edges_foldAngle`` [degrees, valley positive] with NaN
        for ``null`` and derived edges; ``frames``: the coordinates [mm] of the other
        frames that move the same mesh. Other keys are ignored.

    Raises
    ------
    ValueError
        Bad content, naming the file and the element: ``FILE:LINE:COL: not valid JSON:
        ...``, ``FILE: key 'vertices_coords'[4] = [1, 'a'] is invalid: must be 2 or 3
        numbers``, ``FILE: key 'faces_vertices'[3]: face 3 has vertex 40 out of range [0,
        39]``, ``FILE: face 7 is not planar: ...``, ``FILE: vertices 3 and 17 coincide
        ...`` (where merging them would not leave a sheet; a vertex written twice is merged
        with a warning, a cut drawn as two boundaries kept:
        :mod:`kresling.io.coincident_vertices`), an unknown ``frame_unit`` or a frame that does not exist.
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
    return pattern_from_fold(document, source=source, planarity_tolerance=planarity_tolerance,
                             frame=frame, unit=unit, scale=scale)


def pattern_from_fold(document, *, source: str = "", planarity_tolerance=1e-3, frame=0,
                      unit=None, scale=None) -> Pattern:
    """A :class:`~kresling.io.Pattern` from a FOLD document already parsed (a ``dict``).

    As :func:`read_fold`, which calls it; ``source`` names the document in messages and
    becomes the pattern's ``source``.
    """
    source = str(source)
    if not isinstance(document, Mapping):
        raise file_error(source or "FOLD document",
                         f"not a FOLD document: the top level is a JSON {_json_type(document)}, "
                         "must be an object")
    frames = _frames(document, source)
    if not is_integer(frame) or not 0 <= int(frame) < len(frames):
        raise file_error(source, f"frame = {frame!r} is invalid: the file has frames 0 to "
                                 f"{len(frames) - 1} (0 is the key frame, k is "
                                 "file_frames[k - 1])")
    frame = int(frame)
    chosen, owner = _resolve(frames, frame, source)
    if "vertices_coords" not in chosen:
        raise key_error(source, "vertices_coords", "is missing: a FOLD file needs "
                        "vertices_coords, and faces_vertices or edges_vertices")
    factor = _factor(chosen, owner, source, unit, scale)
    vertices = _fold_coordinates(chosen["vertices_coords"],
                                 _fail(source, owner["vertices_coords"], "vertices_coords"))
    count = len(vertices)
    edges = np.zeros((0, 2), dtype=np.int64)
    if "edges_vertices" in chosen:
        edges = checked_edges(_json_list(chosen["edges_vertices"],
                                     _fail(source, owner["edges_vertices"], "edges_vertices")),
                          count, _fail(source, owner["edges_vertices"], "edges_vertices"))
    assignments, angles = _edge_values(chosen, owner, source, len(edges))
    if "faces_vertices" in chosen:
        fail = _fail(source, owner["faces_vertices"], "faces_vertices")
        faces = checked_faces(_json_list(chosen["faces_vertices"], fail), count, fail)
    else:
        faces = _derived_faces(vertices, edges, source)
    moving = _moving_frames(frames, frame, owner, count, source)
    vertices *= factor
    declared = len(edges) if assignments is not None else 0
    edges, assignments, angles = complete_edges(faces, edges, assignments, angles)
    check_panels(vertices, faces, planarity_tolerance,
                 lambda index, message: _face_error(source, index, message))
    merged = merge_coincident_vertices(vertices, faces, edges, assignments, angles,
                                       tuple(f * factor for f in moving),
                                       lambda message: file_error(source, message),
                                       declared=declared, source=source)
    return Pattern(*merged, source)


def _frames(document, source) -> list:
    """The key frame (the document) and every entry of ``file_frames``, checked objects."""
    frames = [document]
    if "file_frames" in document:
        fail = _fail(source, 0, "file_frames")
        for k, entry in enumerate(_json_list(document["file_frames"], fail)):
            if not isinstance(entry, Mapping):
                raise fail(k, "must be an object (a frame)", value=entry)
            frames.append(entry)
    return frames


def _resolve(frames, k, source, depth=0):
    """Frame ``k``'s properties with what it inherits, and the frame each came from."""
    if depth > len(frames):
        raise _fail(source, k, "frame_parent")(None, "makes a cycle of frame parents")
    entry = frames[k]
    own = {key: value for key, value in entry.items() if not key.startswith("file_")}
    if k == 0 or entry.get("frame_inherit") is not True:
        return own, {key: k for key in own} | {key: k for key in ("vertices_coords",) + _MESH
                                                if key not in own}
    parent = entry.get("frame_parent", 0)
    if not is_integer(parent) or not 0 <= int(parent) < len(frames) or int(parent) == k:
        raise _fail(source, k, "frame_parent")(None, f"= {parent!r} is invalid: must be the "
                                                     f"index of another frame (0 to "
                                                     f"{len(frames) - 1})")
    merged, owner = _resolve(frames, int(parent), source, depth + 1)
    merged, owner = dict(merged), dict(owner)
    merged.update(own)
    owner.update({key: k for key in own})
    return merged, owner


def _mesh_of(frames, k, source):
    """Which frames give frame ``k``'s faces and edges: a frame that neither inherits nor
    has a mesh of its own moves the key frame's."""
    entry = frames[k]
    if k and entry.get("frame_inherit") is not True and not any(key in entry for key in _MESH):
        return (0, 0)
    _, owner = _resolve(frames, k, source)
    return tuple(owner[key] for key in _MESH)


def _moving_frames(frames, chosen, owner, count, source) -> list:
    """Coordinates of the other frames that move the chosen frame's mesh (checked)."""
    mesh = tuple(owner[key] for key in _MESH)
    moving = []
    for k, entry in enumerate(frames):
        if k == chosen or "vertices_coords" not in entry or _mesh_of(frames, k, source) != mesh:
            continue
        of = "the key frame" if chosen == 0 else f"frame {chosen}"
        moving.append(_fold_coordinates(entry["vertices_coords"],
                                        _fail(source, k, "vertices_coords"), count=count,
                                        of=of))
    return moving


def _factor(chosen, owner, source, unit, scale) -> float:
    if unit is not None:
        return mm_per_unit(unit, scale)
    name = chosen.get("frame_unit", "unit")
    if not isinstance(name, str) or name not in UNITS:
        raise _fail(source, owner.get("frame_unit", 0), "frame_unit")(
            None, f"= {describe(name)} is a unit this package does not know: must be one of "
                  f"{list(UNITS)} (or state the unit in the problem: [pattern] unit)")
    return mm_per_unit(name, scale, name="frame_unit")


def _edge_values(chosen, owner, source, count):
    assignments = angles = None
    for key in ("edges_assignment", "edges_foldAngle"):
        if key in chosen and "edges_vertices" not in chosen:
            raise _fail(source, owner[key], key)(
                None, "is given without edges_vertices: it has one entry per edge of "
                      "edges_vertices")
    if "edges_assignment" in chosen:
        fail = _fail(source, owner["edges_assignment"], "edges_assignment")
        assignments = checked_assignments(_json_list(chosen["edges_assignment"], fail), count, fail)
    if "edges_foldAngle" in chosen:
        fail = _fail(source, owner["edges_foldAngle"], "edges_foldAngle")
        angles = checked_fold_angles(_json_list(chosen["edges_foldAngle"], fail), count, fail)
    return assignments, angles


def _derived_faces(vertices, edges, source) -> tuple:
    """The faces a flat frame's edges enclose (FOLD tools derive them so)."""
    if not len(edges):
        raise key_error(source, "faces_vertices", "is missing: a FOLD file needs "
                        "faces_vertices, or edges_vertices to derive them from")
    flat = plane_coordinates(vertices)
    if flat is None:
        raise key_error(source, "faces_vertices", "is missing and the frame is not flat: "
                        "faces are derived only from a flat crease pattern's edges (give "
                        "faces_vertices, or choose a flat frame with [pattern] frame)")
    faces = faces_from_edges(flat, edges)
    if not faces:
        raise key_error(source, "faces_vertices", "is missing and edges_vertices encloses "
                        "no face: give faces_vertices")
    for index, face in enumerate(faces):
        twice = [v for v in face if face.count(v) > 1]
        if twice:
            raise key_error(source, "edges_vertices", f"encloses a region whose outline "
                            f"touches itself at vertex {twice[0]} (face {index} derived from "
                            "the edges): a panel must be a simple polygon; add an edge that "
                            "splits it, or give faces_vertices")
    return tuple(tuple(face) for face in faces)


def _fail(source: str, frame: int, key: str):
    """``fail`` for ``key`` of frame ``frame`` (the top level for the key frame)."""
    if frame == 0:
        return lambda index, message, value=MISSING: key_error(source, key, message, index,
                                                               value=value)

    def fail(index, message, value=MISSING):
        sub = f"['{key}']" + (f"[{index}]" if index is not None else "")
        return key_error(source, "file_frames", message, frame - 1, value=value, sub=sub)
    return fail


def _json_type(value) -> str:
    names = {dict: "object", list: "array", str: "string", bool: "boolean", type(None): "null"}
    return names.get(type(value), "number")


def _face_error(source: str, index: int, message: str) -> PatternFileError:
    error = file_error(source, message)
    error.key, error.index = "faces_vertices", index
    return error


def _json_list(value, fail) -> list:
    if not isinstance(value, list):
        raise fail(None, f"must be a JSON array, not {_json_type(value)}", value=value)
    return value


def _fold_coordinates(values, fail, *, count: int | None = None,
                      of: str = "the key frame") -> np.ndarray:
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
                         f"must have {count}, one per vertex of {of}")
    return array
