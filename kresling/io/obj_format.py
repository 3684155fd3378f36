"""The Wavefront OBJ format of a polygon mesh: read and write.

Read: ``v x y z`` vertices (a fourth ``w`` or colour values are ignored) and ``f`` faces of
3 or more vertices, written ``v``, ``v/vt``, ``v/vt/vn`` or ``v//vn``; only the vertex index
is used. Indices count from 1; a negative index counts back from the last vertex read so far
(-1 is the last). ``#`` starts a comment; a line ending in a backslash continues on the next
line; every other statement (``vn``, ``vt``, ``o``, ``g``, ``s``, ``usemtl``, ``mtllib``,
``l``, ...) is ignored. OBJ has no unit: coordinates are taken as mm, and no creases: the
edges are the faces' sides (``"B"`` on one face, else ``"U"``, fold angles unknown).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from kresling._validation import read_input_file
from kresling.io.coincident_vertices import merge_coincident_vertices
from kresling.io.errors import PatternFileError, file_error, line_error
from kresling.io.pattern import (Pattern, checked_coordinates, checked_faces, argument_fail,
                                 check_panels, complete_edges)

__all__ = ["read_obj", "write_obj"]

_TOKEN = re.compile(r"\S+")


def read_obj(path, *, planarity_tolerance=1e-3) -> Pattern:
    """Read a Wavefront OBJ file as a :class:`~kresling.io.Pattern`.

    Parameters
    ----------
    path : str or Path
    planarity_tolerance : float or None, default 1e-3
        Largest distance of a panel's corner from its best-fit plane, as a fraction of the
        panel's diameter; ``None`` skips the check.

    Returns
    -------
    Pattern
        ``vertices`` [mm], shape (N, 3), in file order; ``faces`` 0-based, in file order;
        ``edges`` the faces' sides in order of first appearance; no frames.

    Raises
    ------
    ValueError
        Bad content, as ``FILE:LINE:COLUMN: message`` (1-based, the column of the offending
        token). Vertices are numbered as in the file (from 1), faces from 0 as in
        ``Pattern.faces``: ``sheet.obj:12:9: face 3 has vertex 40 out of range [1, 39]``,
        ``sheet.obj:5:3: vertex 4 has a non-finite coordinate``,
        ``sheet.obj:20:1: face 7 is not planar: ...``.
    OSError
        If the file cannot be read (the message names it).
    """
    source = str(path)
    text = read_input_file(path).decode("utf-8-sig", errors="replace")
    vertices = []
    faces = []          # (line, column of "f", [(index, line, column)], vertices so far)
    for keyword, tokens in _statements(text):
        word, line, column = keyword
        if word == "v":
            vertices.append(_vertex(source, len(vertices) + 1, keyword, tokens))
        elif word == "f":
            faces.append((line, column, [_index(source, len(faces), t) for t in tokens],
                          len(vertices)))
    if not faces:
        raise file_error(source, "has no faces: a pattern needs at least one 'f' statement")
    count = len(vertices)
    resolved = [_face(source, index, face, count) for index, face in enumerate(faces)]
    coordinates = np.array(vertices, dtype=np.float64).reshape(-1, 3)

    def fail(index: int, message: str) -> PatternFileError:
        error = line_error(source, faces[index][0], faces[index][1], message)
        error.key, error.index = "f", index
        return error

    check_panels(coordinates, resolved, planarity_tolerance, fail, first=1)
    edges, assignments, angles = complete_edges(resolved, np.zeros((0, 2), dtype=np.int64))
    merged = merge_coincident_vertices(coordinates, tuple(resolved), edges, assignments, angles,
                                       (), lambda message: file_error(source, message),
                                       declared=0, source=source, first=1)
    return Pattern(*merged, source)


def _statements(text: str):
    """Yield ``((keyword, line, column), [(token, line, column), ...])`` per statement."""
    pending = []
    for number, raw in enumerate(text.splitlines(), start=1):
        content = raw.split("#", 1)[0]
        continued = content.rstrip().endswith("\\")
        if continued:
            content = content.rstrip()[:-1]
        pending.extend((m.group(), number, m.start() + 1) for m in _TOKEN.finditer(content))
        if continued:
            continue
        if pending:
            yield pending[0], pending[1:]
        pending = []
    if pending:
        yield pending[0], pending[1:]


def _vertex(source: str, number: int, keyword, tokens) -> list:
    if len(tokens) < 3:
        raise line_error(source, keyword[1], keyword[2],
                         f"vertex {number} has {len(tokens)} coordinate"
                         f"{'' if len(tokens) == 1 else 's'}: must have x y z")
    values = []
    for text, line, column in tokens[:3]:
        try:
            values.append(float(text))
        except ValueError:
            raise line_error(source, line, column, f"vertex {number} has coordinate {text!r}: "
                                                   "must be a number") from None
        if not np.isfinite(values[-1]):
            raise line_error(source, line, column,
                             f"vertex {number} has a non-finite coordinate")
    return values


def _index(source: str, face: int, token) -> tuple:
    text, line, column = token
    head = text.split("/", 1)[0]
    try:
        value = int(head)
    except ValueError:
        raise line_error(source, line, column,
                         f"face {face} has vertex {text!r}: must be an integer index "
                         "(v, v/vt, v/vt/vn or v//vn)") from None
    return value, line, column


def _face(source: str, index: int, face, count: int) -> tuple:
    line, column, tokens, read = face
    if len(tokens) < 3:
        raise line_error(source, line, column,
                         f"face {index} has {_vertices(len(tokens))}: a face needs at least 3")
    vertices = []
    for value, token_line, token_column in tokens:
        if value > 0 and value <= count:
            vertex = value - 1
        elif value < 0 and -value <= read:
            vertex = read + value
        else:
            allowed = (f"[1, {count}]" if value >= 0 and count else
                       f"[-{read}, -1] (relative to the {_vertices(read)} before it)" if read
                       else "(there are no vertices before it)" if value < 0
                       else "(the file has no vertices)")
            raise line_error(source, token_line, token_column,
                             f"face {index} has vertex {value} out of range {allowed}")
        if vertex in vertices:
            raise line_error(source, token_line, token_column,
                             f"face {index} repeats vertex {vertex + 1}")
        vertices.append(vertex)
    return tuple(vertices)


def _vertices(count: int) -> str:
    return f"{count} vertex" if count == 1 else f"{count} vertices"


def write_obj(path, vertices, faces) -> Path:
    """Write a polygon mesh as a Wavefront OBJ file.

    Parameters
    ----------
    path : str or Path
    vertices : array_like, shape (N, 3) or (N, 2)
        Coordinates [mm] (2D get ``z = 0``); written with full double precision, so
        :func:`read_obj` gives them back exactly.
    faces : sequence of sequence of int
        Polygons of 3 or more distinct 0-based vertex indices (written 1-based).

    Returns
    -------
    Path

    Raises
    ------
    ValueError
        A non-finite coordinate, or a face with an index out of range, a repeated vertex or
        fewer than 3 vertices (naming the face). The geometry (planarity) is not checked.
    """
    coordinates = checked_coordinates(vertices, "vertices")
    faces = checked_faces(faces, len(coordinates), argument_fail("faces"))
    lines = [f"# kresling: {len(coordinates)} vertices [mm], {len(faces)} faces"]
    lines += ["v " + " ".join(repr(x) for x in row) for row in coordinates.tolist()]
    lines += ["f " + " ".join(str(i + 1) for i in face) for face in faces]
    path = Path(path)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path
