"""What a view is drawn from: a model, its triangles and its creases' families.

A view accepts a :class:`kresling.model.Model`, or an object that carries one as ``.model``
with its hinges' families as ``.hinge_family`` (a :class:`kresling.model.KreslingSpecimen`,
a crease pattern's model): from it the view takes the model, the families and the
triangles (a specimen's outward-oriented faces, else ``.elements.triangles`` if present).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from kresling.view.surface import orient_triangles, triangles_from_hinges

__all__ = ["ViewInputs", "view_inputs"]

#: Family of a hinge when none is given.
UNASSIGNED = "unassigned"


@dataclass(frozen=True)
class ViewInputs:
    """A model with the triangles and crease families a view draws.

    Attributes
    ----------
    model : kresling.model.Model
    triangles : ndarray of int, shape (T, 3)
        Panels (triangles) to shade; consistently oriented where the surface allows.
    hinge_family : ndarray of str, shape (H,)
        Family of every hinge (``"unassigned"`` when none was given).
    lines : dict
        Further lines drawn beside the creases, by name: ``{"member bar": edges (E, 2)}``,
        the bars given one by one of a structure that is not all panels (a linkage).
    """

    model: object
    triangles: np.ndarray
    hinge_family: np.ndarray
    lines: dict = field(default_factory=dict)


def view_inputs(model, *, triangles=None, hinge_family=None) -> ViewInputs:
    """Check and complete a view's inputs.

    Parameters
    ----------
    model : kresling.model.Model or an object with ``.model`` and ``.hinge_family``
        E.g. a :class:`kresling.model.KreslingSpecimen`.
    triangles : array_like of int, shape (T, 3), optional
        Node indices of the panels' triangles (e.g. ``Topology.triangles``). Default: a
        specimen's faces, else the carrier's ``.elements.triangles``, else the triangles the
        hinges join (each hinge ``(a, b, c, d)`` joins ``(a, b, c)`` and ``(a, b, d)``),
        de-duplicated and consistently oriented.
    hinge_family : sequence of str, shape (H,), optional
        Family of every hinge, e.g. ``"mountain"``, ``"valley"``, ``"flat"``, ``"bend"``,
        ``"cut"``, ``"boundary"`` (any other name gets a colour of its own). Default: a
        specimen's families, else ``"unassigned"``.

    Returns
    -------
    ViewInputs

    Raises
    ------
    ValueError
        For triangles of the wrong shape or with node indices out of range, or a family
        list of the wrong length.
    """
    carrier = model if hasattr(model, "model") and hasattr(model, "hinge_family") else None
    if carrier is not None:
        model = carrier.model
        if hinge_family is None:
            hinge_family = carrier.hinge_family
        if triangles is None and hasattr(carrier, "centre") and hasattr(carrier, "design"):
            from kresling.analyses.specimen_views import specimen_faces

            triangles = specimen_faces(carrier)   # a Kresling specimen, faces outward
        elif triangles is None and hasattr(getattr(carrier, "elements", None), "triangles"):
            triangles = orient_triangles(carrier.elements.triangles, model.nodes)
    if not (hasattr(model, "nodes") and hasattr(model, "hinges") and hasattr(model, "bars")):
        raise ValueError(f"model = {type(model).__name__} is invalid: must be a "
                         "kresling.model.Model or an object with .model and .hinge_family "
                         "(e.g. a KreslingSpecimen)")
    num_nodes, num_hinges = len(model.nodes), len(model.hinges)
    if triangles is None:
        triangles = orient_triangles(triangles_from_hinges(model.hinges), model.nodes)
    else:
        triangles = np.asarray(triangles)
        if triangles.size == 0:
            triangles = np.zeros((0, 3), dtype=np.int64)
        if triangles.ndim != 2 or triangles.shape[1] != 3 or not np.issubdtype(
                triangles.dtype, np.integer):
            raise ValueError(f"triangles has shape {triangles.shape} and dtype "
                             f"{triangles.dtype}: must be integers of shape (T, 3)")
        triangles = triangles.astype(np.int64)
        if triangles.size and (triangles.min() < 0 or triangles.max() >= num_nodes):
            row = int(np.argwhere((triangles < 0) | (triangles >= num_nodes))[0, 0])
            raise ValueError(f"triangles[{row}] = {triangles[row].tolist()}: node index out "
                             f"of range [0, {num_nodes})")
    if hinge_family is None:
        hinge_family = np.full(num_hinges, UNASSIGNED, dtype=object)
    else:
        hinge_family = np.array([str(f) for f in np.asarray(hinge_family, dtype=object).ravel()],
                                dtype=object)
        if len(hinge_family) != num_hinges:
            raise ValueError(f"hinge_family has {len(hinge_family)} entries: must have one "
                             f"per hinge ({num_hinges})")
    lines = {}
    bar_family = getattr(carrier, "bar_family", None) if carrier is not None else None
    if bar_family is not None and len(bar_family) == len(model.bars):
        member = np.array([f == "member" for f in bar_family], dtype=bool)
        if member.any():
            lines["member bar"] = np.asarray(model.bars, dtype=np.int64)[member]
    return ViewInputs(model=model, triangles=triangles, hinge_family=hinge_family,
                      lines=lines)
