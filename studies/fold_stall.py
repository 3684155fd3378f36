"""Why Origami Simulator's traditional crane and flapping bird stop folding at 53 and 56 %
(docs/folding.md, 'Where a fold stops: the crane and the flapping bird').

For each pattern, folded as a new user folds it (nothing but the pattern: Origami
Simulator's material, relaxed increments):

- ``path``: the fold's message (where it ends, the limit point, the squashed and the
  collapsed triangle: kresling.simulate.fold_stall);
- ``squash``: the height of the triangle squashed furthest at the end, as a fraction of its
  flat height, at every fifth increment;
- ``kink``: the stored energy by family along the straight line from the last equilibrium to
  where a descent (L-BFGS) of the energy one increment further ends, and that triangle's
  height on it;
- ``stiffer``: the same fold with the face-angle springs (``--face``) or the bars (``--bars``)
  that many times the preset's: where it ends, creases more than 1 deg short;
- with ``--simulator``: Origami Simulator's model (kresling/testing/origami_simulator.py)
  with the targets raised to ``--percent`` over ``--ramp`` steps: whether it comes to rest,
  the creases more than 1 deg from their targets, those turned past flat (faces through each
  other) and the largest obtuse corner of a triangle (180 deg: flattened to a line). Minutes.

Run: ``python studies/fold_stall.py [--assets DIR] [--simulator] [--percent 1.0]
[--ramp 100000] [--steps 250000]``; the patterns are the repository's copies of Origami
Simulator's drawings unless ``--assets`` names its assets folder.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from scipy.optimize import minimize

from kresling import solvers
from kresling.assembly import Workspace, assemble
from kresling.io import read_pattern
from kresling.simulate import simulate
from kresling.simulate.fold_stall import squashed_triangle
from kresling.testing import origami_simulator as osm

PUBLIC = Path(__file__).resolve().parent.parent / "tests" / "data" / "public" / "origami_simulator"
NAMES = {"crane": "traditionalCrane.svg", "bird": "flappingBird.svg"}


def problem(path, material=None):
    out = {"pattern": {"file": str(path)},
           "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
           "analysis": {"method": "fold", "relax": True}}
    if material:
        out["material"] = material
    return out


def kink(sim):
    """Energies along the line from the last equilibrium to a descent's end past it."""
    free = sim.model.free_dofs
    ahead = float(sim.path.load_factor[-1]) + 1.0 / sim.problem.analysis.steps
    model = solvers.fold_model_at(sim.model, sim.fold.stages, ahead)
    workspace = Workspace(model)
    start = sim.path.displacement[-1]

    def energy(z):
        u = start.copy()
        u[free] = z
        try:
            a = assemble(model, u, stiffness=False, workspace=workspace)
        except ValueError:
            return np.inf, np.zeros_like(z)
        return a.energy, a.force[free]

    end = start.copy()
    end[free] = minimize(energy, start[free], jac=True, method="L-BFGS-B",
                         options={"maxiter": 20000, "maxfun": 40000, "gtol": 1e-10,
                                  "ftol": 1e-15}).x
    triangle, _, _, _ = squashed_triangle(sim.pattern_model, end)
    nodes = np.asarray(sim.pattern_model.elements.nodes, dtype=float)
    print(f"  kink at {ahead:.4g}: triangle {triangle.tolist()}")
    for s in (0.0, 0.5, 0.9, 0.99, 0.999, 1.0):
        u = start + s * (end - start)
        a = assemble(model, u, stiffness=False, workspace=workspace)
        x = nodes + u.reshape(-1, 3)
        p, q, r = x[triangle]
        height = np.linalg.norm(np.cross(q - p, r - p)) / max(
            np.linalg.norm(q - p), np.linalg.norm(r - q), np.linalg.norm(p - r))
        families = ", ".join(f"{k} {v:.1f}" for k, v in a.energies.items() if v)
        print(f"    s = {s:<5g} height {height:9.4g} mm  {families} N mm")


def stiffer(path, name, face, bars):
    _, radius = osm.bounding_circle(read_pattern(path))
    material = {"calibration": "manual", "bar_modulus": bars * osm.AXIAL_STIFFNESS
                / osm.CREASE_STIFFNESS, "bar_area": 1.0, "fold_stiffness": 1.0,
                "bend_stiffness": 1.0,
                "face_stiffness": face * osm.FACE_STIFFNESS * radius / osm.CREASE_STIFFNESS}
    sim = simulate(problem(path, material), progress=False)
    report = sim.fold_report()
    print(f"  {name}, face springs x{face:g}, bars x{bars:g}: reached "
          f"{sim.path.load_factor[-1]:.4g}, {report['short_of_target']} of "
          f"{report['creases_driven']} creases more than 1 deg short")


def simulator(path, percent, ramp, steps):
    pattern = read_pattern(path)
    model = osm.build(pattern)
    run = osm.integrate(model, percent, steps=steps, ramp_steps=ramp)
    crease = model.hinge_is_crease & (model.hinge_target != 0)
    angle = np.degrees(osm.hinge_angles(model, run.x))[crease]
    target = np.degrees(model.hinge_target[crease]) * percent
    past = (np.sign(angle) != np.sign(target)) & (np.abs(angle) > 90)
    off = np.abs(np.degrees(run.theta[crease]) - target)
    corners = np.degrees(osm.corner_angles(model, run.x))
    print(f"  Origami Simulator's model to {percent:g} over {ramp} steps: at rest "
          f"{run.settled} after {run.steps}; {int(np.sum(off > 1))} of {crease.sum()} creases "
          f"more than 1 deg off (median {np.median(off):.2g}); turned past flat by "
          f"{np.round(np.sort(180 - np.abs(angle[past]))[::-1], 1).tolist()} deg; largest "
          f"corner {corners.max():.1f} deg")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--assets", type=Path, help="Origami Simulator's assets folder")
    parser.add_argument("--simulator", action="store_true")
    parser.add_argument("--percent", type=float, default=1.0)
    parser.add_argument("--ramp", type=int, default=100_000)
    parser.add_argument("--steps", type=int, default=250_000)
    parser.add_argument("--face", type=float, default=10.0)
    parser.add_argument("--bars", type=float, default=10.0)
    args = parser.parse_args(argv)
    for name, file in NAMES.items():
        path = args.assets / "Origami" / file if args.assets else PUBLIC / file
        sim = simulate(problem(path), progress=False)
        print(f"{name}: {sim.stall}")
        for k in range(4, sim.path.num_steps, 5):
            triangle, ratio, _, _ = squashed_triangle(sim.pattern_model, sim.path.displacement[k])
            print(f"  squash at {sim.path.load_factor[k]:.4g}: {triangle.tolist()} at "
                  f"{100 * ratio:.3g} % of its flat height")
        kink(sim)
        stiffer(path, name, args.face, 1.0)
        stiffer(path, name, 1.0, args.bars)
        if args.simulator:
            simulator(path, args.percent, args.ramp, args.steps)


if __name__ == "__main__":
    main()
