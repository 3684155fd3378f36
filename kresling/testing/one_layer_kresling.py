"""A one-layer Kresling in a few lines: six-sided, R = H = 50 mm, the top ring turned by
30 deg, 12 triangles; linear bars (E = 10 N/mm^2, A = 19.7 mm^2) and enhanced-linear folds
(18/342 deg, k L0 = 1e-3 N*mm/rad each), the bottom ring fixed. Its MGDCM path under -0.4 N
on each top node crosses a double bifurcation near u_z = -22.5 mm: the test and benchmark of
MGDCM's accuracy floor."""

import numpy as np

from kresling.model import Model

__all__ = ["SIDES", "one_layer_kresling"]

SIDES = 6


def one_layer_kresling():
    """The model and the reference load (-0.4 N down on each top node)."""
    angles = 2 * np.pi * np.arange(SIDES) / SIDES
    bottom = np.c_[50 * np.cos(angles), 50 * np.sin(angles), np.zeros(SIDES)]
    turned = angles + np.radians(30.0)
    top = np.c_[50 * np.cos(turned), 50 * np.sin(turned), np.full(SIDES, 50.0)]
    nodes = np.vstack([bottom, top])
    triangles = []
    for i in range(SIDES):
        j = (i + 1) % SIDES
        triangles += [(i, j, SIDES + j), (i, SIDES + j, SIDES + i)]
    wings = {}
    for t in triangles:
        for k in range(3):
            edge = tuple(sorted((t[k], t[(k + 1) % 3])))
            wings.setdefault(edge, []).append(t[(k + 2) % 3])
    hinges = [(a, b, *w) for (a, b), w in wings.items() if len(w) == 2]
    length = np.array([np.linalg.norm(nodes[a] - nodes[b]) for a, b, _, _ in hinges])
    fixed = np.zeros((2 * SIDES, 3), bool)
    fixed[:SIDES] = True
    model = Model(nodes, list(wings), hinges, bar_modulus=10.0, bar_area=19.7,
                  bar_law="linear", hinge_stiffness=1e-3 / length,
                  hinge_law="enhanced_linear", hinge_limits=np.radians([18.0, 342.0]),
                  fixed=fixed)
    forces = np.zeros((2 * SIDES, 3))
    forces[SIDES:, 2] = -0.4
    return model, forces
