"""Lumped node masses of a sheet: each triangle's mass shared equally by its corners.

Units are mm, N and s, so masses are in tonnes (t = N s^2/mm) and densities in t/mm^3 (PET:
about 1.38e-9 t/mm^3, i.e. 1.38 g/cm^3). See docs/dynamics.md.

The rule, triangle by triangle: a triangle of area ``A`` cut from a sheet of thickness ``t``
and density ``rho`` weighs ``rho t A``, and each of its three corners takes a third of it.
A panel split into triangles (N4B5 or N5B8) thus gives each node the thirds of the triangles
it is a corner of; an N5B8 centre node, a corner of all the panel's triangles, takes a third
of the panel's mass. These are the row sums of the consistent mass matrix of linear
triangles, and the total is the sheet's mass exactly. A panel given as a polygon (no
triangles) shares its mass equally among its corners.

>>> import numpy as np
>>> square = np.array([[0, 0, 0], [2, 0, 0], [2, 2, 0], [0, 2, 0]], float)
>>> lumped_masses((square, [[0, 1, 2, 3]]), thickness=0.5, density=1e-9).tolist()
[5e-10, 5e-10, 5e-10, 5e-10]
"""

from __future__ import annotations

import numpy as np

from kresling._validation import as_float_array, as_index_lists, as_positive_real

__all__ = ["lumped_masses", "specimen_triangles", "PET_DENSITY", "PET_LAMINATE_THICKNESS"]

#: Density of PET [t/mm^3] (1.38 g/cm^3, a handbook value: the thesis states no density).
PET_DENSITY = 1.38e-9
#: Thickness of the thesis's PET laminate [mm]: a 0.25 mm facet sheet and a 0.05 mm hinge
#: sheet (thesis, section 4.1); the transfer tape between them, whose thickness the thesis
#: does not give, is left out.
PET_LAMINATE_THICKNESS = 0.30


def _polygon_area(points: np.ndarray) -> float:
    """Area of a (possibly non-planar) polygon: its fan of triangles about the centroid."""
    c = points.mean(axis=0)
    a, b = points - c, np.roll(points, -1, axis=0) - c
    return 0.5 * float(np.linalg.norm(np.cross(a, b), axis=1).sum())


def _faces(source):
    """(nodes (N, 3), faces: list of index tuples) of a pattern model, specimen or pair."""
    elements = getattr(source, "elements", None)
    if elements is not None:                      # a PatternModel: its triangles
        return np.asarray(source.model.nodes), [tuple(t) for t in elements.triangles.tolist()]
    if hasattr(source, "design") and hasattr(source, "chirality"):   # a KreslingSpecimen
        return np.asarray(source.model.nodes), [tuple(t) for t in specimen_triangles(source)]
    if not isinstance(source, (tuple, list)) or len(source) != 2:
        raise ValueError(f"source = {type(source).__name__} is invalid: must be a "
                         "PatternModel, a KreslingSpecimen or a pair (nodes, triangles or "
                         "panels)")
    nodes = as_float_array("nodes", source[0])
    if nodes.ndim != 2 or nodes.shape[1] != 3:
        raise ValueError(f"nodes has shape {nodes.shape}: must be (N, 3)")
    faces = as_index_lists("panels", source[1])
    for i, face in enumerate(faces):
        if len(face) < 3:
            raise ValueError(f"panels[{i}] = {list(face)}: a face needs at least 3 nodes")
        if min(face) < 0 or max(face) >= len(nodes):
            raise ValueError(f"panels[{i}] = {list(face)}: node index out of range "
                             f"[0, {len(nodes)})")
    return nodes, [tuple(f) for f in faces]


def lumped_masses(source, thickness, density, extra=None) -> np.ndarray:
    """Node masses of a sheet, each face's mass shared equally by its corners [t].

    Parameters
    ----------
    source : PatternModel, KreslingSpecimen or (nodes, faces)
        A pattern model (its triangles, N5B8 centre nodes included), a Kresling specimen
        (:func:`specimen_triangles`: side triangles and polygon fans) or a pair of node
        coordinates (N, 3) [mm] and faces (triangles or panels, lists of node indices).
    thickness : float
        Sheet thickness [mm].
    density : float
        Sheet density [t/mm^3] (PET: :data:`PET_DENSITY`).
    extra : dict or array_like, optional
        Explicit masses added to nodes [t]: ``{node: mass}`` or an array of shape (N,).

    Returns
    -------
    ndarray, shape (N,)
        Mass of every node [t]; their sum is ``density * thickness`` times the faces' area
        plus the explicit masses.

    Raises
    ------
    ValueError
        For a non-positive thickness or density, a bad face, or a bad or negative explicit
        mass (naming the node).
    """
    thickness = as_positive_real("thickness", thickness)
    density = as_positive_real("density", density)
    nodes, faces = _faces(source)
    masses = np.zeros(len(nodes))
    areal = density * thickness
    for face in faces:
        index = list(face)
        masses[index] += areal * _polygon_area(nodes[index]) / len(index)
    return masses + _extra(extra, len(nodes))


def _extra(extra, count: int) -> np.ndarray:
    out = np.zeros(count)
    if extra is None:
        return out
    if isinstance(extra, dict):
        for node, mass in extra.items():
            if not (isinstance(node, (int, np.integer)) and 0 <= node < count):
                raise ValueError(f"extra has node {node!r}: must be a node index in "
                                 f"[0, {count})")
            out[node] += _mass(f"extra[{node}]", mass)
        return out
    values = as_float_array("extra", extra)
    if values.shape != (count,):
        raise ValueError(f"extra has shape {values.shape}: must be ({count},) or a dict")
    bad = np.flatnonzero(~np.isfinite(values) | (values < 0))
    if bad.size:
        raise ValueError(f"extra[{bad[0]}] = {values[bad[0]]!r} is invalid: must be a finite "
                         "mass >= 0 [t]")
    return out + values


def _mass(name, value) -> float:
    value = float(value)
    if not (np.isfinite(value) and value >= 0):
        raise ValueError(f"{name} = {value!r} is invalid: must be a finite mass >= 0 [t]")
    return value


def specimen_triangles(specimen) -> np.ndarray:
    """The triangles of a Kresling specimen: each cell's 2n side triangles, then each
    level's polygon as a fan of n triangles about its centre node.

    Parameters
    ----------
    specimen : KreslingSpecimen

    Returns
    -------
    ndarray of int, shape (2 n cells + n (cells + 1), 3)
    """
    n = specimen.design.n
    rows = []
    for i, c in enumerate(specimen.chirality):
        for j in range(n):
            b, b1 = i * (n + 1) + j, i * (n + 1) + (j + 1) % n
            t, t1 = b + n + 1, b1 + n + 1
            rows += [[b, b1, t1], [b, t1, t]] if c > 0 else [[b, b1, t], [b1, t1, t]]
    for level in range(specimen.cells + 1):
        centre = level * (n + 1) + n
        rows += [[level * (n + 1) + j, level * (n + 1) + (j + 1) % n, centre]
                 for j in range(n)]
    return np.array(rows, dtype=np.int64)
