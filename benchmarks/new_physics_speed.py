"""The new physics' cost beside the static solver's, side by side in one run.

On Miura-ori sheets (kresling.io.miura, flat, N5B8, manual stiff bars and soft folds) of a
few sizes, with one panel held:
- a fold (every crease to its rigidly folded angle, ``solve_fold``) against displacement
  control of the same sheet (one corner lifted), the same number of increments: time per
  increment and per Newton iteration;
- an implicit time step (``solve_dynamics``, average acceleration) against a static
  Newton iteration (force control) on the same sheet;
- an explicit time step (central differences, at 0.9 of the stable step, every 100th step
  recorded) per element (bars and hinges) and step, beside the stable step's estimate.
Iterations count every Newton iteration, of rejected attempts too; the times include each
solver's set-up (pattern, symbolic factorisation), which the small sheets feel most.
Run: ``python benchmarks/new_physics_speed.py [--repeat 3]``.
"""

from __future__ import annotations

import argparse
import dataclasses

import numpy as np

from kresling.io.miura import miura_sheet
from kresling.model import CreaseLaws, HingeLaw, ManualProperties, build_pattern_model
from kresling.solvers import (fold, solve_displacement_control, solve_dynamics,
                              solve_force_control, stable_time_step)
from solver_speed import best_time  # the same timing as the other benchmarks

MATERIAL = ManualProperties(bar_modulus=1e5, bar_area=1.0, fold_stiffness=1.0,
                            bend_stiffness=1.0)


def sheet(size):
    flat = miura_sheet(size, size, fold_angle=0.0)
    folded = miura_sheet(size, size, fold_angle=30.0)
    pattern = dataclasses.replace(flat, edges_assignment=folded.edges_assignment)
    fixed = np.zeros((pattern.num_vertices + len(pattern.faces), 3), bool)
    fixed[list(pattern.faces[0][:3])] = True
    pm = build_pattern_model(pattern, material=MATERIAL, fixed=fixed,
                             laws=CreaseLaws(fold=HingeLaw(limits_deg=(5.0, 355.0))))
    by_edge = {tuple(sorted(e)): a for e, a in zip(folded.edges.tolist(),
                                                   folded.edges_fold_angle)}
    targets = {h: by_edge[tuple(sorted(pm.model.hinges[h][:2].tolist()))]
               for h, f in enumerate(pm.hinge_family) if f != "bend"}
    return pattern, pm, targets


def main(repeat):
    steps = 40
    print(f"Per increment and per Newton iteration, {steps} increments, best of {repeat}.")
    print(f"{'DOFs':>6} {'fold ms/incr':>13} {'DC ms/incr':>11} {'ratio':>6} "
          f"{'fold ms/it':>11} {'DC ms/it':>9} {'ratio':>6} {'dyn ms/step':>12} "
          f"{'static ms/it':>13} {'ratio':>6}")
    for size in (4, 8, 16):
        pattern, pm, targets = sheet(size)
        model = pm.model
        t_fold, r_fold = best_time(lambda: fold(pm, targets, steps), repeat)
        lift = np.zeros(model.num_dofs)
        lift[3 * (pattern.num_vertices - 1) + 2] = 5.0
        t_dc, r_dc = best_time(lambda: solve_displacement_control(model, lift, steps), repeat)
        force = np.zeros(model.num_dofs)
        force[3 * (pattern.num_vertices - 1) + 2] = 1e-3
        t_fc, r_fc = best_time(lambda: solve_force_control(model, force, steps), repeat)
        masses = np.full(model.num_nodes, 1e-6)
        t_dyn, r_dyn = best_time(lambda: solve_dynamics(model, masses, 1e-3, steps * 1e-3,
                                                        forces=force), repeat)
        # Every Newton iteration, of rejected attempts too (the time is theirs as well).
        it_fold = max(int(r_fold.path.newton_iterations), 1)
        it_dc = max(int(r_dc.newton_iterations), 1)
        it_fc = max(int(r_fc.newton_iterations), 1)
        n_fold, n_dc = max(r_fold.path.num_steps, 1), max(r_dc.num_steps, 1)
        n_dyn = max(r_dyn.path.num_steps, 1)
        a, b = 1e3 * t_fold / n_fold, 1e3 * t_dc / n_dc
        c, d = 1e3 * t_fold / it_fold, 1e3 * t_dc / it_dc
        e, f = 1e3 * t_dyn / n_dyn, 1e3 * t_fc / it_fc
        print(f"{model.num_dofs:>6} {a:>13.3f} {b:>11.3f} {a / b:>6.2f} {c:>11.3f} {d:>9.3f} "
              f"{c / d:>6.2f} {e:>12.3f} {f:>13.3f} {e / f:>6.2f}")


def explicit_table(repeat, steps=2000):
    """The explicit scheme's cost per element and step on the sheets."""
    print(f"\nExplicit central differences, {steps} steps at 0.9 of the stable step, best of "
          f"{repeat}.")
    print(f"{'DOFs':>6} {'elements':>9} {'stable dt [s]':>14} {'estimate ms':>12} "
          f"{'us/step':>9} {'us/element/step':>16}")
    for size in (4, 8, 16, 32):
        _, pm, _ = sheet(size)
        model = pm.model
        masses = np.full(model.num_nodes, 1e-6)
        t_est, stable = best_time(lambda: stable_time_step(model, masses), repeat)
        dt = 0.9 * stable.time_step
        force = np.zeros(model.num_dofs)
        force[-1] = 1e-3
        t_run, run = best_time(lambda: solve_dynamics(model, masses, dt, steps * dt,
                                                      forces=force, scheme="explicit",
                                                      record_every=100), repeat)
        assert run.completed, run.path.message
        elements = len(model.bars) + len(model.hinges)
        per_step = 1e6 * (t_run - t_est) / steps    # the run estimates the step once too
        print(f"{model.num_dofs:>6} {elements:>9} {stable.time_step:>14.4g} {1e3 * t_est:>12.3f} "
              f"{per_step:>9.2f} {per_step / elements:>16.4f}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    arguments = parser.parse_args()
    main(arguments.repeat)
    explicit_table(arguments.repeat)
