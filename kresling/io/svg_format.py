"""SVG crease patterns, drawn with Origami Simulator's conventions, read as a planar pattern.

Origami Simulator (Ghassaei, Demaine, Gershenfeld 2018) reads a crease pattern from the
strokes of an SVG drawing: the stroke's colour is the crease's kind, its opacity the target
fold angle (opacity times stroke-opacity; 1 is 180 degrees):

==========  ===========  ==========================================================
stroke      assignment   meaning
==========  ===========  ==========================================================
black       ``B``        boundary
red         ``M``        mountain, fold angle ``-180 * opacity`` degrees
blue        ``V``        valley, fold angle ``+180 * opacity`` degrees
green       ``C``        cut
yellow      ``F``        facet crease: a triangulation edge, the panel stays flat
magenta     ``U``        undriven crease: a hinge that swings freely
==========  ===========  ==========================================================

``F`` and ``U`` keep Origami Simulator's meaning here (read such a pattern with the
``"origami_simulator"`` convention; :func:`as_fold_assignments` gives FOLD's letters).
``<line>``, ``<polyline>``, ``<polygon>``, ``<rect>`` and ``<path>`` of straight segments
are read, with their transforms; the strokes are snapped into a planar pattern (endpoints
merged, crossings and T-junctions split) whose faces are the regions they enclose.
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from kresling.io.errors import PatternFileError, file_error
from kresling.io.pattern import Pattern, check_panels, complete_edges
from kresling.io.planar_graph import planarize, simple_faces
from kresling.io.units import mm_per_unit

__all__ = ["STROKES", "SNAP_PIXELS", "SNAP_FRACTION", "read_svg", "as_fold_assignments"]

logger = logging.getLogger(__name__)

#: Origami Simulator's stroke colours (RGB) and the assignment of each.
STROKES = {(0, 0, 0): "B", (255, 0, 0): "M", (0, 0, 255): "V", (0, 255, 0): "C",
           (255, 255, 0): "F", (255, 0, 255): "U"}
#: A stroke colour within this distance (per RGB channel, of 255) of one of :data:`STROKES`
#: is that colour (editors write near-primaries such as #fe0000).
COLOUR_TOLERANCE = 32
#: Points of a drawing closer than this many of its user units (CSS pixels unless a viewBox
#: says otherwise) are one vertex, as Origami Simulator merges them: hand-drawn strokes
#: that should meet miss by a fraction of a pixel.
SNAP_PIXELS = 3.0
#: ... but never more than this fraction of the drawing's size (its bounding-box diagonal),
#: so that a drawing a few user units across is not merged into one point.
SNAP_FRACTION = 5e-3
#: Millimetres per CSS pixel (96 per inch): SVG user units after the root's viewBox.
MM_PER_PX = 25.4 / 96.0


def as_fold_assignments(pattern: Pattern) -> Pattern:
    """The pattern with Origami Simulator's letters in FOLD's: facet ``F`` becomes join
    ``J`` (faces acting as one); the other letters mean the same in both (an undriven ``U``
    is FOLD's unassigned crease)."""
    letters = tuple("J" if a == "F" else a for a in pattern.edges_assignment)
    return Pattern(pattern.vertices, pattern.faces, pattern.edges, letters,
                   pattern.edges_fold_angle, pattern.frames, pattern.source)


def read_svg(path, *, planarity_tolerance=1e-3, unit=None, scale=None,
             snap_tolerance=None) -> Pattern:
    """Read an SVG crease pattern (Origami Simulator's conventions, see the module).

    Parameters
    ----------
    path : str or Path
    planarity_tolerance : float or None, default 1e-3
        As :func:`~kresling.io.read_fold` (the faces of a drawing are flat).
    unit : str, optional
        The unit of one SVG user unit (CSS pixel after the root's viewBox), one of
        :data:`~kresling.io.units.UNITS`; default: a CSS pixel, 1/96 in.
    scale : float, optional
        With ``unit="unit"``: mm per user unit.
    snap_tolerance : float, optional
        Points closer than this many user units of the drawing (before ``unit``) are one
        vertex; strokes are split where another's end lies within it. Default:
        :data:`SNAP_PIXELS`, or :data:`SNAP_FRACTION` of the drawing's size if less.

    Returns
    -------
    Pattern
        Vertices [mm] with ``y`` pointing up (the SVG's down) and ``z = 0``, so the
        drawing is seen from +z and faces are counter-clockwise; edges with the strokes'
        assignments (Origami Simulator's letters) and fold angles (degrees; NaN but for
        M, V (from the opacity) and F (0)).

    Notes
    -----
    A drawing is read as Origami Simulator reads it, and repaired where it would be
    ambiguous, with a warning that says what changed: a region inside the sheet (no side
    on its outline) bounded only by black (boundary) strokes is a hole, not a panel; a black
    stroke
    left between two panels becomes a facet crease ``F`` (the panels stay flat together); a
    stroke that has the same panel on both sides (it ends inside it) is dropped; a region
    whose outline touches itself at a corner is refused.

    Raises
    ------
    ValueError
        Naming the file: not SVG, a curved path segment (naming the element), no stroke of
        a crease colour, strokes that enclose no face, or a negative ``snap_tolerance``.
    """
    source = str(path)
    segments, letters, angles = _strokes(path, source)
    factor = MM_PER_PX if unit is None else mm_per_unit(unit, scale)
    segments = segments * factor
    segments[..., 1] *= -1.0                       # SVG's y points down
    with np.errstate(over="ignore", invalid="ignore"):
        size = float(np.linalg.norm(np.ptp(segments.reshape(-1, 2), axis=0)))
    if not np.isfinite(segments).all() or not np.isfinite(size):
        raise file_error(source, "a stroke has a coordinate that is not a finite number (after "
                                 "its transforms)")
    if size == 0.0:
        raise file_error(source, "the strokes have no extent: every point coincides")
    if snap_tolerance is None:
        snap_tolerance = min(SNAP_PIXELS, SNAP_FRACTION * size / factor)
    elif not (isinstance(snap_tolerance, (int, float)) and np.isfinite(snap_tolerance)
              and snap_tolerance > 0):
        raise ValueError(f"snap_tolerance = {snap_tolerance!r} is invalid: must be a number "
                         "> 0 (the drawing's user units)")
    points, edges, origin = planarize(segments, snap_tolerance * factor)
    faces, edges, origin = _panels(source, points, edges, origin, letters)
    if not faces:
        raise file_error(source, f"the {len(segments)} strokes enclose no face with points "
                                 f"closer than snap_tolerance = {snap_tolerance:.3g} px merged: "
                                 "a crease pattern needs a closed boundary (black strokes), "
                                 "and a tolerance below its panels' size")
    vertices = np.column_stack([points, np.zeros(len(points))])
    letters = _boundary_between_panels(
        source, faces, edges, [letters[k] for k in origin])
    edges, assignment, fold = complete_edges(
        faces, edges, tuple(letters), np.asarray(angles)[origin])
    check_panels(vertices, faces, planarity_tolerance,
                 lambda index, message: file_error(source, message))
    used = sorted({v for face in faces for v in face})
    keep = _edges_of_faces(faces, edges)
    renumber = {v: k for k, v in enumerate(used)}
    return Pattern(vertices[used], tuple(tuple(renumber[v] for v in f) for f in faces),
                   np.array([[renumber[u], renumber[v]] for u, v in edges[keep]],
                            dtype=np.int64).reshape(-1, 2),
                   tuple(assignment[k] for k in keep), fold[keep], (), source)


def _panels(source, points, edges, origin, letters):
    """The drawing's faces as panels (simple polygons, holes left out), and its edges and
    their strokes with the edges that bound nothing dropped; each repair logged."""
    faces, dropped = simple_faces(points, edges)
    if dropped:
        shown = ", ".join(str(tuple(edges[k])) for k in dropped[:5])
        logger.warning("%s: %d stroke piece(s) with the same panel on both sides dropped (they "
                       "end inside a panel): edges %s%s", source, len(dropped), shown,
                       " ..." if len(dropped) > 5 else "")
        keep = np.setdiff1d(np.arange(len(edges)), dropped)
        edges, origin = edges[keep], origin[keep]
    for face in faces:
        repeated = sorted({v for v in face if face.count(v) > 1})
        if repeated:
            raise file_error(source, f"a region's outline touches itself at vertex "
                                     f"{repeated[0]} ({points[repeated[0]].round(3).tolist()} "
                                     "mm): it is no simple polygon; draw a crease that "
                                     "splits it there, or move the strokes apart")
    if len(faces) > 1:
        # A hole: a region inside the sheet (every side shared with another region, none on
        # the drawing's outline) bounded only by black strokes.
        stroke = {(min(u, v), max(u, v)): letters[origin[k]]
                  for k, (u, v) in enumerate(edges.tolist())}
        shared = _regions_per_side(faces)
        holes = [f for f in faces
                 if all(stroke.get(key) == "B" and shared[key] == 2
                        for key in (tuple(sorted(side)) for side in _sides(f)))]
        if holes and len(holes) < len(faces):
            logger.warning("%s: %d region(s) bounded only by boundary (black) strokes taken as "
                           "holes, not panels", source, len(holes))
            faces = [f for f in faces if f not in holes]
    return tuple(tuple(face) for face in faces), edges, origin


def _sides(face):
    return zip(face, tuple(face[1:]) + tuple(face[:1]))


def _regions_per_side(faces) -> dict:
    """(u, v), u < v -> how many of the faces have that side."""
    count = {}
    for face in faces:
        for u, v in _sides(face):
            key = (min(u, v), max(u, v))
            count[key] = count.get(key, 0) + 1
    return count


def _boundary_between_panels(source, faces, edges, letters) -> list:
    """The edges' letters with every boundary (black) stroke between two panels made a
    facet crease F (a black stroke that misses the outline, or divides the sheet)."""
    count = _regions_per_side(faces)
    inner = [k for k, (u, v) in enumerate(edges.tolist())
             if letters[k] == "B" and count.get((min(u, v), max(u, v)), 0) == 2]
    if inner:
        logger.warning("%s: %d boundary (black) stroke piece(s) lie between two panels, made "
                       "facet creases F (the panels stay flat together): edges %s%s", source,
                       len(inner), ", ".join(str(tuple(edges[k])) for k in inner[:5]),
                       " ..." if len(inner) > 5 else "")
        letters = list(letters)
        for k in inner:
            letters[k] = "F"
    return letters


def _edges_of_faces(faces, edges) -> list:
    """Indices of the edges that are sides of faces (dangling strokes bound nothing)."""
    sides = {(min(u, v), max(u, v)) for face in faces
             for u, v in zip(face, face[1:] + face[:1])}
    return [k for k, (u, v) in enumerate(edges.tolist()) if (min(u, v), max(u, v)) in sides]


def _strokes(path, source):
    """Every straight stroke of a crease colour: segments (S, 2, 2) in user units, their
    letters and fold angles [degrees]."""
    # svgelements parses SVG paths, shapes, CSS colours and transforms; imported here so
    # that `import kresling` does not pay for it.
    import svgelements

    try:
        document = svgelements.SVG.parse(str(path), reify=True)
    except (ValueError, TypeError, OSError) as error:
        if isinstance(error, OSError) and not Path(path).is_file():
            raise
        raise file_error(source, f"not a valid SVG file: {error}") from None
    except Exception as error:  # the XML parser's errors (ParseError and others)
        raise file_error(source, f"not a valid SVG file: {error}") from None
    if not isinstance(document, svgelements.SVG):
        raise file_error(source, "not a valid SVG file: its root element is not <svg>")
    try:
        return _collect(document, source)
    except PatternFileError:
        raise
    except (ValueError, TypeError, AttributeError, IndexError, ZeroDivisionError,
            OverflowError) as error:  # svgelements' errors on values it cannot use
        raise file_error(source, f"not a valid SVG file: {error}") from None


def _collect(document, source):
    import svgelements

    segments, letters, angles, ignored = [], [], [], {}
    for element in document.elements():
        if not isinstance(element, svgelements.Shape) or element.stroke is None or \
                element.stroke.value is None:
            continue
        letter = _letter(element.stroke)
        if letter is None:
            ignored[element.stroke.hex] = ignored.get(element.stroke.hex, 0) + 1
            continue
        angle = _angle(element, letter)
        for start, end in _lines(element, source):
            segments.append((start, end))
            letters.append(letter)
            angles.append(angle)
    if ignored:
        logger.warning("%s: strokes of other colours ignored: %s", source,
                       ", ".join(f"{colour} ({count})" for colour, count in ignored.items()))
    if not segments:
        raise file_error(source, "has no stroke of a crease colour: boundary black, mountain "
                                 "red, valley blue, cut green, facet yellow, undriven "
                                 "magenta")
    return np.asarray(segments, dtype=float).reshape(-1, 2, 2), letters, angles


def _letter(colour):
    rgb = np.array([colour.red, colour.green, colour.blue])
    for primary, letter in STROKES.items():
        if np.abs(rgb - primary).max() <= COLOUR_TOLERANCE:
            return letter
    return None


def _angle(element, letter) -> float:
    """Origami Simulator's target fold angle: opacity times stroke-opacity, 1 = 180 deg."""
    if letter == "F":
        return 0.0
    if letter not in ("M", "V"):
        return float("nan")
    # Read from the attributes (and style), not from the colour: svgelements rounds the
    # stroke's alpha to 8 bits.
    opacity = _fraction(element.values.get("opacity")) * \
        _fraction(element.values.get("stroke-opacity"))
    return (-180.0 if letter == "M" else 180.0) * opacity


def _fraction(text) -> float:
    try:
        value = float(text)
    except (TypeError, ValueError):
        return 1.0
    return min(max(value, 0.0), 1.0) if np.isfinite(value) else 1.0


def _lines(element, source) -> list:
    """The straight segments of one shape (already transformed), as point pairs."""
    import svgelements

    shape = element if isinstance(element, svgelements.Path) else svgelements.Path(element)
    lines = []
    for segment in shape.segments():
        if isinstance(segment, svgelements.Move):
            continue
        if isinstance(segment, (svgelements.Line, svgelements.Close)):
            if segment.start is None or segment.end is None:
                continue
            start, end = (float(segment.start.x), float(segment.start.y)), \
                (float(segment.end.x), float(segment.end.y))
            if start != end:
                lines.append((start, end))
            continue
        name = element.id or f"<{type(element).__name__.lower()}>"
        raise file_error(source, f"element {name!r} has a {type(segment).__name__} segment: "
                                 "only straight segments are read (flatten curves into "
                                 "lines in your editor)")
    return lines
