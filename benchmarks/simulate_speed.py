"""Speed of ``kresling simulate`` on MERLIN2 v1.1's own example problems.

For each example under tests/data/merlin2_examples/ (the problem file and MERLIN2's run of
it under GNU Octave on a 2-core machine of this project's size), and the Miura-ori sheet of
examples/miura_bending, prints the model's size, MERLIN2's path-analysis wall time as it
recorded it (meta.txt), our time for the same path (model building included; outputs not
written) and the ratio; then, side by side, the time to write every output of the run
(history.csv, displacements.csv, path.fold, summary.json, view.html) against the solve's,
and the files' sizes. With ``--octave DIR`` where
DIR holds MERLIN2 v1.1's source and ``octave-cli`` is installed, MERLIN2 is also timed live,
side by side in this run (its model building and path analysis, no plotting).

Times are best of ``--repeat`` runs. Run: ``python benchmarks/simulate_speed.py``.
"""

from __future__ import annotations

import argparse
import dataclasses
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

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


# MERLIN2 driven from its own input files: model building and path analysis only.
_OCTAVE_DRIVER = """
addpath('{merlin}'); cd('{case}');
Node = dlmread('input_nodes.csv'); P = dlmread('panels.csv'); Panel = {{}};
for i = 1:size(P,1), r = P(i,:); Panel{{i,1}} = r(r > 0); end
fixed = dlmread('fixed_dofs.csv'); load_vec = dlmread('load.csv');
m = size(Node,1); S = zeros(m,4); S(:,1) = (1:m)';
S(ceil(fixed/3) + m*(mod(fixed-1,3)+1)) = 1; Supp = S(any(S(:,2:4),2),:);
L = reshape(load_vec(1:3*m),3,[])'; idx = find(any(L,2)); Load = [idx, L(idx,:)];
{options}
tic; [truss, angles, opt] = PrepareData(Node,Panel,Supp,Load,opt);
truss.U0 = zeros(3*size(truss.Node,1),1);
[U,F] = PathAnalysis(truss,angles,opt); t = toc; printf('SECONDS %.6f\\n', t);
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
}


def octave_seconds(merlin: Path, case: Path) -> float:
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
    """(increments, solve s, outputs s, {file: bytes}), each time the best of ``repeat``, measured
    alternately in one run. The first write packs plotly's JavaScript once (about 0.3 s;
    kept in a cache file), so one write is made before the timed ones."""
    solve, write = float("inf"), float("inf")
    with tempfile.TemporaryDirectory() as tmp:
        simulate(problem, progress=False).write(Path(tmp) / "warm")
        for k in range(repeat):
            start = time.perf_counter()
            sim = simulate(problem, progress=False)
            solve = min(solve, time.perf_counter() - start)
            start = time.perf_counter()
            written = sim.write(Path(tmp) / str(k))
            write = min(write, time.perf_counter() - start)
        sizes = {name: path.stat().st_size for name, path in written.items()}
    return sim.path.num_steps, solve, write, sizes


def print_outputs(repeat: int):
    print(f"\n{'example':<26} {'incr':>5} {'solve s':>8} {'outputs s':>9} {'ratio':>6} "
          f"{'view MB':>7} {'fold MB':>7} {'csv MB':>7}")
    for problem in sorted(EXAMPLES.glob("*/problem.toml")) + MORE:
        steps, solve, write, sizes = outputs(problem, repeat)
        csv = (sizes["history"] + sizes["displacements"]) / 1e6
        print(f"{problem.parent.name:<26} {steps:>5} {solve:>8.4f} {write:>9.4f} "
              f"{write / solve:>6.2f} {sizes.get('view', 0) / 1e6:>7.3f} "
              f"{sizes['fold'] / 1e6:>7.3f} {csv:>7.3f}")
    print("\nsolve s: simulate() (model and path); outputs s: Simulation.write() of every "
          "file; ratio: outputs over solve (goal: <= 1).")


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


if __name__ == "__main__":
    main()
