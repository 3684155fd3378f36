"""Time the lowest vibration modes of Miura-ori sheets from 1,000 to 100,000 DOFs.

Each sheet (N5B8, a manual calibration, PET's density and a 0.3 mm sheet) is held along its
x = 0 edge; the table gives the free DOFs, the time to assemble the tangent, the time of
the shift-invert eigen-solve of the lowest ``--modes`` modes (best of ``--repeat``), the
lowest frequency and the largest backward error ``|K phi - omega^2 M phi| / (|K| |phi|)``
(infinity norms).
Run: ``python benchmarks/modes.py [--modes 10] [--repeat 1] [--sizes 1e3,1e4,1e5]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from kresling.analyses.modes import vibration_modes
from kresling.assembly import assemble
from kresling.io.miura import miura_sheet
from kresling.model import ManualProperties, build_pattern_model
from kresling.model.masses import PET_DENSITY, lumped_masses


def sheet(dofs):
    """A square Miura sheet of about ``dofs`` DOFs (N5B8: about 2 m^2 nodes for m x m)."""
    m = max(2, int(round(np.sqrt(dofs / 6.0))))
    pattern = miura_sheet(m, m)
    pm = build_pattern_model(pattern, material=ManualProperties(
        bar_modulus=3e3, bar_area=1.0, fold_stiffness=0.05, bend_stiffness=0.5))
    nodes = pm.model.nodes
    fixed = np.zeros(nodes.shape, dtype=bool)
    fixed[np.isclose(nodes[:, 0], nodes[:, 0].min())] = True
    return pm.with_supports(fixed)


def row(dofs, k, repeat):
    pm = sheet(dofs)
    model = pm.model
    masses = lumped_masses(pm, 0.3, PET_DENSITY)
    start = time.perf_counter()
    K = assemble(model).stiffness
    t_assemble = time.perf_counter() - start
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        modes = vibration_modes(model, masses, k=k)
        times.append(time.perf_counter() - start)
    free = np.asarray(model.free_dofs)
    phi = modes.shapes[:, free].T
    Kf = K.tocsc()[free][:, free]
    Kphi = Kf @ phi
    residual = np.abs(Kphi - np.repeat(masses, 3)[free][:, None] * phi * modes.eigenvalues)
    # Backward error: the residual over |K|_inf |phi|_inf (K mixes stiff bars and soft
    # hinges, so K phi of a low mode is a cancellation far below |K| |phi|).
    scale = abs(Kf).sum(axis=1).max() * np.abs(phi).max(axis=0)
    worst = float((residual.max(axis=0) / scale).max())
    return free.size, t_assemble, min(times), modes.frequencies_hz[0], worst


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--modes", type=int, default=10)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--sizes", default="1e3,3e3,1e4,3e4,1e5")
    args = parser.parse_args(argv)
    print(f"{'free DOFs':>10} {'assemble s':>11} {'modes s':>9} {'f1 Hz':>10} "
          f"{'residual':>9}")
    for size in (float(s) for s in args.sizes.split(",")):
        dofs, t_a, t_m, f1, worst = row(size, args.modes, args.repeat)
        print(f"{dofs:>10} {t_a:>11.3f} {t_m:>9.3f} {f1:>10.4g} {worst:>9.1e}", flush=True)


if __name__ == "__main__":
    main()
