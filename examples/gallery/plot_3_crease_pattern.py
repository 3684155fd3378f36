"""
Simulating a crease pattern
===========================

Any crease pattern, not only a Kresling cell: a square sheet with one diagonal crease,
written as an OBJ file, three corners held and the fourth lifted 5 mm under displacement
control. The problem is a dict here; a TOML file with the same tables works the same way
(``kresling simulate problem.toml``).
"""

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt

from kresling.io import write_obj
from kresling.simulate import simulate

folder = Path(tempfile.mkdtemp())
write_obj(folder / "square.obj", [[0, 0, 0], [20, 0, 0], [20, 20, 0], [0, 20, 0]],
          [[0, 1, 2], [0, 2, 3]])
simulation = simulate({
    "pattern": {"file": str(folder / "square.obj")},     # one crease: the diagonal 0-2
    "material": {"calibration": "manual", "bar_modulus": 1e4, "bar_area": 1.0,
                 "fold_stiffness": 0.01},               # N/mm^2, mm^2, N*mm/rad per mm
    "support": [{"nodes": [0, 1, 2], "fix": "xyz"}],
    "load": [{"node": 3, "displacement": [0.0, 0.0, 5.0]}],
    "analysis": {"method": "displacement_control", "steps": 20},
}, progress=False)

columns = simulation.history_columns()
energy = simulation.element_histories().energy_by_family()
print(f"{len(columns['step'])} increments; final reaction "
      f"{columns['reaction_3_z'][-1]:.4f} N; energy in the fold "
      f"{energy['folds'][-1]:.4f} N*mm of {energy['total'][-1]:.4f} N*mm")

# %%
# The force that lifts the corner against its rise, and where the work goes: into the
# crease's fold hinge. (``reaction_3_z`` is the force the sheet exerts on the drive, as
# MERLIN2 reports it: negative while the corner is lifted.)
fig, (left, right) = plt.subplots(1, 2, figsize=(9, 3.5), layout="constrained")
rise = 5.0 * columns["load_factor"]       # the fraction of the prescribed 5 mm
left.plot(rise, -columns["reaction_3_z"], marker=".")
left.set_xlabel("corner 3 rise [mm]")
left.set_ylabel("lifting force at corner 3 [N]")
for family, values in energy.items():
    right.plot(rise, values, label=family, ls="--" if family == "total" else "-")
right.set_xlabel("corner 3 rise [mm]")
right.set_ylabel("stored energy [N*mm]")
right.legend()
plt.show()
