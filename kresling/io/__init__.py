"""File formats of crease patterns and their folded configurations: FOLD, OBJ, SVG, STL.

The bottom layer of the package: numpy, and scipy's k-d tree and svgelements where needed.

- :class:`Pattern` is what a file holds: vertices [mm] of shape (N, 3), panels (faces, 0-based
  vertex indices), edges with a FOLD assignment (``M``, ``V``, ``F``, ``B``, ``C``, ``U``,
  ``J``) and fold angle [degrees] each, further configurations (frames) of the vertices;
  :func:`pattern_from_arrays` builds one from arrays; :func:`miura_sheet` generates a
  folded Miura-ori sheet of any size.
- :func:`read_pattern` reads ``.fold`` (:func:`read_fold`), ``.obj`` (:func:`read_obj`) or
  ``.svg`` (:func:`read_svg`, Origami Simulator's stroke colours) files, converting their
  lengths to mm (FOLD's ``frame_unit``, or a unit and scale given); :func:`write_fold`,
  :func:`write_obj` and :func:`write_stl` write them.
- :func:`separate_cuts` separates the faces along cut (``C``) edges, as FOLD 1.2 says.

Fold angles follow FOLD: degrees in [-180, 180], positive for a valley, negative for a
mountain. Readers check what they read and raise :class:`ValueError` (a
:class:`PatternFileError`) naming the file and the element: ``sheet.obj:12:9: face 3 has
vertex 40 out of range [1, 39]``, ``sheet.fold: key 'vertices_coords'[4] = [1, 'a'] is
invalid: must be 2 or 3 numbers``, ``sheet.fold: face 7 is not planar: ...``.

Examples
--------
>>> import numpy as np
>>> from kresling.io import pattern_from_arrays
>>> square = pattern_from_arrays([[0, 0], [10, 0], [10, 10], [0, 10]], [[0, 1, 2, 3]])
>>> square.num_vertices, square.num_faces, square.edges_assignment
(4, 1, ('B', 'B', 'B', 'B'))
"""

from __future__ import annotations

from pathlib import Path

from kresling.io.cuts import separate_cuts
from kresling.io.errors import PatternFileError
from kresling.io.fold_format import (ASSIGNMENTS, fold_angles, fold_document, pattern_from_fold,
                                     read_fold, write_fold, write_fold_document)
from kresling.io.miura import miura_sheet
from kresling.io.obj_format import read_obj, write_obj
from kresling.io.pattern import Pattern, pattern_from_arrays
from kresling.io.stl_format import fan_triangles, write_stl
from kresling.io.svg_format import as_fold_assignments, read_svg
from kresling.io.units import UNITS, mm_per_unit

__all__ = [
    "Pattern", "pattern_from_arrays", "PatternFileError", "ASSIGNMENTS", "UNITS",
    "READERS", "read_pattern", "read_fold", "read_obj", "read_svg", "pattern_from_fold",
    "write_fold", "write_obj", "write_stl", "separate_cuts", "as_fold_assignments",
    "fold_document", "write_fold_document", "fold_angles", "fan_triangles", "miura_sheet",
    "mm_per_unit", "scaled",
]

#: File extensions :func:`read_pattern` reads, and the reader of each.
READERS = {".fold": read_fold, ".obj": read_obj, ".svg": read_svg}


def scaled(pattern: Pattern, factor: float) -> Pattern:
    """The pattern with its coordinates (and frames) multiplied by ``factor``."""
    return Pattern(pattern.vertices * factor, pattern.faces, pattern.edges,
                   pattern.edges_assignment, pattern.edges_fold_angle,
                   tuple(frame * factor for frame in pattern.frames), pattern.source)


def read_pattern(path, *, planarity_tolerance=1e-3, unit=None, scale=None,
                 frame=0, snap_tolerance=None) -> Pattern:
    """Read a crease pattern; the format comes from the file's extension (any case).

    Parameters
    ----------
    path : str or Path
        A ``.fold`` (:func:`read_fold`), ``.obj`` (:func:`read_obj`) or ``.svg``
        (:func:`read_svg`) file.
    planarity_tolerance : float or None, default 1e-3
        Largest distance of a panel's corner from its best-fit plane, as a fraction of the
        panel's diameter; ``None`` skips the check.
    unit : str, optional
        The unit of the file's coordinates (one of :data:`UNITS`), replacing the file's
        own: FOLD's ``frame_unit`` (``"unit"``, taken as 1 mm, if it has none), mm for
        OBJ, CSS pixels (1/96 in) for SVG.
    scale : float, optional
        With ``unit="unit"`` (given, or a FOLD file's): mm per unit (default 1).
    frame : int, default 0
        FOLD only: the frame to read (0 is the key frame; see :func:`read_fold`).
    snap_tolerance : float, optional
        SVG only: points closer than this many of the drawing's user units are one vertex
        (see :func:`read_svg`).

    Returns
    -------
    Pattern
        Coordinates in mm.

    Raises
    ------
    ValueError
        An extension other than ``.fold``, ``.obj`` or ``.svg``, a bad unit or scale, a
        frame of a file that has none, or bad content (naming the file and the element).
    OSError
        If the file cannot be read.
    """
    suffix = Path(path).suffix.lower()
    if suffix not in READERS:
        raise ValueError(f"file extension {Path(path).suffix!r} of {str(path)!r} is invalid: "
                         f"must be one of {sorted(READERS)} (STL is written only: it has "
                         "triangles, not panels)")
    if snap_tolerance is not None and suffix != ".svg":
        raise ValueError(f"snap_tolerance = {snap_tolerance!r} is invalid for {str(path)!r}: "
                         "only SVG drawings are snapped (their strokes merged into vertices)")
    if suffix == ".fold":
        return read_fold(path, planarity_tolerance=planarity_tolerance, frame=frame,
                         unit=unit, scale=scale)
    if frame != 0:
        raise ValueError(f"frame = {frame!r} is invalid for {str(path)!r}: only FOLD files "
                         "have frames")
    if suffix == ".svg":
        return read_svg(path, planarity_tolerance=planarity_tolerance, unit=unit, scale=scale,
                        snap_tolerance=snap_tolerance)
    pattern = read_obj(path, planarity_tolerance=planarity_tolerance)
    factor = 1.0 if unit is None and scale is None else mm_per_unit(unit or "mm", scale)
    return pattern if factor == 1.0 else scaled(pattern, factor)
