"""
A bending curve in both states
==============================

The three-point bending test of section 3.3 on a module of two cells, in the bar-and-hinge
model: the moment against the deflection angle in the extended and the contracted state.
The slopes are the bending stiffness K_B of each state, and their ratio is what makes the
cell a stiffness-switching joint.
"""

import matplotlib.pyplot as plt

from kresling import Design
from kresling.analyses import bending_stiffness
from kresling.analyses.plots import plot_moment_angle

design = Design(n=8, lam=0.8, Lc=30.0)
comparison = bending_stiffness(design)          # the thesis's 5 mm protocol, both states
print(f"K_B extended  = {comparison.extended.stiffness:.3f} N*m/rad")
print(f"K_B contracted = {comparison.contracted.stiffness:.3f} N*m/rad")
print(f"ratio = {comparison.ratio:.2f}")

plot_moment_angle(comparison, title="n = 8, lambda = 0.8, Lc = 30 mm")
plt.show()
