"""Rabbit Ear's crane and Origami Simulator's flapping bird folded by Origami Simulator's model
(kresling/testing/origami_simulator.py: its equations written again), every target applied at
once from the flat sheet as the simulator does when it opens a pattern, and with its
ingredients switched one at a time (docs/folding.md, 'Folding from flat').

The crane to 10 % of its +-180 deg (its crease-pattern frame), the bird to 60 % of its
targets (the simulator's opening crease percent). Columns:

- ``variant``: ``simulator`` its defaults (bars 20 / L0, creases and facets 0.7 L0, face
  angles 0.2, damping 0.45, targets at once) on ear-clipped triangles; ``its triangles``
  the same on the simulator's own triangles (its importer run in Chromium:
  tests/origami_simulator_page.py); then on those, one ingredient switched: ``no face``
  without the face-angle springs, ``bars x10`` the bars 10 times stiffer, ``ramped`` the
  targets raised linearly over ``--ramp`` steps instead of at once;
- ``hinges``: driven hinges more than 1 deg the other way from their target, by the
  hinge's two triangles; ``faces``: creases more than 1 deg the other way by the
  pattern's polygon faces' normals (as tests/io/test_io_public_folds.py measures a fold);
- ``which``: those creases' pattern edges (by the faces);
- ``past 180``: hinges whose angle, followed from step to step, turned past +-180 deg
  (faces through each other);
- ``steps``, ``settled``: integration steps, and whether the kinetic energy per node fell
  under 1e-10 for 500 steps.

Run: ``python studies/origami_simulator_fold.py`` (several minutes: explicit dynamics).
"""

from __future__ import annotations

import argparse
import json
import tempfile
from pathlib import Path

import numpy as np

from kresling.io import fold_angles, read_fold, read_pattern
from kresling.testing import origami_simulator as osm
from kresling.testing.origami_simulator_page import simulators_triangles

#: The public crease patterns the repository's tests use (and their licences).
PUBLIC = Path(__file__).resolve().parent.parent / "tests" / "data" / "public"


def crane():
    path = PUBLIC / "rabbit_ear" / "crane.fold"
    letters = np.array(read_fold(path, unit="unit", scale=100.0).edges_assignment)
    pattern = read_fold(path, unit="unit", scale=100.0, frame=1)
    return pattern, np.where(letters == "M", -180.0, 180.0), 0.1


def bird():
    pattern = read_pattern(PUBLIC / "origami_simulator" / "flappingBird.svg")
    return pattern, np.nan_to_num(pattern.edges_fold_angle), 0.6


def other_way(pattern, model, run, targets):
    creases = np.array([a in "MV" for a in pattern.edges_assignment])
    wanted = np.sign(targets)
    faces = np.degrees(fold_angles(pattern.faces, pattern.edges, run.x))
    wrong_faces = np.flatnonzero(creases & (np.sign(faces) != wanted) & (np.abs(faces) > 1.0))
    hinge = np.degrees(osm.hinge_angles(model, run.x))[model.hinge_is_crease]
    hinge_target = model.hinge_target[model.hinge_is_crease]
    wrong_hinges = int(np.sum((np.sign(hinge) != np.sign(hinge_target)) & (np.abs(hinge) > 1.0)))
    past = int(np.sum(np.abs(run.theta) > np.pi))
    return wrong_hinges, wrong_faces, past


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ramp", type=int, default=50_000)
    parser.add_argument("--steps", type=int, default=400_000)
    parser.add_argument("--only", default="", help="comma-separated variant names")
    parser.add_argument("--patterns", default="crane,bird")
    parser.add_argument("--json", type=Path, help="also write the rows here")
    parser.add_argument("--save", type=Path, help="a folder for each run's end positions")
    args = parser.parse_args(argv)
    variants = {"simulator": ({}, 0), "no face": ({"face": 0.0}, 0),
                "bars x10": ({"axial": 10 * osm.AXIAL_STIFFNESS}, 0),
                "ramped": ({}, args.ramp)}
    only = set(filter(None, args.only.split(",")))
    rows = []
    print(f"{'pattern':8} {'variant':24} {'hinges':>6} {'faces':>5} {'past 180':>8} "
          f"{'steps':>7} {'settled':>7}  which (by the faces)")
    makers = {"crane": crane, "bird": bird}
    for name in args.patterns.split(","):
        make = makers[name]
        pattern, targets, percent = make()
        runs = [("simulator", {}, 0, osm.build(pattern, targets))]   # ear-clipped triangles
        svg = PUBLIC / "origami_simulator" / "flappingBird.svg" if name == "bird" else None
        triangles = simulators_triangles(pattern, Path(tempfile.mkdtemp()), svg)
        theirs = osm.build(pattern, targets, triangles)
        runs += [(label + " + its triangles" if change or ramp else "its triangles", change,
                  ramp, theirs) for label, (change, ramp) in variants.items()]
        for label, change, ramp, model in runs:
            if only and label not in only:
                continue
            stiffness = osm.Stiffness(**change)
            run = osm.integrate(model, percent, s=stiffness, steps=args.steps, ramp_steps=ramp)
            hinges, faces, past = other_way(pattern, model, run, targets)
            if args.save:
                args.save.mkdir(parents=True, exist_ok=True)
                np.save(args.save / f"{name}-{label.replace(' ', '_')}.npy", run.x)
            rows.append({"pattern": name, "variant": label, "hinges": hinges,
                         "faces": len(faces), "which": faces.tolist(), "past_180": past,
                         "steps": run.steps, "settled": run.settled})
            print(f"{name:8} {label:24} {hinges:6d} {len(faces):5d} {past:8d} {run.steps:7d} "
                  f"{str(run.settled):>7}  {faces.tolist()}", flush=True)
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
