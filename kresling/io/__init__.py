"""File formats of crease patterns and their folded configurations: FOLD, OBJ, STL.

The bottom layer of the package: numpy and the standard library only.

- :class:`Pattern` is what a file holds: vertices [mm] of shape (N, 3), panels (faces, 0-based
  vertex indices), edges with a FOLD assignment (``M``, ``V``, ``F``, ``B``, ``C``, ``U``,
  ``J``) and fold angle [degrees] each, further configurations (frames) of the vertices;
  :func:`pattern_from_arrays` builds one from arrays; :func:`miura_sheet` generates a
  folded Miura-ori sheet of any size.
- :func:`read_pattern` reads ``.fold`` (:func:`read_fold`) or ``.obj`` (:func:`read_obj`)
  files; :func:`write_fold`, :func:`write_obj` and :func:`write_stl` write them.

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

from kresling.io.errors import PatternFileError
from kresling.io.fold_format import (ASSIGNMENTS, fold_angles, fold_document, pattern_from_fold,
                                     read_fold, write_fold, write_fold_document)
from kresling.io.miura import miura_sheet
from kresling.io.obj_format import read_obj, write_obj
from kresling.io.pattern import Pattern, pattern_from_arrays
from kresling.io.stl_format import fan_triangles, write_stl

__all__ = [
    "Pattern", "pattern_from_arrays", "PatternFileError", "ASSIGNMENTS",
    "READERS", "read_pattern", "read_fold", "read_obj", "pattern_from_fold",
    "write_fold", "write_obj", "write_stl",
    "fold_document", "write_fold_document", "fold_angles", "fan_triangles", "miura_sheet",
]

#: File extensions :func:`read_pattern` reads, and the reader of each.
READERS = {".fold": read_fold, ".obj": read_obj}


def read_pattern(path, *, planarity_tolerance=1e-3) -> Pattern:
    """Read a crease pattern; the format comes from the file's extension (any case).

    Parameters
    ----------
    path : str or Path
        A ``.fold`` (:func:`read_fold`) or ``.obj`` (:func:`read_obj`) file.
    planarity_tolerance : float or None, default 1e-3
        Largest distance of a panel's corner from its best-fit plane, as a fraction of the
        panel's diameter; ``None`` skips the check.

    Returns
    -------
    Pattern

    Raises
    ------
    ValueError
        An extension other than ``.fold`` or ``.obj``, or bad content (naming the file and
        the element).
    OSError
        If the file cannot be read.
    """
    suffix = Path(path).suffix.lower()
    if suffix not in READERS:
        raise ValueError(f"file extension {Path(path).suffix!r} of {str(path)!r} is invalid: "
                         f"must be one of {sorted(READERS)} (STL is written only: it has "
                         "triangles, not panels)")
    return READERS[suffix](path, planarity_tolerance=planarity_tolerance)
