"""A view of any crease pattern file (FOLD, OBJ): its panels and creases, and its frames
animated.

A FOLD file's key frame is frame ``"0"`` and ``file_frames[K - 1]`` frame ``"K"`` (FOLD's
own numbering: a frame's ``frame_parent`` 0 is the key frame), so the page of a
``kresling simulate`` run's ``path.fold`` opens at increment K with ``#frame=K``. A file
without frames is one state.

Creases are drawn by their FOLD assignment: ``M`` mountain, ``V`` valley, ``F`` flat, ``U``
unassigned, ``B`` boundary, ``C`` cut, ``J`` join (the colours of
:data:`kresling.view.FAMILY_STYLES`). Panels of more than three corners are split into fans
of triangles for shading.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from kresling.io import fan_triangles, read_pattern
from kresling.model.crease_kinds import FAMILY_OF_LETTER
from kresling.view.animation import select_rows
from kresling.view.figure import PathPanel, animated_figure, view_model
from kresling.view.inputs import view_inputs

__all__ = ["view_fold", "fold_frames", "ASSIGNMENT_FAMILIES"]

#: The crease family drawn for each FOLD assignment.
ASSIGNMENT_FAMILIES = FAMILY_OF_LETTER


@dataclass(frozen=True)
class _Sheet:
    """What a view draws of a pattern: its vertices as nodes and every edge as a line (a
    "hinge" whose axis is the edge); no mechanics."""

    nodes: np.ndarray
    hinges: np.ndarray
    bars: np.ndarray


def _pattern(pattern):
    if isinstance(pattern, (str, Path)):
        return read_pattern(pattern, planarity_tolerance=None)
    if not all(hasattr(pattern, key) for key in ("vertices", "faces", "edges",
                                                 "edges_assignment", "frames")):
        raise ValueError(f"pattern = {type(pattern).__name__} is invalid: must be a "
                         "kresling.io.Pattern or the path of a .fold or .obj file")
    return pattern


def fold_frames(pattern) -> list:
    """The frame numbers a pattern's view has: ``[0]`` (the key frame) and ``1..F`` for its
    F frames."""
    return list(range(len(_pattern(pattern).frames) + 1))


def view_fold(pattern, *, max_frames=200, title=None):
    """A crease pattern file's panels and creases, its frames animated.

    Parameters
    ----------
    pattern : kresling.io.Pattern, str or os.PathLike
        A pattern, or a ``.fold`` or ``.obj`` file (read without the panels' planarity
        check: a folded state need not have flat panels).
    max_frames : int, default 200
        At most this many frames (evenly spaced, the key frame and the last included).
    title : str, optional
        Default: the file's folder and name, its size and its number of frames.

    Returns
    -------
    plotly.graph_objects.Figure
        With frames ``"0"`` (the key frame) to ``"F"`` and a slider ("frame K / F") when the
        file has F >= 1 frames; else the one state, without frames.

    Raises
    ------
    ValueError
        For a file that cannot be read as a pattern (the message names the file and the
        element), or another kind of object.

    Examples
    --------
    >>> from kresling.io import pattern_from_arrays
    >>> square = pattern_from_arrays([[0, 0], [10, 0], [10, 10], [0, 10]], [[0, 1, 2, 3]])
    >>> fig = view_fold(square)
    >>> [t.name for t in fig.data], len(fig.frames)
    (['panels', 'boundary', 'extent'], 0)
    """
    pattern = _pattern(pattern)
    vertices = np.asarray(pattern.vertices, dtype=float)
    edges = np.asarray(pattern.edges, dtype=np.int64).reshape(-1, 2)
    sheet = _Sheet(nodes=vertices, hinges=np.column_stack([edges, edges]), bars=edges)
    families = [ASSIGNMENT_FAMILIES.get(a, a) for a in pattern.edges_assignment]
    inputs = view_inputs(sheet, triangles=fan_triangles(pattern.faces), hinge_family=families)
    # The folder too: a simulation's path.fold is named by the folder it was written to.
    source = Path(pattern.source) if pattern.source else None
    name = "crease pattern" if source is None else \
        f"{source.parent.name}/{source.name}" if source.parent.name else source.name
    size = f"{len(vertices)} vertices, {len(pattern.faces)} panels, {len(edges)} edges"
    frames = pattern.frames
    if not frames:
        return view_model(inputs.model, triangles=inputs.triangles,
                          hinge_family=inputs.hinge_family, title=title or f"{name}: {size}")
    displacement = np.array([np.zeros_like(vertices)] + [np.asarray(f, dtype=float) - vertices
                                                          for f in frames])
    displacement = displacement.reshape(len(displacement), -1)
    rows = select_rows(len(displacement), None, max_frames)
    default = f"{name}: {size}, key frame and {len(frames)} frame{'s' * (len(frames) > 1)}"
    return animated_figure([PathPanel(inputs, displacement)], rows, [str(r) for r in rows],
                           title=title or default, total=len(frames), prefix="frame ")
