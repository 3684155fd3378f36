"""The folded surface: shaded panels (triangles) and creases drawn as lines by family.

Coordinates go into the figure rounded to :data:`DECIMALS` decimals of a millimetre
(1e-10 mm): a page's frames then give the path's node positions to 1e-10 mm, and the
numbers stay as short as that allows (a node that does not move, or a round coordinate,
takes a few characters). The lines of a family are drawn as few polylines as its edges
allow (:func:`polyline_order`), so each node is written about once per family, not once per
edge end.
"""

from __future__ import annotations

from collections import deque

import numpy as np

__all__ = ["DECIMALS", "FAMILY_STYLES", "PANEL_COLOUR", "MESH_LIGHTING",
           "triangles_from_hinges", "orient_triangles",
           "crease_groups", "boundary_edges", "rounded", "segments_xyz", "polyline_order",
           "polyline_xyz", "mesh_trace", "line_trace", "family_style"]

#: Decimals kept of every coordinate in the figure [mm]: 10, i.e. 1e-10 mm.
DECIMALS = 10

#: Line style of each crease family: (colour, width [px], dash). A family not listed here
#: gets a colour of its own from :data:`OTHER_COLOURS`.
FAMILY_STYLES = {
    "mountain": ("#d62728", 5, "solid"),
    "valley": ("#1f77b4", 5, "solid"),
    "flat": ("#8c8c8c", 3, "solid"),
    "unassigned": ("#8c8c8c", 3, "solid"),
    "bend": ("#c7c7c7", 2, "dash"),
    "cut": ("#000000", 5, "solid"),
    "boundary": ("#3b3b3b", 4, "solid"),
    # Thin and light: a FOLD file of a simulation marks every edge inside a panel "J", and on
    # a large sheet those would swamp the mountain and valley creases.
    "join": ("#a6dde6", 1.5, "solid"),
    # The families of a Kresling specimen's elements (kresling.model.EDGE_FAMILIES).
    "polygon_edge": ("#6a3d9a", 4, "solid"),
    "polygon_spoke": ("#c7c7c7", 2, "dash"),
    # Members given one by one (a linkage's): the hinges' axes bold, the bars thin.
    "member": ("#ff7f0e", 6, "solid"),
    "member bar": ("#5a5a5a", 2, "solid"),
}
OTHER_COLOURS = ("#ff7f0e", "#2ca02c", "#8c564b", "#e377c2", "#17becf", "#bcbd22")

#: Colour of the panels.
PANEL_COLOUR = "#e9dcc0"
#: How the panels are lit (plotly's Mesh3d ``lighting``).
MESH_LIGHTING = dict(ambient=0.55, diffuse=0.7, specular=0.05, roughness=0.9, fresnel=0.05)


def family_style(family: str, others: list) -> tuple:
    """(colour, width, dash) of a family; ``others`` lists the unlisted families seen so far."""
    if family in FAMILY_STYLES:
        return FAMILY_STYLES[family]
    if family not in others:
        others.append(family)
    return OTHER_COLOURS[others.index(family) % len(OTHER_COLOURS)], 4, "solid"


def triangles_from_hinges(hinges) -> np.ndarray:
    """The triangles the hinges join: ``(a, b, c)`` and ``(a, b, d)`` of every hinge.

    Parameters
    ----------
    hinges : array_like of int, shape (H, 4)

    Returns
    -------
    ndarray of int, shape (T, 3)
        De-duplicated, each row ascending, rows ascending.
    """
    hinges = np.asarray(hinges, dtype=np.int64).reshape(-1, 4)
    if not len(hinges):
        return np.zeros((0, 3), dtype=np.int64)
    both = np.vstack([hinges[:, [0, 1, 2]], hinges[:, [0, 1, 3]]])
    return np.unique(np.sort(both, axis=1), axis=0)


def orient_triangles(triangles, nodes=None) -> np.ndarray:
    """Orient triangles consistently across the edges two of them share.

    Each connected patch keeps its first triangle's orientation and is turned so that
    neighbours run their shared edge in opposite directions (the rule of an orientable
    surface, which gives the panels one lit side). Edges of three or more triangles do not
    propagate orientation. With ``nodes``, a patch is flipped if its normals point, on
    average, towards ``-z`` (so a flat sheet faces up).

    Parameters
    ----------
    triangles : array_like of int, shape (T, 3)
    nodes : array_like, shape (N, 3), optional
        Node coordinates [mm].

    Returns
    -------
    ndarray of int, shape (T, 3)
    """
    tri = np.array(triangles, dtype=np.int64).reshape(-1, 3)
    by_edge = {}
    for t, (a, b, c) in enumerate(tri.tolist()):
        for u, v in ((a, b), (b, c), (c, a)):
            by_edge.setdefault((min(u, v), max(u, v)), []).append(t)
    neighbours = [[] for _ in range(len(tri))]
    for (u, v), ts in by_edge.items():
        if len(ts) == 2:
            neighbours[ts[0]].append((ts[1], u, v))
            neighbours[ts[1]].append((ts[0], u, v))

    def runs(t, u, v):  # +1 if triangle t runs u -> v, -1 if v -> u
        a, b, c = tri[t]
        return 1 if (u, v) in ((a, b), (b, c), (c, a)) else -1

    seen = np.zeros(len(tri), dtype=bool)
    for start in range(len(tri)):
        if seen[start]:
            continue
        seen[start] = True
        patch, queue = [start], deque([start])
        while queue:
            t = queue.popleft()
            for s, u, v in neighbours[t]:
                if not seen[s]:
                    if runs(s, u, v) == runs(t, u, v):
                        tri[s] = tri[s][[0, 2, 1]]
                    seen[s] = True
                    patch.append(s)
                    queue.append(s)
        if nodes is not None:
            x = np.asarray(nodes, dtype=float)
            p = tri[patch]
            normal = np.cross(x[p[:, 1]] - x[p[:, 0]], x[p[:, 2]] - x[p[:, 0]]).sum(axis=0)
            if normal[2] < -1e-12 * max(1.0, np.abs(normal).max()):
                tri[patch] = tri[patch][:, [0, 2, 1]]
    return tri


def _unique_edges(pairs):
    """Sorted, de-duplicated edges and, per row of ``pairs``, its edge's index."""
    pairs = np.sort(np.asarray(pairs, dtype=np.int64).reshape(-1, 2), axis=1)
    if not len(pairs):
        return np.zeros((0, 2), dtype=np.int64), np.zeros(0, dtype=np.int64)
    edges, inverse = np.unique(pairs, axis=0, return_inverse=True)
    return edges, inverse.ravel()


def boundary_edges(triangles, hinges) -> np.ndarray:
    """Edges of exactly one triangle that carry no hinge, shape (E, 2)."""
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    if not len(triangles):
        return np.zeros((0, 2), dtype=np.int64)
    pairs = np.sort(np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]],
                               triangles[:, [2, 0]]]), axis=1)
    edges, counts = np.unique(pairs, axis=0, return_counts=True)
    edges = edges[counts == 1]
    axes = {tuple(e) for e in np.sort(np.asarray(hinges).reshape(-1, 4)[:, :2], axis=1).tolist()}
    keep = [tuple(e) not in axes for e in edges.tolist()]
    return edges[np.asarray(keep, dtype=bool)] if len(edges) else edges


def crease_groups(hinges, hinge_family, triangles) -> dict:
    """Crease lines by family: every hinge axis once, and the surface's boundary.

    An edge carrying several hinges (an edge of three or more triangles) is drawn once, in
    the family of its first hinge.

    Parameters
    ----------
    hinges : array_like of int, shape (H, 4)
    hinge_family : sequence of str, shape (H,)
    triangles : array_like of int, shape (T, 3)

    Returns
    -------
    dict
        ``family -> edges`` (ndarray of int, shape (E, 2)), families in order of first
        appearance, ``"boundary"`` last.
    """
    hinges = np.asarray(hinges, dtype=np.int64).reshape(-1, 4)
    edges, inverse = _unique_edges(hinges[:, :2])
    first = np.full(len(edges), len(hinges), dtype=np.int64)
    np.minimum.at(first, inverse, np.arange(len(hinges)))
    families = [str(hinge_family[i]) for i in first]
    groups = {}
    for family in dict.fromkeys(str(hinge_family[i]) for i in np.sort(first)):
        groups[family] = edges[np.array([f == family for f in families], dtype=bool)]
    boundary = boundary_edges(triangles, hinges)
    if len(boundary):
        groups["boundary"] = np.vstack([groups["boundary"], boundary]) \
            if "boundary" in groups else boundary
        groups["boundary"] = groups.pop("boundary")
    return groups


def rounded(values, decimals: int = DECIMALS) -> list:
    """``values`` rounded to ``decimals`` as a list of Python floats (NaN -> None).

    Lists (not arrays) make plotly write decimal numbers, which the rounding keeps short.
    """
    values = np.round(np.asarray(values, dtype=float), decimals) + 0.0  # no "-0.0"
    out = values.tolist()
    if np.isnan(values).any():
        out = [None if v != v else v for v in out]
    return out


def segments_xyz(points, edges) -> tuple:
    """x, y and z of line segments as plotly draws them: ``p, q, gap`` per edge.

    Parameters
    ----------
    points : ndarray, shape (N, 3)
        Node coordinates [mm].
    edges : ndarray of int, shape (E, 2)

    Returns
    -------
    (list, list, list)
        Each of length 3E, rounded to :data:`DECIMALS`, ``None`` at every third entry.
    """
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    xyz = np.full((len(edges), 3, 3), np.nan)
    xyz[:, 0] = points[edges[:, 0]]
    xyz[:, 1] = points[edges[:, 1]]
    flat = xyz.reshape(-1, 3)
    return tuple(rounded(flat[:, k]) for k in range(3))


def polyline_order(edges) -> np.ndarray:
    """Node indices that draw every edge once, as few polylines as the edges allow.

    Each connected group of edges with ``2k`` odd-degree nodes becomes ``max(k, 1)``
    polylines (an Euler trail through each after pairing its odd nodes), so a node is
    listed about once per polyline through it instead of once per edge end.

    Parameters
    ----------
    edges : array_like of int, shape (E, 2)
        Distinct node pairs.

    Returns
    -------
    ndarray of int
        Node indices, ``-1`` between polylines; consecutive nodes of a polyline are the
        ends of one edge, and every edge appears exactly once.

    Examples
    --------
    >>> polyline_order([[0, 1], [1, 2], [2, 0], [2, 3]]).tolist()
    [3, 2, 0, 1, 2]
    """
    edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    if not len(edges):
        return np.zeros(0, dtype=np.int64)
    virtual = -2                      # joined to every odd node: then every degree is even
    adjacency = {}
    for e, (a, b) in enumerate(edges.tolist()):
        adjacency.setdefault(a, []).append((b, e))
        adjacency.setdefault(b, []).append((a, e))
    odd = [v for v in sorted(adjacency) if len(adjacency[v]) % 2]
    for k, v in enumerate(odd):
        adjacency.setdefault(virtual, []).append((v, len(edges) + k))
        adjacency[v].append((virtual, len(edges) + k))
    used = np.zeros(len(edges) + len(odd), dtype=bool)
    position = dict.fromkeys(adjacency, 0)
    pieces = []
    for start in ([virtual] if odd else []) + sorted(v for v in adjacency if v != virtual):
        if position[start] >= len(adjacency[start]) or used[
                [e for _, e in adjacency[start][position[start]:]]].all():
            continue
        stack, circuit = [start], []              # Hierholzer's algorithm
        while stack:
            v = stack[-1]
            links = adjacency[v]
            while position[v] < len(links) and used[links[position[v]][1]]:
                position[v] += 1
            if position[v] < len(links):
                w, e = links[position[v]]
                used[e] = True
                stack.append(w)
            else:
                circuit.append(stack.pop())
        piece = []
        for v in circuit + [virtual]:             # split the circuit at the virtual node
            if v == virtual:
                if len(piece) > 1:
                    pieces.append(piece)
                piece = []
            else:
                piece.append(v)
    out = []
    for piece in pieces:
        out += ([-1] if out else []) + piece
    return np.asarray(out, dtype=np.int64)


def polyline_xyz(points, order) -> tuple:
    """x, y and z of the polylines of :func:`polyline_order` as plotly draws them.

    Parameters
    ----------
    points : ndarray, shape (N, 3)
        Node coordinates [mm].
    order : ndarray of int
        Node indices, ``-1`` between polylines.

    Returns
    -------
    (list, list, list)
        Rounded to :data:`DECIMALS`, ``None`` between polylines.
    """
    order = np.asarray(order, dtype=np.int64)
    xyz = np.full((len(order), 3), np.nan)
    xyz[order >= 0] = np.asarray(points, dtype=float)[order[order >= 0]]
    return tuple(rounded(xyz[:, k]) for k in range(3))


def mesh_trace(points, triangles, *, coordinates_only: bool = False, scene: str = "scene"):
    """The panels as a flat-shaded Mesh3d.

    Parameters
    ----------
    points : ndarray, shape (N, 3)
        Node coordinates [mm].
    triangles : ndarray of int, shape (T, 3)
    coordinates_only : bool
        Only the vertex coordinates (an animation frame's update).
    scene : str

    Returns
    -------
    plotly.graph_objects.Mesh3d
    """
    import plotly.graph_objects as go  # here: the compact page uses this module without it

    x, y, z = (rounded(points[:, k]) for k in range(3))
    if coordinates_only:
        return go.Mesh3d(x=x, y=y, z=z)
    return go.Mesh3d(
        x=x, y=y, z=z, i=triangles[:, 0].tolist(), j=triangles[:, 1].tolist(),
        k=triangles[:, 2].tolist(), color=PANEL_COLOUR, flatshading=True, opacity=1.0,
        lighting=MESH_LIGHTING,
        lightposition=dict(x=25000, y=50000, z=100000), name="panels", showlegend=True,
        hoverinfo="skip", scene=scene)


def line_trace(points, edges, *, name: str, colour, width: float, dash: str = "solid",
               coordinates_only: bool = False, scene: str = "scene", visible=True,
               order=None, legendgroup=None, showlegend=None):
    """Edges as one Scatter3d of polylines (see :func:`polyline_order`).

    Parameters
    ----------
    points : ndarray, shape (N, 3)
        Node coordinates [mm].
    edges : ndarray of int, shape (E, 2)
    name, colour, width, dash
        Legend name, line colour, width [px] and dash of the lines.
    coordinates_only : bool
        Only the coordinates (an animation frame's update).
    order : ndarray of int, optional
        ``polyline_order(edges)``, to reuse it (every frame draws the same polylines).
    legendgroup, showlegend : optional
        Passed to plotly (several scenes share one legend entry per family).

    Returns
    -------
    plotly.graph_objects.Scatter3d
    """
    import plotly.graph_objects as go  # as in mesh_trace

    x, y, z = polyline_xyz(points, polyline_order(edges) if order is None else order)
    if coordinates_only:
        return go.Scatter3d(x=x, y=y, z=z)
    return go.Scatter3d(x=x, y=y, z=z, mode="lines", name=name,
                        line=dict(color=colour, width=width, dash=dash), hoverinfo="name",
                        scene=scene, visible=visible, connectgaps=False,
                        legendgroup=legendgroup, showlegend=showlegend)
