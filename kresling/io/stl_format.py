"""The STL format of a triangle mesh: write (ASCII or binary).

STL holds triangles only: each face is split into a fan of ``len(face) - 2`` triangles from
its first corner, each with its own unit facet normal (right-hand rule on the corner order).
STL has no unit; coordinates are written in mm. Binary files are little-endian: an 80-byte
header, the triangle count (uint32), then per triangle the normal and three corners
(12 float32) and a zero attribute (uint16): ``84 + 50 * triangles`` bytes.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from kresling.io.pattern import checked_coordinates, checked_faces, argument_fail

__all__ = ["fan_triangles", "write_stl"]

_BINARY_TRIANGLE = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)),
                             ("attribute", "<u2")])


def fan_triangles(faces) -> np.ndarray:
    """The triangles of a fan from each face's first corner.

    Parameters
    ----------
    faces : sequence of sequence of int

    Returns
    -------
    ndarray of int64, shape (T, 3)
        ``T = sum(len(face) - 2)``; face ``(a, b, c, d)`` gives ``(a, b, c)``, ``(a, c, d)``.
    """
    triangles = [(face[0], face[k], face[k + 1]) for face in faces
                 for k in range(1, len(face) - 1)]
    return np.array(triangles, dtype=np.int64).reshape(-1, 3)


def write_stl(path, vertices, faces, *, binary: bool = False, name: str = "kresling") -> Path:
    """Write a polygon mesh as an STL file of fan triangles.

    Parameters
    ----------
    path : str or Path
    vertices : array_like, shape (N, 3) or (N, 2)
        Coordinates [mm] (2D get ``z = 0``).
    faces : sequence of sequence of int
        Polygons of 3 or more distinct 0-based vertex indices; each becomes a fan from its
        first corner (right for convex faces).
    binary : bool, default False
        Binary STL (float32 coordinates) instead of ASCII (full double precision).
    name : str, default "kresling"
        The solid's name (ASCII; whitespace becomes ``_``) or the binary header's text.

    Returns
    -------
    Path

    Raises
    ------
    ValueError
        A non-finite coordinate; a face with an index out of range, a repeated vertex or
        fewer than 3 vertices; a face whose corners are collinear (no normal), naming it.
    """
    coordinates = checked_coordinates(vertices, "vertices")
    faces = checked_faces(faces, len(coordinates), argument_fail("faces"))
    if not isinstance(name, str):
        raise ValueError(f"name = {name!r} is invalid: must be a str")
    triangles = fan_triangles(faces)
    owner = np.repeat(np.arange(len(faces)), [len(face) - 2 for face in faces])
    corners = coordinates[triangles]                                        # (T, 3, 3)
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    # A sliver of a fan (three collinear corners of a valid polygon) takes its face's normal.
    scale = np.abs(corners - corners[:, :1]).max(axis=(1, 2))
    sliver = lengths <= 1e-12 * np.maximum(scale, np.finfo(float).tiny) ** 2
    for t in np.flatnonzero(sliver):
        face = coordinates[list(faces[owner[t]])]
        normal = np.cross(face, np.roll(face, -1, axis=0)).sum(axis=0)      # Newell
        if np.linalg.norm(normal) <= 1e-12 * np.abs(face - face[0]).max() ** 2:
            raise ValueError(f"faces[{owner[t]}]: face {owner[t]} is degenerate: its corners "
                             "are collinear, so it has no normal")
        normals[t], lengths[t] = normal, np.linalg.norm(normal)
    normals /= lengths[:, None]
    path = Path(path)
    if binary:
        records = np.zeros(len(triangles), dtype=_BINARY_TRIANGLE)
        records["normal"], records["corners"] = normals, corners
        header = f"kresling binary STL: {name} [mm]".encode("ascii", "replace")[:80]
        with open(path, "wb") as stream:
            stream.write(header.ljust(80, b" "))
            stream.write(np.uint32(len(triangles)).astype("<u4").tobytes())
            stream.write(records.tobytes())
        return path
    solid = re.sub(r"\s+", "_", name.strip()).encode("ascii", "replace").decode() or "kresling"
    lines = [f"solid {solid}"]
    for normal, triangle in zip(normals.tolist(), corners.tolist()):
        lines.append("  facet normal " + " ".join(repr(x) for x in normal))
        lines.append("    outer loop")
        lines += ["      vertex " + " ".join(repr(x) for x in corner) for corner in triangle]
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append(f"endsolid {solid}")
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return path
