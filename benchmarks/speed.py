"""Speed against MERLIN2, side by side, and how the solver scales to 100,000-DOF sheets.

Prints the machine's description (CPU, cores, memory, load, versions), then these tables in
one run (``--only`` picks some):

1. the bending test (350 increments to 5 mm) on the thesis's Table 3 designs, the optimum
   (n = 10, lam = 0.9, Lc = 15 mm, both states) first: our time beside MERLIN2's under GNU
   Octave on a 2-core machine of this size (kresling/data/merlin2/timing_octave.csv; MERLIN2
   has no bending driver of its own to run live);
2. MERLIN2 v1.1's example problems through ``kresling simulate``'s path (model building
   included, outputs not written; benchmarks/simulate_speed.py), beside MERLIN2's recorded
   time, and timed live with ``--octave DIR`` (MERLIN2's source folder) when ``octave-cli``
   is installed;
3. a generated Miura-ori sheet (kresling.io.miura_sheet, N5B8 with the sheet calibration and
   enhanced-linear bend hinges, one edge clamped, a small transverse load at the opposite
   edge) from ~1,000 to ~100,000
   DOFs: model building, one assembly, time per Newton iteration of force control, the
   factorisation chosen and its fill, peak memory, and the exponent of the time per
   iteration fitted from 1,000 DOFs up. Each size runs in a fresh process (its memory is
   its own).
4. ``outputs``: the time to write every output of each example's ``kresling simulate`` run
   beside its solve, and the files' sizes; then the whole command from the shell against
   MERLIN2's PathAnalysis, minus a do-nothing command's start-up, goal 20x
   (benchmarks/simulate_speed.py);
5. ``startup``: ``kresling bend`` on the optimum as a whole process minus ``kresling
   design``'s, against MERLIN2's stored time, and where the imports go
   (benchmarks/cli_startup.py);
6. ``physics``: a fold increment against a displacement increment, an implicit dynamics
   step against a static iteration (benchmarks/new_physics_speed.py);
7. ``patterns``: one Newton iteration by pattern kind (Miura, box pleat, Kresling tower,
   triangulated sheet) up to ~100,000 DOFs, positive definite and indefinite
   (benchmarks/pattern_scaling.py);
8. ``mgdcm``: MGDCM on a one-layer Kresling whose path crosses a double bifurcation at a
   tolerance of 1e-10 mm (the accuracy-floor case of docs/model.md, 'MGDCM');
9. ``sweeps``: the K_B-ratio map's CPU time per design against the same designs' bending
   tests run alone (benchmarks/sweep_speed.py, ``map_overhead``).

Times are best of ``--repeat`` runs (the sheets: one run); a shared machine makes absolute
times noisy: the load average is printed first. Run:
``python benchmarks/speed.py [--quick] [--octave DIR] [--max-dofs N]``.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

# The benchmarks beside this one (run as a script, its folder is on the path).
import cli_startup  # noqa: E402
import new_physics_speed  # noqa: E402
import pattern_scaling  # noqa: E402
import simulate_speed  # noqa: E402  (the examples' runners and MERLIN2 live under Octave)
import sweep_speed  # noqa: E402

from kresling import Design, data  # noqa: E402
from kresling.analyses import BendingTester  # noqa: E402

TABLES = ("bending", "examples", "sheets", "outputs", "startup", "physics", "patterns", "mgdcm",
          "sweeps")
OPTIMUM = (10, 15.0, 0.9)     # n, Lc [mm], lam: the thesis's optimum, K_ext / K_con largest


def best_time(function, repeat):
    best, result = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        best = min(best, time.perf_counter() - start)
    return best, result


def bending_table(repeat):
    rows = np.genfromtxt(data.path("merlin2/timing_octave.csv"), delimiter=",", names=True)
    rows = sorted(rows, key=lambda r: (int(r["n"]), r["Lc_mm"], r["lambda"]) != OPTIMUM)
    print("\n1. Bending test, 350 increments to 5 mm (MERLIN2: stored run under Octave)")
    header = (f"{'n':>3} {'Lc':>4} {'lam':>4} {'state':>10} {'K_B ours':>10} {'K_B MERLIN2':>11} "
              f"{'MERLIN2 s':>9} {'ours s':>8} {'ratio':>6}")
    print(header)
    print("-" * len(header))
    testers, optimum = {}, [0.0, 0.0]
    for row in rows:
        n, Lc, lam = int(row["n"]), float(row["Lc_mm"]), float(row["lambda"])
        state = int(row["state"])
        tester = testers.setdefault(n, BendingTester(n, "5mm"))
        seconds, result = best_time(lambda: tester.run(Design(n, lam, Lc), state), repeat)
        if (n, Lc, lam) == OPTIMUM:
            optimum[0] += row["wall_s"]
            optimum[1] += seconds
        print(f"{n:>3} {Lc:>4g} {lam:>4g} {'extended' if state else 'contracted':>10} "
              f"{result.stiffness:>10.6f} {row['Kb_Nm_per_rad']:>11.6f} {row['wall_s']:>9.2f} "
              f"{seconds:>8.4f} {row['wall_s'] / seconds:>6.0f}")
    print(f"optimum, both states: MERLIN2 {optimum[0]:.2f} s, ours {optimum[1]:.4f} s: "
          f"{optimum[0] / optimum[1]:.0f}x (goal: 500x)")


def examples_table(repeat, octave):
    print("\n2. MERLIN2's example problems through kresling simulate")
    header = (f"{'example':<26} {'nodes':>5} {'DOFs':>5} {'incr':>5} {'MERLIN2 s':>10} "
              f"{'live s':>8} {'ours s':>8} {'ratio':>7}")
    print(header)
    print("-" * len(header))
    for label, sim, recorded, live, seconds, ratio in simulate_speed.rows(repeat, octave):
        print(f"{label:<26} {sim.model.num_nodes:>5} {sim.model.num_dofs:>5} "
              f"{sim.path.num_steps:>5} {recorded:>10.3f} {live:>8.3f} {seconds:>8.4f} "
              f"{ratio:>7.0f}")
    print("ratio: MERLIN2 (live if timed, else recorded) over ours (goal: 200x each); "
          "'cubic': the same increments, each Newton solve started from a cubic "
          "extrapolation of the path; 'adaptive': the same samples, the path between them in "
          "adaptive increments")


# One sheet size in a fresh process; prints one JSON line.
_SHEET_PROBE = """
import json, resource, sys, time
import numpy as np, scipy.sparse as sp
from kresling import _core
from kresling.assembly import assemble
from kresling.io import miura_sheet
from kresling.model.calibration import SheetMaterial
from kresling.model.pattern_model import CreaseLaws, HingeLaw, build_pattern_model
from kresling.solvers import solve_force_control

def rss():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0   # MiB
nx = int(sys.argv[1]); steps = int(sys.argv[2])
baseline = rss()
start = time.perf_counter()
pattern = miura_sheet(nx, nx)
# Bend hinges enhanced-linear: the super-linear law's stiffness vanishes at rest (its moment
# goes as |angle|^(4/3)), which slows Newton to tens of iterations near the flat panel.
laws = CreaseLaws(bend=HingeLaw("enhanced_linear"))
pm = build_pattern_model(pattern, material=SheetMaterial(5e3, 0.35, 0.127), centre="mean",
                         laws=laws)
build = time.perf_counter() - start
fixed = np.zeros((pm.model.num_nodes, 3), bool)
fixed[:nx + 1] = True                                   # the sheet's edge j = 0, clamped
model = pm.model.replace(fixed=fixed)
forces = np.zeros((model.num_nodes, 3))
top = np.arange(nx * (nx + 1), (nx + 1) ** 2)           # the opposite edge
# A cantilever's tip deflection grows as its length cubed: the load shrinks with the sheet
# so that every size stays in the same nearly linear range (a few Newton iterations each).
forces[top, 2] = 1e-5 * (13.0 / nx) ** 3 / len(top)
try:
    from kresling.assembly import Workspace
    workspace = Workspace(model)
except ImportError:
    workspace = None
def assemble_once(with_matrix):
    kwargs = {} if workspace is None else {"workspace": workspace}
    t = time.perf_counter(); a = assemble(model, stiffness=with_matrix, **kwargs)
    return time.perf_counter() - t, a
assembly = min(assemble_once(True)[0] for _ in range(3))
force_only = min(assemble_once(False)[0] for _ in range(3))
K = assemble_once(True)[1].stiffness
free = np.flatnonzero(~fixed.ravel())
plan = _core.solvers.factorization_plan(sp.tril(K[free][:, free]).tocsc())
del K
start = time.perf_counter()
# The tangent's condition number grows with the sheet (a long, soft cantilever): Newton's
# corrections stagnate at its rounding noise (7.7e-6 mm at 45 x 45), so the tolerance is
# 1e-7 of the sheet's span instead of a fixed 1e-6 mm.
span = float(np.ptp(model.nodes, axis=0).max())
path = solve_force_control(model, forces, steps, tolerance=1e-7 * span)
solve = time.perf_counter() - start
print(json.dumps(dict(
    dofs=int(model.num_dofs), free=int(len(free)), bars=len(model.bars),
    hinges=len(model.hinges), build=build, assembly=assembly, force_only=force_only,
    iterations=int(np.sum(path.iterations)), completed=bool(path.completed), solve=solve,
    plan=plan, peak_mib=rss() - baseline)))
"""


def sheet_table(sizes, steps):
    print("\n3. Miura-ori sheet, force control "
          f"({steps} increments; time per Newton iteration = (solve time - the symbolic "
          "analysis, once per pattern) / iterations)")
    header = (f"{'panels':>9} {'DOFs':>7} {'elements':>8} {'build s':>8} {'asm ms':>8} "
              f"{'asm us/el':>9} {'iters':>5} {'s/iter':>7} {'analysis s':>10} {'factor':>10} "
              f"{'ordering':>8} "
              f"{'nnz(L)':>10} {'fill':>5} {'GFlop':>6} {'peak MiB':>8}")
    print(header)
    print("-" * len(header))
    dofs, per_iteration = [], []
    for nx in sizes:
        out = subprocess.run([sys.executable, "-c", _SHEET_PROBE, str(nx), str(steps)],
                             capture_output=True, text=True)
        if out.returncode != 0:
            print(f"{nx}x{nx}: failed: {out.stderr.strip().splitlines()[-1:]}")
            continue
        r = json.loads(out.stdout.strip().splitlines()[-1])
        p = r["plan"]
        elements = r["bars"] + r["hinges"]
        # The symbolic analysis (ordering, supernodes) is done once per pattern, in the first
        # iteration: reported on its own, the steady cost per iteration without it.
        seconds = max(r["solve"] - p["analysis_seconds"], 0.0) / max(r["iterations"], 1)
        dofs.append(r["free"])
        per_iteration.append(seconds)
        fill = p["factor_nonzeros"] / r["free"]
        print(f"{f'{nx}x{nx}':>9} {r['free']:>7} {elements:>8} {r['build']:>8.2f} "
              f"{1e3 * r['assembly']:>8.2f} {1e6 * r['assembly'] / elements:>9.3f} "
              f"{r['iterations']:>5} {seconds:>7.3f} {p['analysis_seconds']:>10.3f} "
              f"{p['cholesky']:>10} "
              f"{'ND' if p['ordering'] == 'nested dissection' else p['ordering']:>8} "
              f"{p['factor_nonzeros']:>10.3g} {fill:>5.0f} {p['flops'] / 1e9:>6.2f} "
              f"{r['peak_mib']:>8.0f}" + ("" if r["completed"] else "  (path incomplete)"))
    print("Newton tolerance: 1e-7 of the sheet's span. DOFs: free DOFs; asm: one assembly of "
          "force and tangent through a kept pattern (Python call included); fill: nnz(L) per "
          "DOF; GFlop: one factorisation; peak MiB: the process's peak resident memory over "
          "its baseline after imports")
    big = np.array(dofs) >= 1000
    if big.sum() >= 2:
        slope = np.polyfit(np.log(np.array(dofs)[big]), np.log(np.array(per_iteration)[big]), 1)[0]
        print(f"time per iteration grows as DOFs^{slope:.2f} from 1,000 DOFs up (nested "
              "dissection's bound for a sheet: flops ~ n^1.5, fill ~ n log n)")
    if dofs and max(dofs) >= 90_000:
        print(f"largest sheet: {per_iteration[-1]:.2f} s per Newton iteration at {dofs[-1]} DOFs "
              "(goal: under 1 s at 100,000)")


def machine() -> str:
    """The CPU model, cores, memory, OS, Python and numpy, and the load averages."""
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
        memory = next(line.split()[1] for line in Path("/proc/meminfo").read_text().splitlines()
                      if line.startswith("MemTotal"))
        memory = f"{int(memory) / 2**20:.0f} GiB"
    except (OSError, StopIteration):
        memory = "unknown"
    load = os.getloadavg()
    return (f"machine: {cpu}, {os.cpu_count()} cores, {memory} memory; {platform.platform()}; "
            f"Python {platform.python_version()}, numpy {np.__version__}; load average "
            f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f} (other work on the machine slows every "
            "row)")


def mgdcm_table():
    from kresling.testing.one_layer_kresling import SIDES, one_layer_kresling

    from kresling.solvers import solve_mgdcm

    model, forces = one_layer_kresling()
    top = model.dof(SIDES, 2)
    print("\n8. MGDCM, one-layer six-sided Kresling to u_z = -49 mm, tolerance 1e-10 mm "
          "(a double bifurcation near -22.5 mm, another near -28.3 mm)")
    print(f"{'initial factor':>14} {'increments':>10} {'iterations':>10} {'seconds':>8} "
          f"{'u_z end':>8}  outcome")
    for factor in (0.001, 0.003, 0.01):
        start = time.perf_counter()
        path = solve_mgdcm(model, forces, initial_load_factor=factor, tolerance=1e-10,
                           max_increments=100_000, monitor_dof=top, max_displacement=49.0)
        seconds = time.perf_counter() - start
        end = path.displacement[-1].ravel()[top] if path.num_steps else 0.0
        print(f"{factor:>14g} {path.num_steps:>10} {path.newton_iterations:>10} "
              f"{seconds:>8.3f} {end:>8.2f}  "
              + ("completed" if path.completed else path.message))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="one repeat, sheets up to ~12,000 DOFs")
    parser.add_argument("--repeat", type=int, default=None, help="runs per timing (best of)")
    parser.add_argument("--octave", type=Path, metavar="DIR",
                        help="MERLIN2 v1.1's source folder, to time its examples live")
    parser.add_argument("--max-dofs", type=int, default=None,
                        help="largest sheet (DOFs, ~6 per panel); default 100,000")
    parser.add_argument("--steps", type=int, default=2, help="force increments per sheet")
    parser.add_argument("--only", choices=TABLES, action="append",
                        help="run only these tables (repeatable)")
    args = parser.parse_args(argv)
    repeat = args.repeat or (1 if args.quick else 3)
    max_dofs = args.max_dofs or (12_500 if args.quick else 101_000)
    sizes = [nx for nx in (13, 20, 30, 45, 65, 90, 129) if 6 * nx * nx <= max_dofs]
    print("kresling speed benchmark; " + machine())
    tables = set(args.only or TABLES)
    if "bending" in tables:
        bending_table(repeat)
    if "examples" in tables:
        examples_table(repeat, args.octave)
    if "sheets" in tables:
        sheet_table(sizes, args.steps)
    if "outputs" in tables:
        print("\n4. Outputs of kresling simulate beside its solve")
        simulate_speed.print_outputs(repeat)
        simulate_speed.print_commands(repeat, args.octave)
    if "startup" in tables:
        print("\n5. Start-up: kresling bend through the command line")
        cli_startup.main(["--repeat", str(max(repeat, 3))])
    if "physics" in tables:
        print("\n6. The new physics: fold, displacement and dynamics increments")
        new_physics_speed.main(repeat)
    if "patterns" in tables:
        print("\n7. One Newton iteration by pattern kind")
        pattern_scaling.table(list(pattern_scaling.SIZES), max_dofs)
    if "mgdcm" in tables:
        mgdcm_table()
    if "sweeps" in tables:
        print("\n9. Sweeps: the K_B-ratio map against its bending tests run alone")
        sweep_speed.map_overhead(2 if args.quick else 4, repeat)
    print("\n" + machine())
    return 0


if __name__ == "__main__":
    sys.exit(main())
