"""The :class:`Pattern` value type: a crease pattern's vertices, panels and creases.

A pattern is what a file of :mod:`kresling.io` holds: vertex coordinates [mm] (shape (N, 3)),
panels (faces, polygons of 3 or more vertices, 0-based indices), the edges between them with
a FOLD assignment and fold angle [degrees] each, and possibly further configurations
(frames) of the same vertices. :func:`pattern_from_arrays` builds one from arrays and checks
it as the file readers do.

The checks here are shared by the readers; each reports a problem through a ``fail``
callable that turns a message into an exception carrying the location in the file.
"""

from __future__ import annotations

import numbers
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Callable, Optional

import numpy as np

from kresling._validation import as_positive_real
from kresling.io.errors import MISSING, PatternFileError, describe, key_error

__all__ = ["ASSIGNMENTS", "Pattern", "pattern_from_arrays"]

#: FOLD's edge assignments: boundary, mountain, valley, flat, unassigned, cut (a slit: the
#: faces either side are not joined along it), join. ``C`` and ``J`` are FOLD 1.2.
ASSIGNMENTS = ("B", "M", "V", "F", "U", "C", "J")

#: A panel whose area is below this times its squared diameter is degenerate.
DEGENERATE_AREA = 1e-12

#: Callable turning ``(index, message, value=MISSING)`` into the exception to raise.
Fail = Callable[..., Exception]


def _read_only(array: np.ndarray) -> np.ndarray:
    array.setflags(write=False)
    return array


@dataclass(frozen=True, eq=False, repr=False)
class Pattern:
    """A crease pattern: vertices, panels (faces), edges with assignments, further frames.

    Build one with :func:`pattern_from_arrays` (which derives missing edges and checks the
    panels' geometry) or read one with :func:`~kresling.io.read_pattern`. The constructor
    converts and checks the structure (shapes, indices, letters) but not the geometry.
    Patterns are immutable: the arrays are read-only. Two patterns are equal (``==``) when
    every field but ``source`` is (NaN fold angles compare equal).

    Attributes
    ----------
    vertices : ndarray of float64, shape (N, 3)
        Coordinates [mm] of the key frame (usually the flat crease pattern); 2D coordinates
        given to the constructor get ``z = 0``.
    faces : tuple of tuple of int
        The panels: 0-based vertex indices, at least 3 distinct ones each, in file order.
    edges : ndarray of int64, shape (E, 2)
        Vertex pairs; every side of every face is one of them (in either direction).
    edges_assignment : tuple of str, length E
        One of :data:`ASSIGNMENTS` per edge: ``"M"`` mountain, ``"V"`` valley, ``"F"`` flat,
        ``"B"`` boundary, ``"C"`` cut, ``"U"`` unassigned, ``"J"`` join.
    edges_fold_angle : ndarray of float64, shape (E,)
        Fold angle [degrees] in [-180, 180] in FOLD's convention (positive for a valley,
        negative for a mountain, 0 flat); NaN where unknown.
    frames : tuple of ndarray, each of shape (N, 3)
        Further configurations [mm] of the same vertices (a FOLD file's ``file_frames``, the
        deformed states along a path); may be empty.
    source : str
        The file the pattern was read from (``""`` if built in memory).
    """

    vertices: np.ndarray
    faces: tuple
    edges: np.ndarray
    edges_assignment: tuple
    edges_fold_angle: np.ndarray
    frames: tuple = ()
    source: str = ""

    def __post_init__(self) -> None:
        vertices = checked_coordinates(self.vertices, "vertices")
        count = len(vertices)
        faces = checked_faces(self.faces, count, argument_fail("faces"), required=False)
        edges = checked_edges(self.edges, count, argument_fail("edges"))
        assignments = checked_assignments(self.edges_assignment, len(edges),
                                      argument_fail("edges_assignment"))
        angles = checked_fold_angles(self.edges_fold_angle, len(edges),
                                 argument_fail("edges_fold_angle"))
        frames = tuple(checked_coordinates(frame, f"frames[{k}]", count=count)
                       for k, frame in enumerate(_as_list(self.frames, argument_fail("frames"))))
        known = {(min(u, v), max(u, v)) for u, v in edges.tolist()}
        for index, face in enumerate(faces):
            for u, v in _sides(face):
                if (min(u, v), max(u, v)) not in known:
                    raise argument_fail("faces")(
                        index, f"side ({u}, {v}) of face {index} is not in edges: every side "
                               "of a face must be an edge (pattern_from_arrays derives "
                               "missing ones)")
        if not isinstance(self.source, str):
            raise argument_fail("source")(None, "must be a str", value=self.source)
        for name, value in (("vertices", _read_only(vertices)), ("faces", faces),
                            ("edges", _read_only(edges)), ("edges_assignment", assignments),
                            ("edges_fold_angle", _read_only(angles)),
                            ("frames", tuple(_read_only(f) for f in frames))):
            object.__setattr__(self, name, value)

    @property
    def num_vertices(self) -> int:
        """Number of vertices N."""
        return len(self.vertices)

    @property
    def num_faces(self) -> int:
        """Number of faces (panels)."""
        return len(self.faces)

    @property
    def num_edges(self) -> int:
        """Number of edges E."""
        return len(self.edges)

    def face_edges(self) -> tuple:
        """The edge of every side of every face.

        Returns
        -------
        tuple of tuple of int
            For face ``f`` with corners ``c_0 .. c_{k-1}``, entry ``j`` is the index into
            :attr:`edges` of its side from ``c_j`` to ``c_{j+1}`` (``c_k = c_0``).
        """
        index = {}
        for k, (u, v) in enumerate(self.edges.tolist()):
            index.setdefault((min(u, v), max(u, v)), k)
        return tuple(tuple(index[(min(u, v), max(u, v))] for u, v in _sides(face))
                     for face in self.faces)

    def __eq__(self, other) -> bool:
        if not isinstance(other, Pattern):
            return NotImplemented
        return (np.array_equal(self.vertices, other.vertices)
                and self.faces == other.faces
                and np.array_equal(self.edges, other.edges)
                and self.edges_assignment == other.edges_assignment
                and np.array_equal(self.edges_fold_angle, other.edges_fold_angle, equal_nan=True)
                and len(self.frames) == len(other.frames)
                and all(np.array_equal(a, b) for a, b in zip(self.frames, other.frames)))

    __hash__ = None  # mutable-looking arrays: not hashable, like ndarray

    def __repr__(self) -> str:
        source = f", source={self.source!r}" if self.source else ""
        return (f"Pattern({self.num_vertices} vertices, {self.num_faces} faces, "
                f"{self.num_edges} edges, {len(self.frames)} frames{source})")


def pattern_from_arrays(vertices, faces, *, edges=None, edges_assignment=None,
                        edges_fold_angle=None, planarity_tolerance=1e-3,
                        panels_required=True) -> Pattern:
    """A checked :class:`Pattern` from arrays (``source = ""``).

    Parameters
    ----------
    vertices : array_like, shape (N, 3) or (N, 2)
        Coordinates [mm]; 2D ones get ``z = 0``.
    faces : sequence of sequence of int
        Panels: 0-based vertex indices, at least 3 distinct ones each.
    edges : array_like of int, shape (E, 2), optional
        Edges in this order; the sides of faces not among them are appended (each side once,
        in order of first appearance in ``faces``).
    edges_assignment : sequence of str, length E, optional
        Letters of :data:`ASSIGNMENTS` (any case) for ``edges``; default, and for the
        appended edges: ``"B"`` for a side of one face, ``"U"`` otherwise.
    edges_fold_angle : array_like, shape (E,), optional
        Fold angles [degrees] of ``edges`` in FOLD's convention (valley positive); NaN or
        ``None`` where unknown (the default, and for the appended edges).
    planarity_tolerance : float or None, default 1e-3
        Largest distance of a panel's corner from the panel's best-fit plane, as a fraction
        of the panel's diameter; ``None`` skips the check (a deformed mesh).
    panels_required : bool, default True
        False accepts ``faces = []``: vertices alone, the nodes of a structure whose bars
        and hinges are given one by one (:class:`kresling.model.Members`).

    Returns
    -------
    Pattern

    Raises
    ------
    ValueError
        Naming the argument and the entry: a vertex index out of range, a repeated vertex or
        fewer than 3 in a face, a non-finite coordinate, an assignment list of the wrong
        length or an unknown letter, a degenerate or non-planar panel.
    """
    coordinates = checked_coordinates(vertices, "vertices")
    face_list = checked_faces(faces, len(coordinates), argument_fail("faces"),
                              required=panels_required)
    given = (np.zeros((0, 2), dtype=np.int64) if edges is None
             else checked_edges(edges, len(coordinates), argument_fail("edges")))
    assignments = (None if edges_assignment is None else checked_assignments(
        edges_assignment, len(given), argument_fail("edges_assignment")))
    angles = (None if edges_fold_angle is None else checked_fold_angles(
        edges_fold_angle, len(given), argument_fail("edges_fold_angle")))
    check_panels(coordinates, face_list, planarity_tolerance,
                 lambda index, message: PatternFileError(message, key="faces", index=index))
    return Pattern(coordinates, face_list, *complete_edges(face_list, given, assignments, angles))


# -- shared checks -------------------------------------------------------------------------
#
# A ``fail`` callable turns ``(index, message, value=MISSING)`` into the exception to raise,
# adding where the entry is: a FOLD key, an argument name, an OBJ line.

def argument_fail(name: str) -> Fail:
    """``fail`` for an argument given in memory: messages start with ``name[index]``."""
    return lambda index, message, value=MISSING: key_error("", name, message, index,
                                                           value=value)


def _sides(face) -> list:
    return list(zip(face, face[1:] + face[:1]))


def _is_sequence(value) -> bool:
    return isinstance(value, (Sequence, np.ndarray)) and not isinstance(value, (str, bytes))


def _as_list(values, fail: Fail) -> list:
    if _is_sequence(values):
        return list(values)
    raise fail(None, "must be a sequence", value=values)


def is_number(value) -> bool:
    """A real number a float can hold, not a bool (JSON ``true`` is not a coordinate, nor is
    a 400-digit integer: float() of it overflows)."""
    if not isinstance(value, numbers.Real) or isinstance(value, (bool, np.bool_)):
        return False
    if isinstance(value, numbers.Integral):
        return abs(int(value)) < 2**1024
    return True


def is_integer(value) -> bool:
    """An integral number (an int or an integral float), not a bool."""
    if not is_number(value):
        return False
    if isinstance(value, numbers.Integral):
        return True
    return bool(np.isfinite(value)) and float(value) == int(value)


#: Largest coordinate magnitude of a vertex [mm]: far beyond any sheet, and far enough
#: inside the floating-point range that squared lengths, areas and the hinges' gradients
#: (products of up to ~6 lengths) stay finite (1e30^6 = 1e180).
MAX_COORDINATE = 1e30


def checked_coordinates(values, name: str, *, count: int | None = None) -> np.ndarray:
    """(N, 3) float64 copy of 2D or 3D coordinates given in memory."""
    try:
        array = np.array(values, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):  # text, ragged rows, 10**400
        array = None
    rows = "N" if count is None else str(count)
    if array is None or array.ndim != 2 or array.shape[1] not in (2, 3) or (
            count is not None and len(array) != count):
        found = "entries that are not numbers" if array is None else f"shape {array.shape}"
        raise PatternFileError(f"{name} has {found}: must be an array of shape ({rows}, 3) "
                               f"or ({rows}, 2) [mm]", key=name)
    if array.shape[1] == 2:
        array = np.column_stack([array, np.zeros(len(array))])
    bad = np.flatnonzero(~np.isfinite(array).all(axis=1))
    if bad.size:
        raise PatternFileError(f"{name}[{bad[0]}]: vertex {bad[0]} has a non-finite coordinate",
                               key=name, index=int(bad[0]))
    far = np.flatnonzero((np.abs(array) > MAX_COORDINATE).any(axis=1))
    if far.size:
        raise PatternFileError(f"{name}[{far[0]}]: vertex {far[0]} has a coordinate of "
                               f"{np.abs(array[far[0]]).max():.3g} mm, out of range: at most "
                               f"{MAX_COORDINATE:g} mm", key=name, index=int(far[0]))
    return array


def check_face(face, count: int, fail: Fail, index: int) -> tuple:
    """One face as a tuple of int: integer entries in ``[0, count)``, distinct, >= 3."""
    # The readers' faces (Python ints, valid): accepted at once; anything else entry by
    # entry below, which names the first bad one.
    # (A problem file's inline panels are lists of ints: the same bulk path, as a tuple.)
    if type(face) in (tuple, list) and len(face) >= 3 and all(type(v) is int for v in face) \
            and min(face) >= 0 and max(face) < count and len(set(face)) == len(face):
        return tuple(face)
    if not _is_sequence(face):
        raise fail(index, "must be a list of vertex indices", value=face)
    vertices = []
    for value in face:
        if not is_integer(value):
            raise fail(index, f"face {index} has vertex {describe(value)}: must be an integer "
                              "index")
        vertex = int(value)
        if not 0 <= vertex < count:
            allowed = f"[0, {count - 1}]" if count else "(there are no vertices)"
            raise fail(index, f"face {index} has vertex {vertex} out of range {allowed}")
        if vertex in vertices:
            raise fail(index, f"face {index} repeats vertex {vertex}")
        vertices.append(vertex)
    if len(vertices) < 3:
        raise fail(index, f"face {index} has {len(vertices)} "
                          f"{'vertex' if len(vertices) == 1 else 'vertices'}: a face needs at "
                          "least 3")
    return tuple(vertices)


def checked_faces(faces, count: int, fail: Fail, *, required: bool = True) -> tuple:
    faces = tuple(check_face(face, count, fail, index)
                  for index, face in enumerate(_as_list(faces, fail)))
    if not faces and required:
        raise fail(None, "is empty: a pattern needs at least one face (panel)")
    return faces


def check_edge(edge, count: int, fail: Fail, index: int) -> tuple:
    """One edge as ``(u, v)``: two distinct integer vertex indices in ``[0, count)``."""
    if not _is_sequence(edge) or len(edge) != 2 or not all(is_integer(v) for v in edge):
        raise fail(index, "must be 2 vertex indices", value=edge)
    u, v = int(edge[0]), int(edge[1])
    for vertex in (u, v):
        if not 0 <= vertex < count:
            allowed = f"[0, {count - 1}]" if count else "(there are no vertices)"
            raise fail(index, f"vertex {vertex} is out of range {allowed}", value=edge)
    if u == v:
        raise fail(index, "an edge needs two different vertices", value=edge)
    return u, v


def check_unique_edges(edges: np.ndarray, fail: Fail) -> None:
    """Each vertex pair once; ``fail`` names the repeat."""
    pairs = np.sort(np.asarray(edges, dtype=np.int64).reshape(-1, 2), axis=1)
    # A repeat is next to its twin once sorted (numpy's unique would import numpy.ma, about
    # 10 ms of every read).
    ordered = pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))]
    if not (ordered[1:] == ordered[:-1]).all(axis=1).any():
        return
    seen = {}
    for index, (u, v) in enumerate(np.asarray(edges).tolist()):
        key = (min(u, v), max(u, v))
        if key in seen:
            raise fail(index, f"repeats edge {seen[key]}", value=[u, v])
        seen[key] = index


def checked_edges(edges, count: int, fail: Fail) -> np.ndarray:
    # An integer array of valid pairs (what the readers build) is checked in bulk; anything
    # else pair by pair, which names the first bad one.
    if isinstance(edges, np.ndarray) and edges.dtype.kind in "iu" and edges.ndim == 2 and \
            edges.shape[1] == 2 and len(edges) and edges.min() >= 0 and \
            edges.max() < count and (edges[:, 0] != edges[:, 1]).all():
        array = edges.astype(np.int64)
        check_unique_edges(array, fail)
        return array
    pairs = [check_edge(edge, count, fail, k) for k, edge in enumerate(_as_list(edges, fail))]
    array = np.array(pairs, dtype=np.int64).reshape(-1, 2)
    check_unique_edges(array, fail)
    return array


def normalise_assignment(value) -> Optional[str]:
    """The upper-case letter of a FOLD assignment, or None if ``value`` is not one."""
    if isinstance(value, str) and value.upper() in ASSIGNMENTS:
        return value.upper()
    return None


def check_count(values: list, count: int, fail: Fail, what: str = "edge") -> None:
    """One entry per edge (or per ``what``)."""
    if len(values) != count:
        raise fail(None, f"has {len(values)} entries: must have one per {what} ({count})")


def check_assignment(value, fail: Fail, index: int) -> str:
    """An assignment letter, any case; returned upper case."""
    letter = normalise_assignment(value)
    if letter is None:
        raise fail(index, f"must be one of {', '.join(ASSIGNMENTS)} (any case)", value=value)
    return letter


def checked_assignments(values, count: int, fail: Fail) -> tuple:
    values = list(values) if isinstance(values, str) else _as_list(values, fail)
    check_count(values, count, fail)
    return tuple(check_assignment(value, fail, index) for index, value in enumerate(values))


def check_fold_angle(value, fail: Fail, index: int) -> float:
    """A fold angle [degrees] in [-180, 180]; ``None`` and NaN mean unknown (NaN)."""
    if value is None:
        return float("nan")
    if not is_number(value):
        raise fail(index, "must be a number of degrees (or null)", value=value)
    angle = float(value)
    if not (np.isnan(angle) or -180.0 <= angle <= 180.0):
        raise fail(index, "must be in [-180, 180] degrees", value=value)
    return angle


def checked_fold_angles(values, count: int, fail: Fail) -> np.ndarray:
    values = _as_list(values, fail)
    check_count(values, count, fail)
    return np.array([check_fold_angle(v, fail, k) for k, v in enumerate(values)],
                    dtype=np.float64).reshape(-1)


def complete_edges(faces, edges: np.ndarray, assignments=None, angles=None):
    """Append the faces' sides missing from ``edges``; fill in assignments and angles.

    Parameters
    ----------
    faces : tuple of tuple of int
    edges : ndarray of int, shape (E, 2)
        Checked, distinct vertex pairs.
    assignments : tuple of str, length E, optional
    angles : ndarray, shape (E,), optional

    Returns
    -------
    edges : ndarray of int64, shape (E', 2)
        ``edges``, then every face side not among them once, in order of first appearance
        (in the direction it first appears).
    assignments : tuple of str, length E'
        As given; else (and for appended edges) ``"B"`` for a side of one face, else ``"U"``.
    angles : ndarray, shape (E',)
        As given; else (and for appended edges) NaN.
    """
    pairs = [tuple(pair) for pair in np.asarray(edges, dtype=np.int64).reshape(-1, 2).tolist()]
    index = {(min(u, v), max(u, v)): k for k, (u, v) in enumerate(pairs)}
    faces_per_edge = Counter()
    for face in faces:
        for u, v in _sides(face):
            key = (min(u, v), max(u, v))
            faces_per_edge[key] += 1
            if key not in index:
                index[key] = len(pairs)
                pairs.append((u, v))
    given = 0 if assignments is None else len(assignments)
    letters = tuple(assignments or ()) + tuple(
        "B" if faces_per_edge[(min(u, v), max(u, v))] == 1 else "U" for u, v in pairs[given:])
    fold = np.full(len(pairs), np.nan)
    if angles is not None:
        fold[:len(angles)] = angles
    return np.array(pairs, dtype=np.int64).reshape(-1, 2), letters, fold


def _accepting(ratio: float) -> str:
    """A tolerance, written with 2 significant digits, at least ``ratio``: what accepts a
    panel whose worst corner lies ``ratio`` of its diameter off its plane."""
    exponent = np.floor(np.log10(ratio)) - 1
    return f"{np.ceil(ratio / 10.0**exponent * (1 + 1e-12)) * 10.0**exponent:.2g}"


def check_panels(vertices: np.ndarray, faces, planarity_tolerance,
                 fail: Callable[[int, str], Exception], *, first: int = 0) -> None:
    """Raise ``fail(face, message)`` for the first degenerate or non-planar panel.

    A panel is degenerate if two consecutive corners coincide (closer than 1e-12 of its
    diameter) or its area is below :data:`DEGENERATE_AREA` times its squared diameter. It
    is not planar if a corner lies farther than ``planarity_tolerance`` times its diameter
    from its best-fit plane (least squares, by SVD); ``None`` skips that check. The first
    bad face in file order is reported; ``first`` is the number the file gives its first
    vertex (1 for OBJ), for the message.
    """
    if planarity_tolerance is not None:
        planarity_tolerance = as_positive_real("planarity_tolerance", planarity_tolerance)
    problems = {}
    by_size = {}
    for index, face in enumerate(faces):
        by_size.setdefault(len(face), []).append(index)
    for size, indices in by_size.items():
        corners = vertices[np.array([faces[i] for i in indices])]          # (F, k, 3)
        centred = corners - corners.mean(axis=1, keepdims=True)
        spans = corners[:, :, None, :] - corners[:, None, :, :]
        diameter = np.sqrt((spans ** 2).sum(axis=-1).max(axis=(1, 2)))     # (F,)
        sides = np.linalg.norm(np.roll(corners, -1, axis=1) - corners, axis=-1)
        area = 0.5 * np.linalg.norm(
            np.cross(centred, np.roll(centred, -1, axis=1)).sum(axis=1), axis=-1)
        # Python only for the panels flagged (the rest, nearly always all, in bulk).
        flagged = np.flatnonzero((diameter == 0.0)
                                 | (sides <= 1e-12 * diameter[:, None]).any(axis=1)
                                 | (area < DEGENERATE_AREA * diameter ** 2))
        for row in flagged.tolist():
            index = indices[row]
            face = faces[index]
            if diameter[row] == 0.0:
                problems[index] = f"face {index} is degenerate: all its corners coincide"
                continue
            short = np.flatnonzero(sides[row] <= 1e-12 * diameter[row])
            if short.size:
                k = int(short[0])
                problems[index] = (f"face {index} is degenerate: its corners at vertices "
                                   f"{face[k] + first} and {face[(k + 1) % size] + first} "
                                   "coincide")
            elif area[row] < DEGENERATE_AREA * diameter[row] ** 2:
                problems[index] = (f"face {index} is degenerate: its area {area[row]:.3g} mm^2 "
                                   f"is below {DEGENERATE_AREA:g} of its squared diameter "
                                   f"({diameter[row]:.3g} mm)^2")
        if planarity_tolerance is None or size == 3:
            continue
        _, _, vt = np.linalg.svd(centred)
        distance = np.abs(np.einsum("fkj,fj->fk", centred, vt[:, -1, :]))   # (F, k)
        worst = distance.argmax(axis=1)
        for row, index in enumerate(indices):
            off = distance[row, worst[row]]
            if index not in problems and off > planarity_tolerance * diameter[row]:
                problems[index] = (f"face {index} is not planar: its corner at vertex "
                                   f"{faces[index][worst[row]] + first} lies {off:.3g} mm off "
                                   f"its plane (tolerance {planarity_tolerance:g} of its "
                                   f"{diameter[row]:.3g} mm size; a larger planarity_tolerance "
                                   f"accepts it: planarity_tolerance = "
                                   f"{_accepting(off / diameter[row])})")
    if problems:
        index = min(problems)
        raise fail(index, problems[index])
