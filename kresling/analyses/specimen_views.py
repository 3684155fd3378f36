"""Views of a built specimen: its FOLD file and a 3D plot (undeformed or deformed).

The faces are the model's triangles (recovered from its hinges: each hinge joins two), so
the file shows exactly what the solver sees, the polygons inside the stack included (their
edges then join three faces). Edge assignments come from the element families:

=================  ==========  ===================================================
family             assignment  why
=================  ==========  ===================================================
valley             ``V``       valley crease
mountain           ``C``       cut through in the thesis's specimens (``M`` if
                               ``cut_mountains=False``)
polygon edge       ``M``       convex seen from outside each cell (Psi < pi)
polygon spoke      ``F``       inside the flat polygon
edge of one face   ``B``       boundary (none in a closed specimen)
=================  ==========  ===================================================

Faces are counter-clockwise about their outward normal: away from the axis for the cells'
facets, down for the bottom polygon and up for the others. Fold angles (degrees) are
``180 - the interior dihedral angle``, positive for valleys, negative otherwise, 0 on the
polygons' spokes.
"""

from __future__ import annotations

import logging

import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

from kresling.io import fold_document, write_fold_document

__all__ = ["specimen_faces", "specimen_edges", "specimen_fold", "write_specimen_fold",
           "plot_specimen"]

logger = logging.getLogger(__name__)

_ASSIGNMENT = {"valley": "V", "mountain": "C", "polygon_edge": "M", "polygon_spoke": "F"}
_SIGN = {"V": 1.0, "M": -1.0, "C": -1.0, "F": 0.0, "B": 0.0}


def specimen_faces(specimen) -> np.ndarray:
    """The model's triangles, oriented outward (see the module notes), shape (T, 3)."""
    hinges = specimen.model.hinges
    triangles = np.unique(np.sort(np.vstack([hinges[:, [0, 1, 2]], hinges[:, [0, 1, 3]]]),
                                  axis=1), axis=0)
    X = specimen.model.nodes
    a, b, c = (X[triangles[:, k]] for k in range(3))
    normal = np.cross(b - a, c - a)
    # Facets face away from the axis; a polygon's triangles (they hold its centre node) face
    # down at the bottom level and up elsewhere.
    centres = np.array([specimen.centre(level) for level in range(specimen.cells + 1)])
    fan = np.isin(triangles, centres).any(axis=1)
    outward = np.column_stack([(a + b + c)[:, :2], np.zeros(len(triangles))])
    up = np.where(np.isin(triangles, specimen.centre(0)).any(axis=1), -1.0, 1.0)
    outward[fan] = np.column_stack([np.zeros((fan.sum(), 2)), up[fan]])
    flip = np.einsum("ij,ij->i", normal, outward) < 0
    triangles[flip] = triangles[flip][:, [0, 2, 1]]
    return triangles


def specimen_edges(specimen, *, cut_mountains: bool = True):
    """One FOLD edge per geometric edge (MERLIN2's coincident bars merged).

    Returns
    -------
    edges : ndarray of int, shape (E, 2)
    assignments : list of str, length E
    """
    bars = np.sort(specimen.model.bars, axis=1)
    edges, first = np.unique(bars, axis=0, return_index=True)
    families = specimen.bar_family[first]
    table = dict(_ASSIGNMENT, mountain="C" if cut_mountains else "M")
    assignments = [table[f] for f in families]
    faces = specimen_faces(specimen)
    counts = {}
    for face in faces:
        for u, v in ((face[0], face[1]), (face[1], face[2]), (face[2], face[0])):
            key = (min(u, v), max(u, v))
            counts[key] = counts.get(key, 0) + 1
    for k, (u, v) in enumerate(edges):
        if counts.get((u, v), 0) == 1:
            assignments[k] = "B"
    return edges, assignments


def _fold_angles(specimen, edges, assignments, u=None) -> np.ndarray:
    """FOLD fold angles [degrees] from the hinges' dihedral angles (interior side)."""
    hinges = specimen.model.hinges
    theta = specimen.model.element_state(u)["hinge_angle"] if u is not None \
        else specimen.model.hinge_rest_angle
    interior = np.minimum(theta, 2 * np.pi - theta)
    by_edge = {}
    for (a, b), angle in zip(np.sort(hinges[:, :2], axis=1), interior):
        by_edge.setdefault((a, b), angle)  # the first hinge of an edge (the outer faces)
    out = np.zeros(len(edges))
    for k, ((a, b), letter) in enumerate(zip(edges, assignments)):
        if (a, b) in by_edge:
            out[k] = _SIGN[letter] * np.degrees(np.pi - by_edge[(a, b)])
    return out


def specimen_fold(specimen, *, frames=(), title: str = "", cut_mountains: bool = True) -> dict:
    """The specimen as a FOLD document (key frame: the built, stress-free geometry).

    Parameters
    ----------
    specimen : KreslingSpecimen
    frames : sequence of (str, array_like)
        Further frames: a title and a displacement of the model, shape (N, 3) or (3N,) [mm]
        (e.g. the last step of a bending test).
    title : str
    cut_mountains : bool, default True
        Assign the mountain creases ``C`` (cut, as in the thesis's specimens) or ``M``.

    Returns
    -------
    dict
        Ready for :func:`kresling.io.write_fold_document`.
    """
    edges, assignments = specimen_edges(specimen, cut_mountains=cut_mountains)
    X = specimen.model.nodes
    extra_frames = []
    for name, u in frames:
        u = np.asarray(u, dtype=float).reshape(-1, 3)
        extra_frames.append({"title": name, "vertices_coords": X + u,
                             "edges_foldAngle": _fold_angles(specimen, edges, assignments, u.ravel())})
    d = specimen.design
    return fold_document(
        X, edges, assignments, specimen_faces(specimen),
        edges_fold_angle=_fold_angles(specimen, edges, assignments), frames=extra_frames,
        title=title or f"Kresling specimen n={d.n} lambda={d.lam:g} Lc={d.Lc:g} mm, states "
                       f"{list(specimen.states)}",
        extra={"frame_classes": ["foldedForm"],
               "kresling:design": {"n": d.n, "lam": d.lam, "Lc": d.Lc, "R": d.R},
               "kresling:states": list(specimen.states),
               "kresling:chirality": list(specimen.chirality)})


def write_specimen_fold(path, specimen, **options):
    """Write :func:`specimen_fold` to ``path`` (JSON); returns the path."""
    return write_fold_document(path, specimen_fold(specimen, **options))


def _equal_axes(ax, points, view=None) -> None:
    """Equal scales on x, y and z around ``points``, few ticks, labels clear of the ticks.

    An axis seen end on (looking along x or y, e.g. ``view=(10, 0)``) gets no ticks and no
    label: they would fall on top of each other."""
    from matplotlib.ticker import MaxNLocator

    low, high = points.min(axis=0), points.max(axis=0)
    span = np.maximum(high - low, 1e-9)
    pad = 0.02 * span.max()
    ax.set_xlim(low[0] - pad, high[0] + pad), ax.set_ylim(low[1] - pad, high[1] + pad)
    ax.set_zlim(low[2] - pad, high[2] + pad)
    # Equal scales; zoomed out a little so that the tick labels and axis labels of a tall or
    # wide specimen stay inside the axes' box.
    ax.set_box_aspect(span + 2 * pad, zoom=0.88)
    for axis, name in zip((ax.xaxis, ax.yaxis, ax.zaxis), "xyz"):
        axis.set_major_locator(MaxNLocator(nbins=4, steps=[1, 2, 2.5, 5, 10]))
        axis.set_label_text(f"{name} [mm]", fontsize=9)
        axis.labelpad = 11 if name == "z" else 4
    ax.tick_params(labelsize=7, pad=1)
    ax.patch.set_alpha(0.0)   # a neighbour's labels reaching into this axes stay visible
    if view is not None:
        azimuth = np.radians(view[1])
        end_on = {"x": abs(np.sin(azimuth)) < 0.2, "y": abs(np.cos(azimuth)) < 0.2}
        for name, hidden in end_on.items():
            if hidden:
                getattr(ax, f"set_{name}ticks")([])
                getattr(ax, f"set_{name}label")("")


def plot_specimen(specimen, displacement=None, *, scale: float = 1.0, ax=None,
                  undeformed: bool = True, title: str = "", view=None):
    """Draw a specimen in 3D: facets, creases by family, optionally displaced.

    Parameters
    ----------
    specimen : KreslingSpecimen
    displacement : array_like, shape (N, 3) or (3N,), optional
        Node displacements [mm] (e.g. the last step of a bending test).
    scale : float, default 1
        Displacements are drawn ``scale`` times magnified (stated in the title).
    ax : mpl_toolkits.mplot3d.Axes3D, optional
    undeformed : bool, default True
        Also draw the built geometry, as a faint wireframe, when displaced.
    title : str
    view : (float, float), optional
        Elevation and azimuth of the camera [degrees] (``(10, 0)`` looks along x, so a
        bending test's deflection along y is seen side on).

    Returns
    -------
    Axes3D
    """
    if ax is None:
        ax = plt.figure(figsize=(5.0, 6.0), layout="constrained").add_subplot(projection="3d")
    X = specimen.model.nodes
    Y = X if displacement is None else X + scale * np.asarray(displacement, float).reshape(-1, 3)
    faces = specimen_faces(specimen)
    ax.add_collection3d(Poly3DCollection(Y[faces], facecolor="tab:blue", alpha=0.18,
                                         edgecolor="none"))
    edges, assignments = specimen_edges(specimen)
    styles = {"V": ("tab:blue", "-"), "C": ("tab:red", "--"), "M": ("k", "-"),
              "F": ("0.6", ":"), "B": ("k", "-")}
    for letter, (color, style) in styles.items():
        chosen = edges[np.array(assignments) == letter]
        if len(chosen):
            ax.add_collection3d(Line3DCollection(Y[chosen], colors=color, linestyles=style,
                                                 linewidths=0.9))
    if undeformed and displacement is not None:
        ax.add_collection3d(Line3DCollection(X[edges], colors="0.75", linewidths=0.4))
    if view is not None:
        ax.view_init(*view)
    _equal_axes(ax, np.vstack([X, Y]), view)
    d = specimen.design
    states = "extended" if set(specimen.states) == {1} else \
        "contracted" if set(specimen.states) == {0} else f"states {list(specimen.states)}"
    default = f"n={d.n}, λ={d.lam:g}, Lc={d.Lc:g} mm, {states}"
    if displacement is not None:
        default += f"\ndisplacements × {scale:g}"
    ax.set_title(title or default, fontsize=9)
    return ax
