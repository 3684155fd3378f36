"""Fold angles in FOLD's convention and the hinges' rest angles, both ways.

A hinge of the model measures the dihedral angle ``theta`` in [0, 2 pi) about its axis
``a -> b`` (pi: flat). A FOLD file states fold angles ``rho`` in [-180, 180] degrees:
positive for a valley, which brings together the sides of the two faces that their vertex
order faces (counter-clockwise seen from that side), negative for a mountain, 0 flat. The
two meet through one sign per hinge, ``rho = sigma (pi - theta)``, where ``sigma`` says
whether the hinge's own orientation agrees with the faces' (docs/folding.md).
"""

from __future__ import annotations

import numpy as np

__all__ = ["hinge_fold_signs", "fold_angles_deg", "rest_angles_for"]


def hinge_fold_signs(pattern_model) -> np.ndarray:
    """The sign ``sigma`` of each hinge (``rho = sigma (pi - theta)``), shape (H,).

    Found in the reference configuration from the panel that holds the hinge's second wing:
    +1 where that panel's normal (by its vertex order) points the way of
    ``(b - a) x (b - d)``, -1 otherwise.
    """
    # Imported here: the model's modules are read by commands (kresling bend) that read no
    # pattern file.
    from kresling.io.frame_angles import newell_normals

    elements = pattern_model.elements
    X = np.asarray(pattern_model.model.nodes, dtype=float)
    normals = newell_normals(X[None], elements.panels)[0]
    panels_of = {}  # node -> the panels it belongs to (a centre node: its own panel)
    for p, panel in enumerate(elements.panels):
        members = list(panel) + ([int(elements.panel_centre[p])]
                                 if elements.panel_centre[p] >= 0 else [])
        for node in members:
            panels_of.setdefault(int(node), set()).add(p)
    hinges = np.asarray(pattern_model.model.hinges, dtype=np.int64).reshape(-1, 4)
    if not len(normals):
        return np.ones(len(hinges))
    panel_of = np.full(len(hinges), -1, dtype=np.int64)
    for h, (a, b, _, d) in enumerate(hinges.tolist()):
        shared = panels_of.get(a, set()) & panels_of.get(b, set()) & panels_of.get(d, set())
        if shared:   # else a hinge of no panel (a model built by hand): theta's own orientation
            panel_of[h] = min(shared)
    a, b, d = X[hinges[:, 0]], X[hinges[:, 1]], X[hinges[:, 3]]
    agrees = np.einsum("ij,ij->i", normals[panel_of], np.cross(b - a, b - d)) >= 0
    return np.where((panel_of < 0) | agrees, 1.0, -1.0)


def fold_angles_deg(pattern_model, u=None, signs=None) -> np.ndarray:
    """Each hinge's fold angle at displacement ``u`` [deg], FOLD's convention, shape (H,)."""
    if signs is None:
        signs = hinge_fold_signs(pattern_model)
    theta = pattern_model.model.element_state(u)["hinge_angle"]
    return np.degrees(signs * (np.pi - theta))


def rest_angles_for(fold_angle_deg, signs) -> np.ndarray:
    """The rest angles [rad] in [0, 2 pi) that put hinges of ``signs`` at the fold angles
    ``fold_angle_deg`` [deg] (a fold of -180 or 180 deg, folded flat, is taken to within 1e-9
    rad of it: 2 pi itself is no rest angle)."""
    theta = np.pi - np.asarray(signs, dtype=float) * np.radians(fold_angle_deg)
    return np.clip(theta, 0.0, np.nextafter(2 * np.pi, 0) - 1e-9)
