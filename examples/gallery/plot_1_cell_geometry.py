"""
The geometry of a cell
======================

The thesis's optimal cell (n = 10, lambda = 0.9, Lc = 15 mm, R = 30 mm): its derived lengths
and angles, its two stable states, and the truss path between them along which the mountain
creases stretch and come back to their rest length (the bistability).
"""

import matplotlib.pyplot as plt

import kresling
from kresling.plots import plot_cell, plot_kinematic_path

design = kresling.Design(n=10, lam=0.9, Lc=15.0, R=30.0)
print(f"extended height Le = {design.Le:.3f} mm (contracted Lc = {design.Lc:g} mm)")
print(f"twist alpha0 = {design.alpha0:.4f} rad (contracted), "
      f"alpha_e = {design.alpha_e:.4f} rad (extended)")
print(f"facet angle Psi: {design.psi_con:.4f} rad contracted, {design.psi_ext:.4f} rad "
      f"extended (ratio {design.psi_ratio:.2f})")

# %%
# Both stable states in 3D: valley creases solid blue, mountain creases dashed red.
fig = plt.figure(figsize=(9, 4.5))
for column, state in enumerate(("contracted", "extended"), start=1):
    plot_cell(design, state, fig.add_subplot(1, 2, column, projection="3d"))

# %%
# Between the states, as a pin-jointed truss: the valley bars keep their length, the
# mountain bars stretch (eqn 9) and return to ``Mg`` at the other state.
plot_kinematic_path(design)
plt.show()
