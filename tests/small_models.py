"""Small models with closed-form answers, shared by the tests of several layers."""

#: A 20 mm square creased along its diagonal 0-2, the triangle 0-1-2 held, 1 g on the free
#: corner 3: a problem's shared tables (the panel turns about the crease, a rotational
#: spring of 0.05 N*mm/rad per mm over 20 sqrt(2) mm, node 3 at 20 / sqrt(2) mm from it).
CREASED_SQUARE = {
    "pattern": {"vertices": [[0.0, 0.0, 0.0], [20.0, 0.0, 0.0], [20.0, 20.0, 0.0],
                             [0.0, 20.0, 0.0]], "panels": [[0, 1, 2], [0, 2, 3]]},
    "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                 "fold_stiffness": 0.05},
    "support": [{"nodes": [0, 1, 2], "fix": "xyz"}],
    "mass": [{"node": 3, "mass": 1e-6}]}

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
