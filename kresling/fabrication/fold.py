"""FOLD files of fabrication: the names the fabrication code has always used for FOLD.

The FOLD format itself (documents, fold angles, reading and writing patterns) lives in
:mod:`kresling.io.fold_format`; this module keeps the fabrication API on top of it:
:func:`write_fold` here writes a ready FOLD document (such as
:func:`~kresling.fabrication.pattern_fold_document`, the Kresling cell's crease pattern with
its two stable states), whereas :func:`kresling.io.write_fold` writes a
:class:`~kresling.io.Pattern` or arrays. Lengths are in mm and fold angles in degrees,
positive for valleys and negative for mountains, with faces counter-clockwise about +z: a
valley folds the faces towards +z.
"""

from __future__ import annotations

from pathlib import Path

from kresling.io.fold_format import ASSIGNMENTS, fold_angles, fold_document, write_fold_document

__all__ = ["ASSIGNMENTS", "fold_angles", "fold_document", "write_fold"]


def write_fold(path, document: dict) -> Path:
    """Write a FOLD document (see :func:`fold_document`) as JSON; returns the path.

    Raises
    ------
    ValueError
        If the document holds something JSON cannot (NaN, inf).
    """
    return write_fold_document(path, document)
