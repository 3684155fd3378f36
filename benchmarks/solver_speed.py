"""Speed and memory of the bar-and-hinge solver against MERLIN2 under Octave.

Prints four tables:

1. the eight reference bending runs (Table 3; 350 increments to 5 mm): MERLIN2's wall
   time on a machine of this size (kresling/data/merlin2/timing_octave.csv) beside ours,
   iteration for iteration as MERLIN2 runs (extrapolation 0) and with the quadratic
   starting guess (extrapolation 2, one Newton iteration per increment); K_B must agree;
2. where one Newton iteration's time goes (the C++ program solver_breakdown): assembling
   the tangent, the force alone, factorising, solving; for specimens 4 to 60 cells tall,
   i.e. ~100 to ~2,000 free DOFs, to show how the cost grows with the DOF count;
3. end-to-end runs of the tall specimens;
4. peak memory (resident set) of one run in a fresh process, beyond the interpreter's.

Times are best of ``--repeat`` runs; absolute times on a shared machine are noisy, ratios
measured in one run less so. Run: ``python benchmarks/solver_speed.py [--quick]``.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from kresling import Design, data
from kresling.analyses import BendingTester

ROOT = Path(__file__).resolve().parents[1]


def best_time(function, repeat):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return min(times), result


def reference_runs(repeat):
    timing = np.genfromtxt(data.path("merlin2/timing_octave.csv"), delimiter=",", names=True)
    print("\n1. The reference bending runs (350 increments to 5 mm)")
    header = (f"{'n':>3} {'Lc':>4} {'lam':>4} {'state':>10} {'K_B ours':>10} {'K_B MERLIN2':>11} "
              f"{'Octave s':>9} {'exact s':>8} {'ratio':>6} {'iters':>6} {'fast s':>8} "
              f"{'ratio':>6} {'iters':>6}")
    print(header)
    print("-" * len(header))
    for row in timing:
        n, Lc, lam, state = int(row["n"]), float(row["Lc_mm"]), float(row["lambda"]), int(row["state"])
        design = Design(n, lam, Lc)
        exact = BendingTester(n, "5mm", extrapolation=0)
        fast = BendingTester(n, "5mm", extrapolation=2)
        t_exact, r_exact = best_time(lambda: exact.run(design, state), repeat)
        t_fast, r_fast = best_time(lambda: fast.run(design, state), repeat)
        # The reference prints six decimals: agreement to half a unit of the last digit.
        for r in (r_exact, r_fast):
            if abs(r.stiffness - row["Kb_Nm_per_rad"]) > 5e-7:
                raise SystemExit(f"K_B {r.stiffness} disagrees with MERLIN2's {row['Kb_Nm_per_rad']}")
        print(f"{n:>3} {Lc:>4g} {lam:>4g} {'extended' if state else 'contracted':>10} "
              f"{r_fast.stiffness:>10.6f} {row['Kb_Nm_per_rad']:>11.6f} {row['wall_s']:>9.2f} "
              f"{t_exact:>8.4f} {row['wall_s'] / t_exact:>6.0f} {r_exact.iterations.sum():>6d} "
              f"{t_fast:>8.4f} {row['wall_s'] / t_fast:>6.0f} {r_fast.iterations.sum():>6d}")
    print("(Octave: MERLIN2's time per run; exact: MERLIN2's Newton sequence; fast: quadratic "
          "starting guess; ratio = Octave time / ours)")


def breakdown(quick):
    program = ROOT / "build" / "py" / "solver_breakdown"
    print("\n2. One Newton iteration, piece by piece [microseconds] (C++, no Python)")
    if not program.exists():
        print(f"   {program} not built: run `make install` (it builds the benchmark programs)")
        return
    output = subprocess.run([str(program)] + (["--quick"] if quick else []), check=True,
                            capture_output=True, text=True).stdout
    print(output.rstrip())
    rows = [line.split() for line in output.splitlines()[1:]]
    dofs = np.array([float(r[2]) for r in rows])
    per_iteration = np.array([float(r[5]) + float(r[7]) + float(r[8]) for r in rows])
    if len(rows) >= 3:
        exponent = np.polyfit(np.log(dofs[1:]), np.log(per_iteration[1:]), 1)[0]
        print(f"   time per iteration (tangent + factorisation + solve) grows as DOFs^{exponent:.2f} "
              f"over the n = 10 towers")


def tall_specimens(quick, repeat):
    print("\n3. Tall specimens, end to end (n = 10, extended, 20 increments to 5 mm)")
    # MERLIN2's absolute tolerance ||du|| <= 1e-6 mm is below the rounding noise of the
    # correction once the tangent's condition number reaches ~1e8 (60 cells): there the
    # tolerance is relaxed to 1e-5 mm, as the table says.
    print(f"{'cells':>5} {'free DOFs':>9} {'tolerance':>9} {'iterations':>10} {'s per run':>9} "
          f"{'ms per iteration':>16} {'us per iteration per DOF':>24}")
    design = Design(10, 0.9, 15)
    for cells in ((4, 8, 16) if quick else (4, 8, 16, 30, 60)):
        tolerance = 1e-5 if cells >= 60 else 1e-6
        tester = BendingTester(10, "5mm", steps=20, cells=cells, tolerance=tolerance)
        t, r = best_time(lambda: tester.run(design, 1), repeat)
        iterations = int(r.iterations.sum())
        status = "" if r.completed else f"  FAILED: {r.message}"
        print(f"{cells:>5} {r.num_free_dofs:>9} {tolerance:>9.0e} {iterations:>10} {t:>9.3f} "
              f"{1e3 * t / max(iterations, 1):>16.3f} {1e6 * t / max(iterations, 1) / r.num_free_dofs:>24.3f}{status}")


def peak_memory(quick):
    print("\n4. Peak memory of one run in a fresh process (resident set, MiB)")
    code = ("import resource, sys; from kresling import Design; from kresling.analyses import BendingTester; "
            "base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss; "
            "n, cells = int(sys.argv[1]), int(sys.argv[2]); "
            "BendingTester(n, '5mm', cells=cells, steps=20 if cells > 4 else 350, "
            "tolerance=1e-5 if cells >= 60 else 1e-6).run(Design(n, 0.9, 15), 1); "
            "print(base, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)")
    print(f"{'model':>22} {'after import':>12} {'peak':>8} {'run adds':>9}")
    for n, cells in ((4, 4), (10, 4), (10, 16)) if quick else ((4, 4), (10, 4), (10, 16), (10, 60)):
        out = subprocess.run([sys.executable, "-c", code, str(n), str(cells)], check=True,
                             capture_output=True, text=True).stdout.split()
        base, peak = (int(v) / 1024 for v in out)
        print(f"{f'n={n}, {cells} cells':>22} {base:>12.1f} {peak:>8.1f} {peak - base:>9.1f}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats and sizes")
    parser.add_argument("--repeat", type=int, default=None, help="runs per timing (best of)")
    args = parser.parse_args(argv)
    repeat = args.repeat or (1 if args.quick else 3)
    load = os.getloadavg()
    print(f"kresling solver benchmark; {os.cpu_count()} cores, load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f} (other work on the machine slows every row)")
    reference_runs(repeat)
    breakdown(args.quick)
    tall_specimens(args.quick, repeat)
    peak_memory(args.quick)
    return 0


if __name__ == "__main__":
    sys.exit(main())
