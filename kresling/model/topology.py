"""From panels to triangles, bars and hinges (docs/model.md, 'Topology')."""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from kresling import _core
from kresling._validation import as_bool, as_choice, as_index_lists, as_points

_SPLITS = {"N4B5": 0, "N5B8": 1}


@dataclass(frozen=True)
class Topology:
    """The elements a set of panels produces.

    Attributes
    ----------
    nodes : ndarray, shape (N, 3)
        The input nodes, followed by the centre nodes N5B8 adds [mm].
    triangles : ndarray of int, shape (T, 3)
        In canonical order (each row ascending, rows ascending), as MERLIN2 orders them.
    triangle_panel : ndarray of int, shape (T,)
        The panel each triangle came from.
    bars : ndarray of int, shape (B, 2)
        End nodes of every bar.
    hinges : ndarray of int, shape (H, 4)
        ``(a, b, c, d)``: axis ``a -> b`` (``a < b``), wing ``c`` in the lower-numbered triangle.
    hinge_is_bend : ndarray of bool, shape (H,)
        True for an edge added inside a panel (a bend hinge), False for a fold between panels.
    """

    nodes: np.ndarray
    triangles: np.ndarray
    triangle_panel: np.ndarray
    bars: np.ndarray
    hinges: np.ndarray
    hinge_is_bend: np.ndarray

    @classmethod
    def _from_core(cls, core) -> "Topology":
        """Read the C++ core's topology (``kresling._core.model.Topology``): every field of
        this class is one of its properties."""
        return cls(**{f.name: np.asarray(getattr(core, f.name)) for f in fields(cls)})


def panel_topology(nodes, panels, *, split="N4B5", duplicate_shared_edges=True) -> Topology:
    """Split panels into triangles and put a bar and a hinge on every shared edge.

    Parameters
    ----------
    nodes : array_like, shape (N, 3)
        Node coordinates [mm].
    panels : sequence of sequence of int
        Node indices around each panel (0-based, at least 3 each).
    split : {"N4B5", "N5B8"}
        How quads and larger panels become triangles: the shortest diagonal, recursively
        (N4B5), or a fan around a new centre node (N5B8). Triangles are never split.
    duplicate_shared_edges : bool, default True
        MERLIN2's rule: one bar and one hinge for *every pair* of triangles sharing an edge,
        so an edge in k triangles carries k(k-1)/2 of each (needed to reproduce its numbers).
        False: one bar per edge, and on an edge of k > 2 triangles hinges only between
        angularly neighbouring triangles (not across the widest opening).

    Returns
    -------
    Topology
    """
    as_choice("split", split, _SPLITS)
    nodes = as_points("nodes", nodes)
    panels = as_index_lists("panels", panels)
    t = _core.model.build_topology(nodes, panels, _SPLITS[split],
                                   as_bool("duplicate_shared_edges", duplicate_shared_edges))
    return Topology._from_core(t)
