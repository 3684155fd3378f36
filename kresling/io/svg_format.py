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
from kresling.io.planar_graph import faces_from_edges, planarize
from kresling.io.units import mm_per_unit

__all__ = ["STROKES", "SNAP_TOLERANCE", "read_svg", "as_fold_assignments"]

logger = logging.getLogger(__name__)

#: Origami Simulator's stroke colours (RGB) and the assignment of each.
STROKES = {(0, 0, 0): "B", (255, 0, 0): "M", (0, 0, 255): "V", (0, 255, 0): "C",
           (255, 255, 0): "F", (255, 0, 255): "U"}
#: A stroke colour within this distance (per RGB channel, of 255) of one of :data:`STROKES`
#: is that colour (editors write near-primaries such as #fe0000).
COLOUR_TOLERANCE = 32
#: Points closer than this fraction of the drawing's size (its bounding-box diagonal) are
#: one vertex.
SNAP_TOLERANCE = 1e-4
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
             snap_tolerance=SNAP_TOLERANCE) -> Pattern:
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
    snap_tolerance : float, default :data:`SNAP_TOLERANCE`
        Points closer than this fraction of the drawing's size are merged.

    Returns
    -------
    Pattern
        Vertices [mm] with ``y`` pointing up (the SVG's down) and ``z = 0``, so the
        drawing is seen from +z and faces are counter-clockwise; edges with the strokes'
        assignments (Origami Simulator's letters) and fold angles (degrees; NaN but for
        M, V (from the opacity) and F (0)).

    Raises
    ------
    ValueError
        Naming the file: not SVG, a curved path segment (naming the element), no stroke of
        a crease colour, or strokes that enclose no face.
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
    points, edges, origin = planarize(segments, snap_tolerance * size)
    faces = tuple(tuple(face) for face in faces_from_edges(points, edges))
    if not faces:
        raise file_error(source, f"the {len(segments)} strokes enclose no face: a crease "
                                 "pattern needs a closed boundary (black strokes)")
    vertices = np.column_stack([points, np.zeros(len(points))])
    edges, assignment, fold = complete_edges(
        faces, edges, tuple(letters[k] for k in origin), np.asarray(angles)[origin])
    check_panels(vertices, faces, planarity_tolerance,
                 lambda index, message: file_error(source, message))
    used = sorted({v for face in faces for v in face})
    keep = _edges_of_faces(faces, edges)
    renumber = {v: k for k, v in enumerate(used)}
    return Pattern(vertices[used], tuple(tuple(renumber[v] for v in f) for f in faces),
                   np.array([[renumber[u], renumber[v]] for u, v in edges[keep]],
                            dtype=np.int64).reshape(-1, 2),
                   tuple(assignment[k] for k in keep), fold[keep], (), source)


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
