"""Small models with closed-form answers, shared by the tests of several layers."""

import numpy as np

from kresling.model import Model


def chain(n, spring=2.5, mass=3e-6, length=4.0):
    """n equal masses on n linear bars along x, node 0 held, y and z held everywhere."""
    nodes = np.zeros((n + 1, 3))
    nodes[:, 0] = length * np.arange(n + 1)
    bars = np.column_stack([np.arange(n), np.arange(1, n + 1)])
    fixed = np.ones((n + 1, 3), dtype=bool)
    fixed[1:, 0] = False
    # modulus * area / length = spring: the linear law's axial stiffness exactly.
    model = Model(nodes, bars, np.zeros((0, 4), dtype=int), bar_modulus=spring * length / 0.5,
                  bar_area=0.5, bar_law="linear", hinge_stiffness=[], fixed=fixed)
    return model, np.full(n + 1, mass)
