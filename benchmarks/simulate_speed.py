"""Speed of ``kresling simulate`` on MERLIN2 v1.1's own example problems.

For each example under tests/data/merlin2_examples/ (the problem file and MERLIN2's run of
it under GNU Octave on a 2-core machine of this project's size), and the Miura-ori sheet of
examples/miura_bending, prints the model's size, MERLIN2's path-analysis wall time as it
recorded it (meta.txt), our time for the same path (model building included; outputs not
written) and the ratio; then, side by side, the time to write every output of the run
(history.csv, displacements.csv, path.fold, summary.json, view.html) against the solve's,
and the files' sizes. With ``--octave DIR`` where
DIR holds MERLIN2 v1.1's source and ``octave-cli`` is installed, MERLIN2 is also timed live,
side by side in this run (its PathAnalysis, after its PrepareData; no plotting).

Then the whole command from the shell: ``kresling simulate PROBLEM.toml`` as a process
(reading, building, solving and writing every output) minus the start-up of a command that
computes nothing (``kresling design``: the interpreter, numpy and the package), against
MERLIN2's PathAnalysis time (live when timed, else recorded; the Miura sheet has a live time
only, posed to MERLIN2 from the same files), with the goal of 20x; and the outputs' cost
beside the solve's, goal <= 1.

Times are best of ``--repeat`` runs. Run: ``python benchmarks/simulate_speed.py``.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import shutil
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

from kresling.simulate import load_problem, simulate

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "tests" / "data" / "merlin2_examples"
#: Further problems timed with their outputs (no MERLIN2 run of their own).
MORE = [ROOT / "examples" / "miura_bending" / "problem.toml"]


def recorded_seconds(case: Path) -> float:
    for line in (case / "meta.txt").read_text().splitlines():
        if line.startswith("pathanalysis_wall_s="):
            return float(line.split("=", 1)[1])
    return float("nan")


def variants(problem: Path):
    """The problem as posed (label: its folder's name), and for displacement control also
    with its fixed increments started from a cubic extrapolation of the path and with
    adaptive increments (the same samples; labels suffixed " cubic" and " adaptive")."""
    posed = load_problem(problem)
    yield problem.parent.name, posed
    if posed.analysis.method == "displacement_control":
        for suffix, change in ((" cubic", {"predictor": "cubic"}),
                               (" adaptive", {"increments": "adaptive"})):
            analysis = dataclasses.replace(posed.analysis, **change)
            yield problem.parent.name + suffix, dataclasses.replace(posed, analysis=analysis)


def ours(problem, repeat: int):
    best, sim = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        sim = simulate(problem, progress=False)
        best = min(best, time.perf_counter() - start)
    return best, sim


# MERLIN2 driven from its own input files: its model building, then its path analysis timed.
_OCTAVE_DRIVER = """
addpath('{merlin}'); cd('{case}');
Node = dlmread('input_nodes.csv'); P = dlmread('panels.csv'); Panel = {{}};
for i = 1:size(P,1), r = P(i,:); Panel{{i,1}} = r(r > 0); end
fixed = dlmread('fixed_dofs.csv'); load_vec = dlmread('load.csv');
m = size(Node,1); S = zeros(m,4); S(:,1) = (1:m)';
S(ceil(fixed/3) + m*(mod(fixed-1,3)+1)) = 1; Supp = S(any(S(:,2:4),2),:);
L = reshape(load_vec(1:3*m),3,[])'; idx = find(any(L,2)); Load = [idx, L(idx,:)];
{options}
[truss, angles, opt] = PrepareData(Node,Panel,Supp,Load,opt);
truss.U0 = zeros(3*size(truss.Node,1),1);
tic; [U,F] = PathAnalysis(truss,angles,opt); t = toc; printf('SECONDS %.6f\\n', t);
"""

_OCTAVE_OPTIONS = {
    "polygon_N5B8_auto": "opt = struct('ModelType','N5B8','MaterCalib','auto','ModElastic',5e3,"
                         "'Poisson',0.35,'Thickness',0.127,'LScaleFactor',3,'LoadType','Force',"
                         "'InitialLoadFactor',1e-5,'MaxIcr',100,'StopCriterion',"
                         "@(Node,U,icrm) abs(U(15))>12);",
    "kresling_folding": "opt = struct('ModelType','N4B5','MaterCalib','manual','BarCM',"
                        "@(Ex)Ogden(Ex,5e3),'Abar',0.1,'Kf',1e-3,'RotSprFold',"
                        "@(he,h0,kf,L0)EnhancedLinear(he,h0,kf,L0,45,315),'LoadType','Force',"
                        "'InitialLoadFactor',0.032,'MaxIcr',180);",
    # Displacement loading: the driver's Load row [59, 0, -30, 0] is the total prescribed
    # motion (load.csv holds it), taken in DispStep steps by MERLIN2's step rule.
    "gmiura_pointload": "opt = struct('ModelType','N5B8','MaterCalib','auto','ModElastic',1e3,"
                        "'Poisson',0.3,'Thickness',0.25,'LScaleFactor',2,"
                        "'LoadType','Displacement','DispStep',200);",
    # examples/miura_bending: the same sheet calibration and laws (our defaults for
    # calibration = "auto" are MERLIN2's: Ogden bars, super-linear bends, enhanced-linear
    # folds at 45/315 deg, its length scale), the corner driven -20 mm in z in 50 steps.
    "miura_bending": "opt = struct('ModelType','N5B8','MaterCalib','auto','ModElastic',1e3,"
                     "'Poisson',0.3,'Thickness',0.25,'LoadType','Displacement',"
                     "'DispStep',50);",
}


def merlin2_inputs(problem: Path, folder: Path) -> Path:
    """MERLIN2's input files (input_nodes.csv, panels.csv, fixed_dofs.csv, load.csv, as in
    tests/data/merlin2_examples/) of a problem on an OBJ pattern whose vertices are its
    nodes, written into ``folder`` (named as the problem's folder, for its options)."""
    posed = load_problem(problem)
    pattern = problem.parent / tomllib.loads(problem.read_text())["pattern"]["file"]
    vertices, faces = [], []
    for line in pattern.read_text().splitlines():
        words = line.split()
        if words and words[0] == "v":
            vertices.append([float(w) for w in words[1:4]])
        elif words and words[0] == "f":
            faces.append([int(w.split("/")[0]) for w in words[1:]])
    folder.mkdir(parents=True, exist_ok=True)
    np.savetxt(folder / "input_nodes.csv", vertices, delimiter=",", fmt="%.17g")
    width = max(map(len, faces))
    np.savetxt(folder / "panels.csv", [f + [0] * (width - len(f)) for f in faces],
               delimiter=",", fmt="%d")
    fixed = sorted(3 * s.node + "xyz".index(a) + 1 for s in posed.supports for a in s.axes)
    np.savetxt(folder / "fixed_dofs.csv", fixed, fmt="%d")
    load = np.zeros(3 * len(vertices))
    for entry in posed.loads:
        for node in entry.nodes:
            load[3 * node:3 * node + 3] = entry.vector
    np.savetxt(folder / "load.csv", load, fmt="%.17g")
    return folder


def octave_seconds(merlin: Path, case: Path) -> float:
    """MERLIN2's PathAnalysis wall time [s] on ``case`` (a folder of its input files), or NaN
    without Octave or options for that case."""
    options = _OCTAVE_OPTIONS.get(case.name)
    if options is None or shutil.which("octave-cli") is None:
        return float("nan")
    script = _OCTAVE_DRIVER.format(merlin=merlin, case=case, options=options)
    with tempfile.TemporaryDirectory() as tmp:
        driver = Path(tmp) / "driver.m"
        driver.write_text(script)
        shim = Path(tmp) / "optimoptions.m"  # Octave lacks optimoptions; fminunc takes optimset
        shim.write_text("function o = optimoptions(varargin)\n  o = optimset();\nend\n")
        out = subprocess.run(["octave-cli", "--no-gui", "-q", "--eval",
                              f"addpath('{tmp}'); run('{driver}')"], capture_output=True,
                             text=True, timeout=600)
    for line in out.stdout.splitlines():
        if line.startswith("SECONDS"):
            return float(line.split()[1])
    return float("nan")


def rows(repeat: int, octave):
    """Per example and variant: (label, simulation, MERLIN2's recorded s, live s or NaN,
    ours s, ratio of MERLIN2's time, live if timed, to ours)."""
    for problem in sorted(EXAMPLES.glob("*/problem.toml")):
        case = problem.parent
        live = octave_seconds(octave, case) if octave else float("nan")
        recorded = recorded_seconds(case)
        reference = live if live == live else recorded
        for label, posed in variants(problem):
            seconds, sim = ours(posed, repeat)
            yield label, sim, recorded, live, seconds, reference / seconds


def outputs(problem, repeat: int):
    """(increments, solve s, streamed s, write s, {file: bytes}), each time the best of
    ``repeat``, measured alternately in one run: the run alone, the run writing its files as
    it goes (as ``kresling simulate`` runs it), and the files written whole at its end. The
    first write packs plotly's JavaScript once (about 0.3 s; kept in a cache file), so one
    write is made before the timed ones."""
    solve, streamed, write = float("inf"), float("inf"), float("inf")
    with tempfile.TemporaryDirectory() as tmp:
        simulate(problem, progress=False).write(Path(tmp) / "warm")
        for k in range(repeat):
            start = time.perf_counter()
            simulate(problem, progress=False)
            solve = min(solve, time.perf_counter() - start)
            start = time.perf_counter()
            sim = simulate(problem, progress=False, stream=Path(tmp) / str(k))
            streamed = min(streamed, time.perf_counter() - start)
            start = time.perf_counter()
            written = sim.write(Path(tmp) / str(k))
            write = min(write, time.perf_counter() - start)
        sizes = {name: path.stat().st_size for name, path in written.items()}
    return sim.path.num_steps, solve, streamed, write, sizes


def print_outputs(repeat: int):
    print(f"\n{'example':<26} {'incr':>5} {'solve s':>8} {'stream s':>8} {'write s':>8} "
          f"{'ratio':>6} {'view MB':>7} {'fold MB':>7} {'csv MB':>7}")
    for problem in sorted(EXAMPLES.glob("*/problem.toml")) + MORE:
        steps, solve, streamed, write, sizes = outputs(problem, repeat)
        csv = (sizes["history"] + sizes["displacements"]) / 1e6
        stream = max(streamed - solve, 0.0)
        print(f"{problem.parent.name:<26} {steps:>5} {solve:>8.4f} {stream:>8.4f} {write:>8.4f} "
              f"{(stream + write) / solve:>6.2f} {sizes.get('view', 0) / 1e6:>7.3f} "
              f"{sizes['fold'] / 1e6:>7.3f} {csv:>7.3f}")
    print("\nsolve s: simulate() (model and path); stream s: what writing the files as the "
          "path goes adds to it (as kresling simulate runs); write s: Simulation.write() of "
          "every file at the end; ratio: the outputs (stream + write) over the solve (goal: "
          "<= 1).")


#: A command that computes nothing: its process is the interpreter's, numpy's and the
#: package's start-up, which the whole commands below are timed beyond.
BASELINE = ["design", "--n", "10", "--lam", "0.9", "--Lc", "15", "--R", "30"]


def process_seconds(args) -> float:
    """Wall time [s] of ``python -m kresling ARGS`` (its standard output discarded)."""
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "kresling", *args], check=True,
                   stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def command_rows(repeat: int, octave):
    """Per example: (label, MERLIN2's PathAnalysis s, whether live, our process s, the
    baseline's s, ratio). MERLIN2 runs first, then our command and the baseline alternately,
    best of ``repeat`` each."""
    problems = sorted(EXAMPLES.glob("*/problem.toml")) + MORE
    with tempfile.TemporaryDirectory() as tmp:
        for problem in problems:
            case = problem.parent
            if case in [m.parent for m in MORE]:
                case = merlin2_inputs(problem, Path(tmp) / "merlin2" / case.name)
                recorded = float("nan")
            else:
                recorded = recorded_seconds(case)
            live = octave_seconds(octave, case) if octave else float("nan")
            merlin2 = live if live == live else recorded
            ours, baseline = float("inf"), float("inf")
            for k in range(repeat):
                ours = min(ours, process_seconds(["simulate", str(problem), "--quiet", "--out",
                                                  str(Path(tmp) / f"{case.name}{k}")]))
                baseline = min(baseline, process_seconds(BASELINE))
            yield (problem.parent.name, merlin2, live == live, ours, baseline,
                   merlin2 / (ours - baseline))


def print_commands(repeat: int, octave):
    print(f"\nload average {os.getloadavg()[0]:.2f} (2 cores)")
    print(f"{'example':<26} {'MERLIN2 s':>10} {'':>8} {'process s':>10} {'start-up s':>10} "
          f"{'ratio':>7}")
    for label, merlin2, live, ours, baseline, ratio in command_rows(repeat, octave):
        print(f"{label:<26} {merlin2:>10.3f} {'live' if live else 'recorded':>8} {ours:>10.3f} "
              f"{baseline:>10.3f} {ratio:>6.1f}x")
    print("\nMERLIN2 s: its PathAnalysis (live with --octave, else as recorded); process s: "
          "kresling simulate PROBLEM.toml as a whole process, every output written; start-up "
          "s: kresling design's process, a command that computes nothing; ratio: MERLIN2 over "
          "(process minus start-up), goal >= 20x.")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--octave", type=Path, metavar="DIR",
                        help="MERLIN2 v1.1's source folder, to time it live under Octave")
    args = parser.parse_args(argv)
    print(f"{'example':<26} {'nodes':>5} {'bars':>5} {'hinges':>6} {'incr':>5} "
          f"{'MERLIN2 s':>10} {'live s':>8} {'ours s':>8} {'ratio':>7}")
    for label, sim, recorded, live, seconds, ratio in rows(args.repeat, args.octave):
        m = sim.model
        print(f"{label:<26} {m.num_nodes:>5} {len(m.bars):>5} {len(m.hinges):>6} "
              f"{sim.path.num_steps:>5} {recorded:>10.3f} {live:>8.3f} {seconds:>8.4f} "
              f"{ratio:>7.0f}")
    print("\nMERLIN2 s: its path-analysis time as recorded with the reference run; live s: "
          "timed now (with --octave); ratio: MERLIN2 (live if timed) over ours. 'cubic': the "
          "same increments, each Newton solve started from a cubic extrapolation of the path; "
          "'adaptive': the same samples, the path between them in adaptive increments.")
    print_outputs(args.repeat)
    print_commands(args.repeat, args.octave)


if __name__ == "__main__":
    main()
