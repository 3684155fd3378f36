"""What panel-panel contact ([contact] self = true) adds to a fold whose panels touch.

The sheet is an accordion: ``pleats`` strips 1 mm wide and ``length`` mm long, each split
into 1 mm squares (two triangles each), creases alternately valley and mountain, folded to
170 deg. Near the end of the fold neighbouring strips close to 10 deg apart, so that the
free corner of each square comes within d_hat = 0.2 mm of the face across its crease
(1 mm x sin 10 deg = 0.17 mm): the barrier acts on thousands of pairs and the tangent's
pattern changes as they enter. The same fold is timed with and without contact, side by
side in this run, best of ``--repeat``; the table gives the model's size, the times, the
overhead and the pairs acting at the end, for the pairs' Hessians projected to be
positive semi-definite, exact, and adaptive (the default). The default sheet
has about 10,000 DOFs.

Run: ``python benchmarks/self_contact_speed.py [--pleats 66 --length 50 --steps 10]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from kresling.simulate import simulate

MATERIAL = {"calibration": "manual", "bar_modulus": 1e4, "bar_area": 1.0,
            "fold_stiffness": 1.0, "bend_stiffness": 10.0}


def accordion(pleats: int, length: int, steps: int, contact: bool,
              tangent: str = "projected") -> dict:
    """The problem of an accordion of ``pleats`` strips, ``length`` squares long."""
    columns = pleats + 1
    vertices = [[float(i), float(j), 0.0] for j in range(length + 1) for i in range(columns)]
    panels = [[j * columns + i, j * columns + i + 1, (j + 1) * columns + i + 1,
               (j + 1) * columns + i] for j in range(length) for i in range(pleats)]
    valleys = [[j * columns + i, (j + 1) * columns + i]
               for i in range(1, pleats, 2) for j in range(length)]
    mountains = [[j * columns + i, (j + 1) * columns + i]
                 for i in range(2, pleats, 2) for j in range(length)]
    middle = (length // 2) * columns + pleats // 2
    data = {"pattern": {"vertices": vertices, "panels": panels, "split": "N4B5"},
            "material": MATERIAL,
            "support": [{"nodes": [middle, middle + 1, middle + columns], "fix": "xyz"}],
            "actuation": [{"edges": valleys, "fold_angle_deg": 170.0},
                          {"edges": mountains, "fold_angle_deg": -170.0}],
            "analysis": {"method": "fold", "steps": steps, "tolerance": 1e-5}}
    if contact:
        data["contact"] = {"distance": 0.2, "self": True, "tangent": tangent}
    return data


def timed(problem: dict, repeat: int):
    best, sim = np.inf, None
    for _ in range(repeat):
        start = time.process_time()
        sim = simulate(problem, progress=False)
        best = min(best, time.process_time() - start)
    return best, sim


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pleats", type=int, default=66)
    parser.add_argument("--length", type=int, default=50)
    parser.add_argument("--steps", type=int, default=10)
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    plain_s, plain = timed(accordion(args.pleats, args.length, args.steps, False), args.repeat)
    print(f"| DOFs | triangles | steps | tangent | without contact [s] | with contact [s] "
          f"| overhead | Newton iterations (without / with) | pairs at the end "
          f"| min gap [mm] | completed |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for tangent in ("projected", "exact", "adaptive"):
        contact_s, sim = timed(accordion(args.pleats, args.length, args.steps, True, tangent),
                               args.repeat)
        final = sim.model.element_state(sim.path.displacement[-1])
        pairs = final["self_contact_segments"].size // 6
        print(f"| {sim.model.num_nodes * 3} | {len(sim.pattern_model.elements.triangles)} | "
              f"{args.steps} | {tangent} | {plain_s:.2f} | {contact_s:.2f} | "
              f"{100 * (contact_s / plain_s - 1):+.0f} % | "
              f"{plain.path.newton_iterations} / {sim.path.newton_iterations} | {pairs} | "
              f"{float(final['self_contact_gap'][0]):.3f} | "
              f"{plain.completed} / {sim.completed} |")


if __name__ == "__main__":
    main()
