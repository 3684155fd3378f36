"""The triangular facet angle Psi of a built cell (thesis section 3.4, figure 3.8).

Psi is the dihedral angle between the perimeter triangles and the end polygon, measured
inside the cell: small in the contracted state (the facets lie nearly flat, loads go into
the creases) and larger in the extended one (the facets stand up, loads go into the
facets). The thesis compares the ratio Psi_ext / Psi_con with the K_B ratio over the design
space (figures 3.9-3.12).

Here Psi is read from the built bar-and-hinge model: the dihedral angles at the hinges on
the polygon edges of a single cell, both end polygons (2n hinges; each taken on its interior
side, ``min(theta, 2 pi - theta)``, since the wing order fixes which side the dihedral angle
is measured on), computed from the model's nodes with ``atan2(|m x n|, m . n)`` of the two
wings' normals. That is exact to rounding at every angle, where the model's rest angles
(MERLIN2's arccosine, kept for its forces) carry up to ~1e-8 rad near a flat fold (a
nearly flat extended cell, lam -> 0.5 with Lc = 0). They equal ``Design.psi_ext`` /
``psi_con`` (closed form) to rounding.
"""

from __future__ import annotations

import math

import numpy as np

from kresling.geometry import Design, as_design, state_index
from kresling.model.kresling_specimen import kresling_specimen

__all__ = ["facet_angles", "facet_angle", "facet_angle_ratio"]

#: The 2n polygon-edge hinges of a cell agree to this [rad] (they are equal by symmetry).
SPREAD_TOLERANCE = 1e-9


def facet_angles(design: Design, state) -> np.ndarray:
    """Psi at every polygon edge of a built cell in ``state`` [rad].

    Parameters
    ----------
    design : Design
    state : {0, 1, "contracted", "extended"}

    Returns
    -------
    ndarray, shape (2 n,)
        The bottom polygon's n edges, then the top polygon's (hinge order of the model).
    """
    design = as_design(design)
    specimen = kresling_specimen(design, [state_index(state)], chirality=[design.chirality])
    model = specimen.model
    hinges = model.hinges[specimen.hinge_family == "polygon_edge"]
    a, b, c, d = (model.nodes[hinges[:, k]] for k in range(4))
    axis = b - a
    m, n = np.cross(c - a, axis), np.cross(axis, b - d)   # the wings' normals (MERLIN2's)
    return np.arctan2(np.linalg.norm(np.cross(m, n), axis=1), np.einsum("ij,ij->i", m, n))


def facet_angle(design: Design, state) -> float:
    """Psi of a built cell in ``state`` [rad] (the common value of :func:`facet_angles`).

    Raises
    ------
    RuntimeError
        If the polygon-edge hinges disagree by more than :data:`SPREAD_TOLERANCE` (a
        builder bug: they are equal by symmetry).

    Examples
    --------
    >>> from kresling import Design
    >>> round(facet_angle(Design(4, 0.7, 30), "extended"), 10)  # MERLIN2 golden hinge 1
    1.2878022801
    """
    angles = facet_angles(design, state)
    if np.ptp(angles) > SPREAD_TOLERANCE:
        raise RuntimeError(f"{design!r}: polygon-edge hinge angles spread by {np.ptp(angles):.3g} rad")
    return float(angles.mean())


def facet_angle_ratio(design: Design) -> float:
    """Psi_ext / Psi_con from the built cells (``inf`` if Psi_con is 0: Lc = 0)."""
    contracted = facet_angle(design, 0)
    return facet_angle(design, 1) / contracted if contracted > 0 else math.inf
