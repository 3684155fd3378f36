"""A Miura-ori sheet of any size, folded to a given angle: a generated :class:`Pattern`.

The rigidly folded Miura-ori of parallelogram panels with sides ``a`` and ``b`` and sector
angle ``gamma``, each panel at fold angle ``theta`` to the sheet's plane (Schenk and Guest,
"Geometry of Miura-folded metamaterials", PNAS 2013). With

    H = a sin(theta) sin(gamma)
    S = b cos(theta) tan(gamma) / sqrt(1 + cos^2(theta) tan^2(gamma))
    L = a sqrt(1 - sin^2(theta) sin^2(gamma))
    V = b / sqrt(1 + cos^2(theta) tan^2(gamma))

vertex (i, j), i = 0..nx along x and j = 0..ny along y, sits at
``(i S, j L + V [i odd], H [j odd])``: every panel edge along j has length a, every edge
along i length b, and each panel's corner angle is gamma at every fold angle (the folding is
rigid). ``theta = 0`` is the flat pattern.
"""

from __future__ import annotations

import numpy as np

from kresling._validation import as_finite_real, as_integer
from kresling.io.fold_format import fold_angles
from kresling.io.pattern import Pattern, pattern_from_arrays

__all__ = ["miura_sheet"]

#: Largest sheet the builder makes: (nx + 1) (ny + 1) vertices at most.
MAX_VERTICES = 2_000_000


def miura_sheet(nx, ny, *, a=10.0, b=10.0, sector_angle=60.0, fold_angle=30.0) -> Pattern:
    """The crease pattern of an ``nx`` x ``ny`` panel Miura-ori sheet, folded rigidly.

    Parameters
    ----------
    nx, ny : int
        Panels along x (across the zig-zag creases) and along y; each >= 1.
    a, b : float, default 10
        Panel side lengths [mm]: ``a`` along y (the zig-zag creases), ``b`` along x.
    sector_angle : float, default 60
        The panels' corner angle gamma [degrees], in (0, 90).
    fold_angle : float, default 30
        Each panel's angle theta to the sheet's plane [degrees], in [0, 90): 0 is flat.

    Returns
    -------
    Pattern
        ``(nx + 1) (ny + 1)`` vertices [mm], vertex (i, j) at index ``j (nx + 1) + i``;
        ``nx ny`` quadrilateral panels, counter-clockwise seen from +z; interior creases
        assigned ``"M"`` or ``"V"`` with their fold angles [degrees] (``"F"`` and 0 when
        flat), the rim ``"B"``.

    Raises
    ------
    ValueError
        Naming the parameter: a count < 1 or too large a sheet, a length <= 0, an angle out
        of range.

    Examples
    --------
    >>> sheet = miura_sheet(2, 3)
    >>> sheet.num_vertices, sheet.num_faces
    (12, 6)
    """
    nx, ny = as_integer("nx", nx), as_integer("ny", ny)
    for name, value in (("nx", nx), ("ny", ny)):
        if value < 1:
            raise ValueError(f"{name} = {value!r} is invalid: must be >= 1 (panels)")
    if (nx + 1) * (ny + 1) > MAX_VERTICES:
        raise ValueError(f"nx, ny = {nx}, {ny} is invalid: the sheet would have "
                         f"{(nx + 1) * (ny + 1)} vertices; must have at most {MAX_VERTICES}")
    a, b = as_finite_real("a", a), as_finite_real("b", b)
    for name, value in (("a", a), ("b", b)):
        if value <= 0:
            raise ValueError(f"{name} = {value!r} is invalid: must be > 0 [mm]")
    gamma_deg = as_finite_real("sector_angle", sector_angle)
    if not 0 < gamma_deg < 90:
        raise ValueError(f"sector_angle = {gamma_deg!r} is invalid: must be in (0, 90) "
                         "[degrees]")
    theta_deg = as_finite_real("fold_angle", fold_angle)
    if not 0 <= theta_deg < 90:
        raise ValueError(f"fold_angle = {theta_deg!r} is invalid: must be in [0, 90) "
                         "[degrees]")
    gamma, theta = float(np.radians(gamma_deg)), float(np.radians(theta_deg))
    root = np.sqrt(1.0 + (np.cos(theta) * np.tan(gamma)) ** 2)
    H = a * np.sin(theta) * np.sin(gamma)
    S = b * np.cos(theta) * np.tan(gamma) / root
    L = a * np.sqrt(1.0 - (np.sin(theta) * np.sin(gamma)) ** 2)
    V = b / root

    i, j = np.meshgrid(np.arange(nx + 1), np.arange(ny + 1))   # (ny + 1, nx + 1)
    vertices = np.column_stack([(i * S).ravel(), (j * L + V * (i % 2)).ravel(),
                                (H * (j % 2)).ravel()])
    index = np.arange((nx + 1) * (ny + 1)).reshape(ny + 1, nx + 1)
    faces = np.column_stack([index[:-1, :-1].ravel(), index[:-1, 1:].ravel(),
                             index[1:, 1:].ravel(), index[1:, :-1].ravel()])
    faces = [tuple(int(v) for v in face) for face in faces]
    # The edges once each, in order of first appearance, then their fold angles.
    seen, edges = set(), []
    for face in faces:
        for u, v in zip(face, face[1:] + face[:1]):
            key = (min(u, v), max(u, v))
            if key not in seen:
                seen.add(key)
                edges.append((u, v))
    edges = np.array(edges, dtype=np.int64)
    angles = np.degrees(fold_angles(faces, edges, vertices))
    boundary = _boundary_mask(faces, edges)
    assignment = np.where(boundary, "B", np.where(angles > 1e-9, "V",
                                                  np.where(angles < -1e-9, "M", "F")))
    angles = np.where(boundary, 0.0, angles)
    return pattern_from_arrays(vertices, faces, edges=edges,
                               edges_assignment=assignment.tolist(), edges_fold_angle=angles)


def _boundary_mask(faces, edges) -> np.ndarray:
    """True for the edges that are a side of one face only."""
    count = {}
    for face in faces:
        for u, v in zip(face, face[1:] + face[:1]):
            key = (min(u, v), max(u, v))
            count[key] = count.get(key, 0) + 1
    return np.array([count[(min(u, v), max(u, v))] == 1 for u, v in edges])
