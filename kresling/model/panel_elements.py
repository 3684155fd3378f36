"""The bars and hinges of a crease pattern's panels, built by MERLIN2's rules (C++ core).

See docs/model.md, 'Topology'. Unlike :func:`kresling.model.panel_topology` (the Kresling
specimen's builder), this follows MERLIN2 v1.1 element for element and in its order, so a
model built here can be compared with one MERLIN2 built.

>>> import numpy as np
>>> square = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
>>> e = build_panel_elements(square, [[0, 1, 2, 3]], split="N5B8")
>>> e.nodes[4].tolist(), len(e.bends), len(e.folds), len(e.bars)
([0.5, 0.5, 0.0], 4, 0, 8)
"""

from __future__ import annotations

import numpy as np

from kresling import _core
from kresling._validation import as_choice, as_index_lists, as_points

__all__ = ["PanelElements", "build_panel_elements", "SPLITS"]

#: How panels with more than three vertices become triangles.
SPLITS = {"N4B5": 0, "N5B8": 1}
#: Where N5B8 puts a panel's centre node.
CENTRES = {"merlin2": 0, "mean": 1}


class PanelElements:
    """Bars and hinges of a set of panels (read-only arrays, 0-based node indices).

    Attributes
    ----------
    nodes : ndarray, shape (N + C, 3)
        The pattern's N vertices, then one centre node per split panel (N5B8) [mm].
    panels : tuple of tuple of int
        The panels as given.
    panel_centre : ndarray of int, shape (P,)
        Each panel's centre node, -1 for none.
    triangles : ndarray of int, shape (T, 3)
        The panels' pieces: rows ascending, sorted, unique.
    bends : ndarray of int, shape (Nb, 4)
        Bend hinges ``(a, b, c, d)``: axis ``a -> b`` inside a panel, wings ``c``, ``d``.
    bend_panel : ndarray of int, shape (Nb,)
        The panel of each bend hinge.
    folds : ndarray of int, shape (F, 4)
        Fold hinges between two triangles of different panels, axis ascending.
    boundary : ndarray of int, shape (E, 2)
        Edges of one triangle only.
    bars : ndarray of int, shape (Nb + F + E, 2)
        Bars on the bend axes, fold axes and boundary edges, in that order.
    split : str
    """

    def __init__(self, core, panels, split):
        self._core = core
        self.panels = tuple(tuple(int(v) for v in p) for p in panels)
        self.split = split
        for name in ("nodes", "panel_centre", "triangles", "bends", "bend_panel", "folds",
                     "boundary", "bars"):
            array = np.asarray(getattr(core, name))
            array.flags.writeable = False
            setattr(self, name, array)

    @property
    def num_vertices(self) -> int:
        """Vertices of the pattern (the nodes before any centre node)."""
        return int(len(self.nodes) - np.count_nonzero(self.panel_centre >= 0))

    def __repr__(self):
        return (f"PanelElements({self.split}: {len(self.nodes)} nodes, {len(self.bars)} bars, "
                f"{len(self.folds)} folds, {len(self.bends)} bends)")


def build_panel_elements(vertices, panels, *, split="N5B8", centre="merlin2") -> PanelElements:
    """Split panels into triangles and place bars, fold and bend hinges (MERLIN2's rules).

    Parameters
    ----------
    vertices : array_like, shape (N, 3)
        Vertex coordinates [mm].
    panels : sequence of sequence of int
        Vertex indices in order around each panel (0-based, at least 3 each).
    split : {"N5B8", "N4B5"}
        N5B8: a centre node in every panel of 4 or more vertices, with a spoke (bar and
        bend hinge) to each corner; a quad's centre where its diagonals cross (on the shorter
        one if it is warped), a larger panel's where the sum of its corners' triangle areas
        over the squared diagonals is least. N4B5: quads cut along the shorter diagonal,
        larger panels along their shortest diagonals recursively. Triangles stay whole.
        Any simple polygon is a panel: only diagonals inside the panel are cut along, and
        an N5B8 centre is used only where the panel is star-shaped from it (MERLIN2's,
        else the corners' mean); a panel star-shaped from neither is cut as N4B5 does,
        with no centre node (``panel_centre`` -1).
    centre : {"merlin2", "mean"}
        N5B8 centre nodes by MERLIN2's rules (above), or at the mean of the corners.

    Returns
    -------
    PanelElements

    Raises
    ------
    ValueError
        For an unknown split, or a panel with fewer than 3 vertices, an out-of-range or
        repeated vertex, sides that cross or touch (not a simple polygon), or no area; the
        message names the panel.
    """
    as_choice("split", split, SPLITS)
    as_choice("centre", centre, CENTRES)
    vertices = as_points("vertices", vertices)
    panels = as_index_lists("panels", panels)
    core = _core.model.build_panel_elements(vertices, panels, SPLITS[split], CENTRES[centre])
    return PanelElements(core, panels, split)
