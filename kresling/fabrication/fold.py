"""The FOLD format (JSON) of a crease pattern and its folded states.

General: the functions take plain arrays, so any mesh with faces (a crease pattern, a
bar-and-hinge model) can be written. FOLD (Demaine, Ku, Lang; version 1.1 of the spec) stores
the flat pattern in the key frame and further frames in ``file_frames``; lengths are in the
file's unit (here mm) and fold angles in degrees, positive for valleys and negative for
mountains, with faces counter-clockwise about +z: a valley folds the faces towards +z.
"""

from __future__ import annotations

import json
import logging
from pathlib import Path

import numpy as np

__all__ = ["ASSIGNMENTS", "fold_angles", "fold_document", "write_fold"]

logger = logging.getLogger(__name__)

#: FOLD's edge assignments: boundary, mountain, valley, flat, unassigned, cut (a slit: the
#: faces either side are not joined along it), join.
ASSIGNMENTS = ("B", "M", "V", "F", "U", "C", "J")


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
        mountain and the sign is arbitrary; the caller's assignment decides it.
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
        Fold angles of the key frame [degrees].
    frames : sequence of dict
        Further frames, each with ``"title"``, ``"vertices_coords"`` (shape (V, 3)) and
        optionally ``"edges_foldAngle"`` (degrees) and ``"classes"`` (default
        ``["foldedForm"]``); each inherits the key frame's edges and faces.
    title, unit, creator : str
    extra : dict, optional
        More top-level properties; custom ones should have a ``"prefix:"`` namespace.

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
        "file_spec": 1.1,
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


def write_fold(path, document: dict) -> Path:
    """Write a FOLD document (see :func:`fold_document`) as JSON; returns the path."""
    path = Path(path)
    path.write_text(json.dumps(document, indent=1, allow_nan=False))
    logger.info("wrote %s (%d vertices, %d edges)", path, len(document["vertices_coords"]),
                len(document["edges_vertices"]))
    return path


def _frame(frame: dict, vertex_count: int, edge_count: int) -> dict:
    coordinates = np.asarray(frame["vertices_coords"], dtype=float)
    if coordinates.shape != (vertex_count, 3):
        raise ValueError(f"frame {frame.get('title', '')!r}: vertices_coords has shape "
                         f"{coordinates.shape}: must be ({vertex_count}, 3)")
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
    if not np.all(np.isfinite(angles)) or np.any(np.abs(angles) > 180.0):
        raise ValueError(f"{name} must hold finite angles in [-180, 180] degrees")
    return angles.tolist()


def _check_length(name: str, values, count: int) -> None:
    if len(values) != count:
        raise ValueError(f"{name} has {len(values)} entries: must have one per edge ({count})")


def _check_indices(name: str, indices: np.ndarray, count: int) -> None:
    bad = indices[(indices < 0) | (indices >= count)]
    if bad.size:
        raise ValueError(f"{name} refers to vertex {int(bad[0])}: must be in [0, {count})")
