"""The separate pieces cut beside the strip: reinforcement panels and the bridged base polygon."""

from __future__ import annotations

import numpy as np

from kresling.fabrication.pattern import CreasePattern
from kresling.fabrication.planar import offset_polygon, signed_area

__all__ = ["facet_inradius", "reinforcement_panels", "base_polygon_paths"]


def facet_inradius(pattern: CreasePattern) -> float:
    """Inradius of a facet (sides P, Vg, Mg; all facets are congruent) [mm]."""
    d = pattern.design
    semi_perimeter = 0.5 * (d.P + d.Vg + d.Mg)
    area = abs(signed_area(pattern.faces_of_kind("facet")[0]))
    return area / semi_perimeter


def reinforcement_panels(pattern: CreasePattern, inset: float, spacing: float) -> list:
    """The inner reinforcement panels (thesis section 2.2), laid out above the strip.

    Each panel is its facet with every side moved ``inset`` inwards, so it clears the
    creases; the panels keep the strip's arrangement, shifted up by the strip's height plus
    ``spacing``, so they cannot overlap each other or the strip.

    Parameters
    ----------
    pattern : CreasePattern
    inset : float
        [mm], must be below the facet's inradius.
    spacing : float
        [mm]

    Returns
    -------
    list of ndarray, shape (3, 2)
        One triangle per facet, in facet order [mm].

    Raises
    ------
    ValueError
        If ``inset`` leaves no panel.
    """
    inradius = facet_inradius(pattern)
    if inset >= inradius:
        d = pattern.design
        raise ValueError(
            f"panel_inset = {inset!r} mm is invalid for this design: a facet (sides P = "
            f"{d.P:.4g}, Vg = {d.Vg:.4g}, Mg = {d.Mg:.4g} mm) has an inradius of "
            f"{inradius:.4g} mm; must be < {inradius:.4g} mm")
    strip_top = pattern.points[pattern.top, 1].max()
    shift = np.array([0.0, strip_top + spacing])
    return [offset_polygon(facet, -inset) + shift for facet in pattern.faces_of_kind("facet")]


def base_polygon_paths(polygon, bridges: int, width: float):
    """Split the base polygon's outline at ``bridges`` uncut bridges.

    Parameters
    ----------
    polygon : array_like, shape (n, 2)
        Corners [mm].
    bridges : int
        Number of bridges, on edges spread evenly round the polygon (0: cut it all).
    width : float
        Length of each bridge along its edge [mm].

    Returns
    -------
    cuts : list of ndarray, shape (k, 2)
        Open polylines that cut the outline between the bridges (a single closed outline,
        first corner repeated at the end, when ``bridges == 0``).
    bridge_segments : list of ndarray, shape (2, 2)
        The bridges themselves, to be cut in a later pass.

    Raises
    ------
    ValueError
        If there are more bridges than edges or a bridge is longer than its edge.
    """
    polygon = np.asarray(polygon, dtype=float)
    n = len(polygon)
    if bridges > n:
        raise ValueError(f"polygon_bridges = {bridges} is invalid: must be <= n = {n}")
    if bridges == 0:
        return [np.vstack([polygon, polygon[:1]])], []
    edge_length = float(np.linalg.norm(polygon[1] - polygon[0]))
    if width >= edge_length:
        raise ValueError(f"bridge_width = {width!r} mm is invalid: the base polygon's edges are "
                         f"{edge_length:.4g} mm long; must be shorter")
    bridged = sorted({int(round(j * n / bridges)) % n for j in range(bridges)})
    ends = []                               # (start, end) of each bridge along its edge
    for e in bridged:
        a, b = polygon[e], polygon[(e + 1) % n]
        middle, along = 0.5 * (a + b), (b - a) / np.linalg.norm(b - a)
        ends.append((middle - 0.5 * width * along, middle + 0.5 * width * along))
    cuts = []
    for k, e in enumerate(bridged):
        following = bridged[(k + 1) % len(bridged)]
        corners = [(e + 1 + j) % n for j in range((following - e - 1) % n + 1)]
        cuts.append(np.vstack([ends[k][1], polygon[corners], ends[(k + 1) % len(bridged)][0]]))
    return cuts, [np.array(segment) for segment in ends]
