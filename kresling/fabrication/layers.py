"""A cut file as data: paths grouped into cut passes (layers), in mm, before any file format.

The writers (:mod:`~kresling.fabrication.svg`, :mod:`~kresling.fabrication.dxf`) turn a
:class:`CutSheet` into a file; the processes (:mod:`~kresling.fabrication.processes`) make
one from a crease pattern.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from kresling.fabrication._checks import cut_path_count, sheet_size
from kresling.fabrication.planar import mirror_x

__all__ = ["CutPath", "CutLayer", "CutSheet"]


@dataclass(frozen=True, eq=False)
class CutPath:
    """One continuous tool path.

    Attributes
    ----------
    points : ndarray, shape (k, 2)
        Corners [mm], y up.
    closed : bool
        Whether the last corner joins the first.
    role : str
        What the path is, e.g. ``"outline"``, ``"valley gap"``, ``"perforation"``.
    """

    points: np.ndarray
    closed: bool
    role: str

    def length(self) -> float:
        """Length of the path [mm]."""
        points = np.vstack([self.points, self.points[:1]]) if self.closed else self.points
        return float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())


@dataclass(frozen=True)
class CutLayer:
    """One cut pass: the paths a cutter runs with one tool setting, in order.

    Attributes
    ----------
    key : str
        Short identifier, used as the DXF layer name and in the SVG layer's id.
    name : str
        Label shown in Inkscape / Illustrator.
    colour : str
        Stroke colour ``"#rrggbb"``; distinct per layer.
    paths : tuple of CutPath
    description : str
        How to run the pass (blade depth, what to remove afterwards).
    """

    key: str
    name: str
    colour: str
    paths: tuple
    description: str = ""

    def count(self, role: str | None = None) -> int:
        """Number of paths (of one role, if given)."""
        return sum(1 for path in self.paths if role is None or path.role == role)


@dataclass(frozen=True)
class CutSheet:
    """Everything cut from one sheet: the layers in cutting order and the pieces they free.

    Attributes
    ----------
    title : str
    layers : tuple of CutLayer
    pieces : tuple of (str, ndarray)
        Name and outline polygon (shape (k, 2), mm) of every part that comes out.
    notes : tuple of str
        What the user must know to use the file (which side is drawn, what goes where).
    """

    title: str
    layers: tuple
    pieces: tuple = ()
    notes: tuple = field(default=())

    def __post_init__(self):
        count = sum(len(layer.paths) for layer in self.layers)
        cut_path_count(count, "cut a smaller design (fewer or shorter creases)")
        if count:
            sheet_size(f"the cut sheet {self.title!r}", *self.size)

    def bounds(self) -> np.ndarray:
        """``[[xmin, ymin], [xmax, ymax]]`` of every path [mm], shape (2, 2)."""
        points = np.vstack([path.points for layer in self.layers for path in layer.paths])
        return np.array([points.min(axis=0), points.max(axis=0)])

    @property
    def size(self) -> tuple:
        """``(width, height)`` of the bounding box of the paths [mm]."""
        (x0, y0), (x1, y1) = self.bounds()
        return float(x1 - x0), float(y1 - y0)

    def layer(self, key: str) -> CutLayer:
        """The layer with this key."""
        for layer in self.layers:
            if layer.key == key:
                return layer
        raise ValueError(f"layer = {key!r} is invalid: must be one of "
                         f"{[layer.key for layer in self.layers]}")

    def mapped(self, function) -> "CutSheet":
        """The sheet with ``function`` (``(k, 2)`` array -> ``(k, 2)`` array) applied to every
        path and piece."""
        layers = tuple(
            replace(layer, paths=tuple(replace(p, points=function(p.points)) for p in layer.paths))
            for layer in self.layers)
        pieces = tuple((name, function(polygon)) for name, polygon in self.pieces)
        return replace(self, layers=layers, pieces=pieces)

    def translated(self, offset) -> "CutSheet":
        """The sheet moved by ``offset`` (shape (2,), mm)."""
        return self.mapped(lambda points: points + np.asarray(offset, dtype=float))

    def mirrored(self) -> "CutSheet":
        """The mirror image in the vertical line through the middle of the sheet."""
        (x0, _), (x1, _) = self.bounds()
        return self.mapped(lambda points: mirror_x(points, 0.5 * (x0 + x1)))
