r"""The flat crease pattern of a generalized Kresling cell (thesis section 2.2, eqns 1-7).

The cell is cut from one strip of ``2n`` congruent triangles with sides ``P``, ``Vg`` and
``Mg``. Flat, the strip's bottom points ``B_0 .. B_n`` lie ``P`` apart on the x axis and its
top points ``T_0 .. T_n`` ``P`` apart on the line ``y = Vg sin(theta_g)``, with
``T_i = B_(i-1) + Vg (cos theta_g, sin theta_g)`` (schematic, mountains drawn upright)::

        T_0       T_1       T_2               T_n
         +---------+---------+------ ... ------+
         |  upper /|        /|                 |\
       M |      /  |      /  |               M | \  closing tab
         |    / V  |    /    |                 | /  (glued under facet 0)
         |  / lower|  /      |                 |/
         +---------+---------+------ ... ------+
        B_0  \ /  B_1  \ /  B_2               B_n
             tab       tab      (triangular tabs glue to the separate base polygon)

Folded, ``B_i`` goes to bottom vertex ``i`` and ``T_i`` to top vertex ``i`` of
:meth:`kresling.Design.vertices` (indices mod ``n``; ``-i`` for chirality -1, whose pattern
is the mirror image), so ``B_i T_(i+1)`` is the valley crease (length Vg), ``B_i T_i`` the
mountain crease (Mg), ``B_i B_(i+1)`` a polygon edge (P) where a tab folds in onto the base
polygon, and ``B_n T_n`` the seam that closes onto ``B_0 T_0``.

The pattern is drawn as seen from the outside of the folded cell: mountain and valley are
as seen from outside, and faces run counter-clockwise about the +z axis, which points out of
the cell once folded (the convention of the FOLD format).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling.fabrication._checks import non_negative, positive, sheet_size
from kresling.fabrication.planar import barycentric, convex_overlap, mirror_x, signed_area
from kresling.geometry import Design, as_design

__all__ = ["CreasePattern", "crease_pattern", "CREASE_KINDS", "FACE_KINDS"]

#: What each line of the pattern is: the cell's two crease families, the polygon edges where
#: the tabs fold, the closing tab's fold, and the boundary of a piece.
CREASE_KINDS = ("mountain", "valley", "tab", "seam", "boundary")
#: The faces: strip triangles, triangular tabs, the closing tab, the separate base polygon.
FACE_KINDS = ("facet", "tab", "closing tab", "base polygon")


@dataclass(frozen=True, eq=False)
class CreasePattern:
    """The flat pattern of one cell as points, lines and faces (mm).

    Build it with :func:`crease_pattern`. Attributes are read-only arrays and tuples.

    Attributes
    ----------
    design : Design
    points : ndarray, shape (V, 2)
        Flat positions [mm]; ``V = 4n + 4``: ``B_0..B_n``, ``T_0..T_n``, the ``n`` tab tips,
        the closing tab's two free corners, then the ``n`` corners of the base polygon.
    edges : ndarray of int, shape (E, 2)
        Every side of every face once.
    edge_kinds : tuple of str, length E
        One of :data:`CREASE_KINDS` per edge.
    faces : tuple of tuple of int
        Point indices of each face, counter-clockwise.
    face_kinds : tuple of str
        One of :data:`FACE_KINDS` per face; the ``2n`` facets come first, in strip order.
    anchors : ndarray of int, shape (V, 3)
    weights : ndarray, shape (V, 3)
        Where each point goes when folded: the weighted sum of three anchor points (bottom
        vertices ``0..n-1``, top vertices ``n..2n-1``, the bottom centre ``2n``). The weights
        are barycentric coordinates in a flat triangle congruent to the anchors' triangle, so
        folding is an isometry of every face.
    tab_height, closing_tab_width, tab_clearance : float
        The parameters it was built with [mm].
    """

    design: Design
    points: np.ndarray
    edges: np.ndarray
    edge_kinds: tuple
    faces: tuple
    face_kinds: tuple
    anchors: np.ndarray
    weights: np.ndarray
    tab_height: float
    closing_tab_width: float
    tab_clearance: float

    @property
    def bottom(self) -> np.ndarray:
        """Indices of ``B_0..B_n``, shape (n + 1,)."""
        return np.arange(self.design.n + 1)

    @property
    def top(self) -> np.ndarray:
        """Indices of ``T_0..T_n``, shape (n + 1,)."""
        return np.arange(self.design.n + 1, 2 * self.design.n + 2)

    def edges_of_kind(self, kind: str) -> np.ndarray:
        """The edges of one kind, shape (k, 2)."""
        return self.edges[[k for k, name in enumerate(self.edge_kinds) if name == kind]]

    def faces_of_kind(self, kind: str) -> list:
        """Corner points of every face of one kind: a list of (m, 2) arrays."""
        return [self.points[list(f)] for f, name in zip(self.faces, self.face_kinds) if name == kind]

    def outline(self) -> np.ndarray:
        """The cut outline of the cell piece (strip, tabs, closing tab), CCW, shape (k, 2)."""
        n = self.design.n
        tips, (corner_b, corner_t) = 2 * n + 2 + np.arange(n), 3 * n + 2 + np.arange(2)
        order = [index for i in range(n) for index in (self.bottom[i], tips[i])]
        order += [self.bottom[n], corner_b, corner_t]
        order += list(self.top[::-1])
        outline = self.points[order]
        return outline if signed_area(outline) > 0 else outline[::-1]

    def base_polygon(self) -> np.ndarray:
        """The base polygon's corners, CCW, shape (n, 2)."""
        return self.points[3 * self.design.n + 4:]

    def folded(self, state) -> np.ndarray:
        """Every point's position on the folded cell in a stable state.

        Parameters
        ----------
        state : {0, 1, "contracted", "extended"}

        Returns
        -------
        ndarray, shape (V, 3)
            mm, in the frame of :meth:`kresling.Design.vertices`. ``B_n`` lands on ``B_0``
            and ``T_n`` on ``T_0`` (the strip closes), tabs on the base polygon's plane and
            the closing tab on facet 0.
        """
        bottom, top = self.design.vertices(state)
        anchor_points = np.vstack([bottom, top, np.zeros((1, 3))])
        return np.einsum("vk,vkd->vd", self.weights, anchor_points[self.anchors])

    def face_name(self, index: int) -> str:
        """A face as messages name it, e.g. ``"tab 3"`` or ``"facet 0"``."""
        kind = self.face_kinds[index]
        ordinal = self.face_kinds[:index].count(kind)
        return kind if kind in ("closing tab", "base polygon") else f"{kind} {ordinal}"


def crease_pattern(design: Design, *, tab_height: float = 8.0, closing_tab_width: float = 6.0,
                   tab_clearance: float = 1.0, polygon_spacing: float = 5.0) -> CreasePattern:
    """Lay out the flat crease pattern of a generalized Kresling cell.

    Parameters
    ----------
    design : Design
        The cell; chirality -1 gives the mirror image of chirality +1.
    tab_height : float, default 8.0
        Height of the triangular tabs on the polygon edges [mm] (isosceles, on the whole edge).
        The thesis does not give it; 8 mm leaves a glue area of ~75 mm^2 per tab at n = 10.
        Must be below the base polygon's apothem ``R cos(pi/n)``, else neighbouring tabs
        overlap when laid flat on the base polygon.
    closing_tab_width : float, default 6.0
        Width of the closing (glue) tab across the seam [mm] (thesis silent).
    tab_clearance : float, default 1.0
        How far the closing tab's free corners stay from the other creases of the facet it is
        glued to [mm], so it stiffens neither (more than half the laminate's 1 mm valley gap).
    polygon_spacing : float, default 5.0
        Gap between the tab tips and the base polygon in the layout [mm].

    Returns
    -------
    CreasePattern

    Raises
    ------
    ValueError
        If a parameter is not a finite positive number, the tabs would overlap on the base
        polygon, or the closing tab does not fit in the facet it is glued to.
    """
    design = as_design(design)
    positive("tab_height", tab_height)
    positive("closing_tab_width", closing_tab_width)
    non_negative("tab_clearance", tab_clearance)
    non_negative("polygon_spacing", polygon_spacing)
    n, P, R = design.n, design.P, design.R
    apothem = R * math.cos(math.pi / n)
    if tab_height >= apothem:
        raise ValueError(
            f"tab_height = {tab_height!r} mm is invalid for n = {n}, R = {R:g} mm: laid flat on "
            f"the base polygon, neighbouring tabs would overlap; must be < {apothem:.4g} mm "
            "(the polygon's apothem R cos(pi/n))")
    rise = design.Vg * np.array([math.cos(design.theta_g), math.sin(design.theta_g)])
    bottom = np.column_stack([P * np.arange(n + 1), np.zeros(n + 1)])
    top = bottom - [P, 0.0] + rise                          # T_i = B_(i-1) + rise
    tips = np.column_stack([P * (np.arange(n) + 0.5), np.full(n, -tab_height)])
    closing = _closing_tab_corners(bottom[n], top[n], top[n] + [P, 0.0], closing_tab_width,
                                   tab_clearance)
    polygon = _base_polygon(n, R, centre_x=0.5 * n * P, top_y=-tab_height - polygon_spacing)
    points = np.vstack([bottom, top, tips, closing, polygon])
    width, height = np.ptp(points, axis=0)
    sheet_size(f"the crease pattern of {design!r}", width, height)

    B, T = np.arange(n + 1), np.arange(n + 1, 2 * n + 2)
    A, (CB, CT), Q = 2 * n + 2 + np.arange(n), 3 * n + 2 + np.arange(2), 3 * n + 4 + np.arange(n)
    faces = [f for i in range(n) for f in ((B[i], B[i + 1], T[i + 1]), (B[i], T[i + 1], T[i]))]
    faces += [(B[i], A[i], B[i + 1]) for i in range(n)] + [(B[n], CB, CT, T[n]), tuple(Q)]
    faces = [_counter_clockwise(f, points) for f in faces]
    face_kinds = ("facet",) * (2 * n) + ("tab",) * n + ("closing tab", "base polygon")

    named = {frozenset((B[i], B[i + 1])): "tab" for i in range(n)}
    named.update({frozenset((B[i], T[i + 1])): "valley" for i in range(n)})
    named.update({frozenset((B[i], T[i])): "mountain" for i in range(1, n)})
    named[frozenset((B[n], T[n]))] = "seam"
    edges = _unique_edges(faces)
    edge_kinds = tuple(named.get(frozenset(e), "boundary") for e in edges)

    # Anchors: 0..n-1 bottom vertices, n..2n-1 top vertices, 2n the bottom centre.
    anchors = np.zeros((len(points), 3), dtype=int)
    weights = np.zeros((len(points), 3))
    weights[:, 0] = 1.0
    anchors[B, 0], anchors[T, 0] = B % n, n + B % n
    anchors[Q, 0] = (-np.arange(n)) % n     # seen from outside, i.e. from below: reversed
    for i in range(n):                      # a tab tip lies on the polygon, towards its centre
        hinge = 0.5 * (bottom[i] + bottom[i + 1])
        reference = [bottom[i], bottom[i + 1], hinge - [0.0, apothem]]
        anchors[A[i]] = [i, (i + 1) % n, 2 * n]
        weights[A[i]] = barycentric(tips[i], reference)
    for index in (CB, CT):                  # the closing tab lies on facet (b_0, t_0, t_1)
        anchors[index] = [0, n, n + 1]
        weights[index] = barycentric(points[index], [bottom[n], top[n], top[n] + [P, 0.0]])

    pattern = CreasePattern(design, points, edges, edge_kinds, tuple(faces), face_kinds,
                            anchors, weights, float(tab_height), float(closing_tab_width),
                            float(tab_clearance))
    if design.chirality < 0:
        pattern = _mirrored(pattern)
    _check_no_overlap(pattern)
    return pattern


def _closing_tab_corners(seam_bottom, seam_top, apex, width, clearance) -> np.ndarray:
    """The free corners (near the bottom, near the top) of the closing tab.

    The tab sits in the triangle ``seam_bottom, seam_top, apex`` beyond the seam (a copy of
    facet 0): its cap is parallel to the seam at ``width``, its corners ``clearance`` inside
    the triangle's two other sides.
    """
    seam = seam_top - seam_bottom
    inward = np.array([seam[1], -seam[0]]) / np.linalg.norm(seam)
    if np.dot(apex - seam_bottom, inward) < 0:
        inward = -inward

    def inset_side(start, other):
        """The side ``start -> apex`` moved ``clearance`` towards ``other``."""
        direction = apex - start
        normal = np.array([direction[1], -direction[0]]) / np.linalg.norm(direction)
        normal = normal if np.dot(other - start, normal) > 0 else -normal
        return start + clearance * normal, direction

    sides = [inset_side(seam_bottom, seam_top), inset_side(seam_top, seam_bottom)]
    cap_point = seam_bottom + width * inward
    corners = [_intersect(*side, cap_point, seam) for side in sides]
    wedge_tip = _intersect(*sides[0], *sides[1])
    limit = float(np.dot(wedge_tip - seam_bottom, inward))
    if width >= limit:
        raise ValueError(
            f"closing_tab_width = {width!r} mm is invalid for this design: the closing tab must "
            f"fit inside the facet it is glued to, {clearance:g} mm (tab_clearance) clear of its "
            f"other creases; must be < {limit:.4g} mm")
    return np.array(corners)


def _intersect(p1, d1, p2, d2) -> np.ndarray:
    """Where the lines ``p1 + s d1`` and ``p2 + t d2`` meet."""
    s, _ = np.linalg.solve(np.column_stack([d1, -np.asarray(d2)]), np.asarray(p2) - p1)
    return p1 + s * np.asarray(d1)


def _base_polygon(n: int, R: float, centre_x: float, top_y: float) -> np.ndarray:
    """Regular n-gon, one edge horizontal at the bottom, its highest point at ``top_y``."""
    angles = -0.5 * math.pi + math.pi / n + 2.0 * math.pi * np.arange(n) / n
    corners = R * np.column_stack([np.cos(angles), np.sin(angles)])
    return corners + [centre_x, top_y - corners[:, 1].max()]


def _counter_clockwise(face, points) -> tuple:
    face = tuple(int(i) for i in face)
    return face if signed_area(points[list(face)]) > 0 else face[::-1]


def _unique_edges(faces) -> np.ndarray:
    seen, edges = set(), []
    for face in faces:
        for a, b in zip(face, face[1:] + face[:1]):
            if frozenset((a, b)) not in seen:
                seen.add(frozenset((a, b)))
                edges.append((a, b))
    return np.array(edges, dtype=int)


def _mirrored(pattern: CreasePattern) -> CreasePattern:
    """The mirror image: x reflected, faces re-oriented, vertex index i -> -i (chirality -1)."""
    n = pattern.design.n
    points = mirror_x(pattern.points, 0.5 * (pattern.points[:, 0].min() + pattern.points[:, 0].max()))
    anchors = pattern.anchors.copy()
    polygon_anchor = anchors < 2 * n
    # Bottom j -> -j, top n + j -> n + (-j); the centre (2n) stays.
    anchors[polygon_anchor] = np.where(anchors[polygon_anchor] < n,
                                       (-anchors[polygon_anchor]) % n,
                                       n + (-(anchors[polygon_anchor] - n)) % n)
    faces = tuple(face[::-1] for face in pattern.faces)
    return CreasePattern(pattern.design, points, pattern.edges, pattern.edge_kinds, faces,
                         pattern.face_kinds, anchors, pattern.weights, pattern.tab_height,
                         pattern.closing_tab_width, pattern.tab_clearance)


def _check_no_overlap(pattern: CreasePattern, tolerance: float = 1e-6) -> None:
    """Faces may touch along edges and corners, never overlap (all faces are convex)."""
    polygons = [pattern.points[list(face)] for face in pattern.faces]
    low = np.array([p.min(axis=0) for p in polygons])
    high = np.array([p.max(axis=0) for p in polygons])
    # Only faces whose bounding boxes overlap need the exact test: O(faces) pairs, not O(faces^2).
    boxes_meet = np.all(np.minimum(high[:, None], high[None]) - np.maximum(low[:, None], low[None])
                        > tolerance, axis=2)
    for a, b in zip(*np.nonzero(np.triu(boxes_meet, k=1))):
        if convex_overlap(polygons[a], polygons[b]) > tolerance:
            raise ValueError(
                f"{pattern.design!r} cannot be laid flat: {pattern.face_name(a)} overlaps "
                f"{pattern.face_name(b)} (tab_height = {pattern.tab_height:g} mm, "
                f"closing_tab_width = {pattern.closing_tab_width:g} mm)")
