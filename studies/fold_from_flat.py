"""How two public crease patterns leave the flat state when all their creases are driven at
once (docs/folding.md, 'Folding from flat'): creases folded the other way, whether the path
depends on its increments, and whether states with stiffer creases lead back to the model.

Rabbit Ear's crane (its crease-pattern frame, to 10, 30 and 60 % of its +-180 deg) and
Origami Simulator's flapping bird (to 10, 30 and 60 % of its targets), with stiff bars
(1e5 N/mm^2) and panels as stiff in bending as the creases in folding, the first panel's
corners held. The columns:

- ``other way``: the summary's ``fold.left_branch`` (model hinges more than 1 deg the other
  way from their target); ``by faces``: creases whose fold angle from the faces' normals is
  more than 1 deg the other way;
- ``x10 steps``: the largest difference [mm] of the end state folded in ten times as many
  increments (one path: rounding and Newton's tolerance);
- ``unstable``: the largest number of negative eigenvalues of the tangent on the path;
- ``energy``: the stored energy at the end [N mm];
- ``stiffer creases``: folded with the driven creases ``g`` times stiffer, the other-way
  count, the stiffness factor at which following that state back to the creases' own
  stiffness (30 geometric steps) lost it (Newton failed) or ``1`` if it got there, and the
  other-way counts (model hinges / by faces) and the energy where it ended (``-`` if lost).

Run: ``python studies/fold_from_flat.py`` (about ten seconds).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from kresling.io import fold_angles, read_fold, read_pattern
from kresling.model.fold_angles import fold_angles_deg
from kresling.simulate import simulate
from kresling.solvers import solve_fold

PUBLIC = Path(__file__).resolve().parent.parent / "tests" / "data" / "public"
STIFF = {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
         "fold_stiffness": 1.0, "bend_stiffness": 1.0}


def crane(fraction):
    """The crane's problem keys and per-edge targets [deg] at `fraction` of +-180."""
    path = PUBLIC / "rabbit_ear" / "crane.fold"
    keys = {"file": str(path), "unit": "unit", "scale": 100.0, "frame": 1}
    letters = np.array(read_fold(path, unit="unit", scale=100.0).edges_assignment)
    return keys, fraction * np.where(letters == "M", -180.0, 180.0)


def bird(fraction):
    """The flapping bird's problem keys and per-edge targets [deg] at `fraction`."""
    path = PUBLIC / "origami_simulator" / "flappingBird.svg"
    return {"file": str(path)}, fraction * np.nan_to_num(read_pattern(path).edges_fold_angle)


def fold_problem(keys, targets, steps):
    """Every M and V crease to its target, the first panel's corners held."""
    pattern = read_pattern(keys["file"], **{k: keys[k] for k in ("unit", "scale", "frame")
                                           if k in keys})
    actuation = [{"edges": [edge], "fold_angle_deg": float(target)}
                 for edge, letter, target in zip(pattern.edges.tolist(),
                                                 pattern.edges_assignment, targets)
                 if letter in "MV"]
    problem = {"pattern": keys, "material": STIFF, "laws": {"fold_limits_deg": [1.0, 359.0]},
               "support": [{"nodes": list(pattern.faces[0][:3]), "fix": "xyz"}],
               "actuation": actuation, "analysis": {"method": "fold", "steps": steps}}
    return pattern, problem


def by_faces(pattern, sim, targets, u):
    """Creases whose fold angle from the faces' normals is > 1 deg the other way."""
    x = (sim.model.nodes + u.reshape(-1, 3))[:pattern.num_vertices]
    creases = np.array([a in "MV" for a in pattern.edges_assignment])
    reached = np.degrees(fold_angles(pattern.faces, pattern.edges, x))[creases]
    wanted = np.sign(np.asarray(targets)[creases])
    return int(np.sum((np.sign(reached) != wanted) & (np.abs(reached) > 1.0)))


def other_way(sim, u):
    """As the summary's fold.left_branch, at displacement u."""
    plan = sim.fold
    reached = fold_angles_deg(sim.pattern_model, u, plan.signs)[plan.hinges]
    return int(np.sum((np.sign(reached) * np.sign(plan.target_deg) < 0) & (np.abs(reached) > 1)))


def stiffer_creases(sim, pattern, targets, steps, factor, softening_steps=30):
    """Fold with the driven creases `factor` times stiffer, then follow that state back to
    their own stiffness: (other-way count there, the factor at which it was lost or 1, the
    other-way count, by hinges and by faces, and the energy [N mm] where it ended)."""
    model = sim.model
    hinges, rest_targets = sim.fold.stages[0]
    hinges = np.asarray(hinges)
    own = np.asarray(model.hinge_stiffness)

    def with_factor(g):
        stiffness = own.copy()
        stiffness[hinges] *= g
        return model.replace(hinge_stiffness=stiffness)

    guided = solve_fold(with_factor(factor), [(hinges, rest_targets)], steps)
    if not guided.completed:
        return None, factor, None, None, None
    u = guided.displacement[-1]
    count = other_way(sim, u)
    rest = np.asarray(model.hinge_rest_angle).copy()
    rest[hinges] = rest_targets
    for g in np.geomspace(factor, 1.0, softening_steps)[1:]:
        # One equilibrium solve of the softened model from the last state: a stage that
        # drives one crease to where it already rests changes nothing else.
        softened = with_factor(g).replace(hinge_rest_angle=rest)
        step = solve_fold(softened, [(hinges[:1], rest[hinges[:1]])], 1, initial=u)
        if not step.completed:
            return count, g, other_way(sim, u), by_faces(pattern, sim, targets, u), None
        u = step.displacement[-1]
    return (count, 1.0, other_way(sim, u), by_faces(pattern, sim, targets, u),
            float(step.energy[-1]))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps-per-tenth", type=int, default=10,
                        help="increments per 10 %% of the targets (default 10)")
    args = parser.parse_args(argv)
    print(f"{'pattern':8s} {'fold':>5s} {'steps':>5s} {'other way':>9s} {'by faces':>8s} "
          f"{'x10 steps':>10s} {'unstable':>8s} {'energy':>8s}  stiffer creases (g: count, "
          f"lost at, counts and energy there)")
    for name, case in (("crane", crane), ("bird", bird)):
        for fraction in (0.1, 0.3, 0.6):
            keys, targets = case(fraction)
            steps = max(1, round(args.steps_per_tenth * fraction * 10))
            pattern, problem = fold_problem(keys, targets, steps)
            sim = simulate(problem, progress=False)
            problem["analysis"]["steps"] = 10 * steps
            finer = simulate(problem, progress=False)
            u = sim.path.displacement[-1]
            difference = np.abs(finer.path.displacement[-1] - u).max()
            guided = [stiffer_creases(sim, pattern, targets, steps, g) for g in (10.0, 1000.0)]
            print(f"{name:8s} {100 * fraction:4.0f}% {steps:5d} {other_way(sim, u):9d} "
                  f"{by_faces(pattern, sim, targets, u):8d} {difference:10.1e} "
                  f"{int(np.max(sim.path.negative_eigenvalues)):8d} {sim.path.energy[-1]:8.4g}  "
                  + "; ".join(f"{g:g}: {c}, {lost:.3g}, {end}/{faces}, "
                              + ("-" if energy is None else f"{energy:.4g}")
                              for g, (c, lost, end, faces, energy) in zip((10, 1000), guided)))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
