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
4. peak memory of one run (the heap's high-water mark in a fresh process).

Times are best of ``--repeat`` runs; absolute times on a shared machine are noisy, ratios
measured in one run less so. Run: ``python benchmarks/solver_speed.py [--quick]``.
"""

from __future__ import annotations

import argparse
import os
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
        fast = BendingTester(n, "5mm", extrapolation=2, adaptive=False)
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
          "starting guess, fixed steps; ratio = Octave time / ours;\n the bending test's default "
          "follows this protocol in adaptive increments: benchmarks/adaptive_speed.py)")


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
    # Up to 400 DOFs the (dense-ish) tangents take the dense Cholesky, above it CHOLMOD: fit
    # the growth within the sparse path only.
    sparse = dofs > 400
    if sparse.sum() >= 2:
        exponent = np.polyfit(np.log(dofs[sparse]), np.log(per_iteration[sparse]), 1)[0]
        print(f"   on the sparse (CHOLMOD) path the time per iteration (tangent + factorisation + "
              f"solve) grows as DOFs^{exponent:.2f}; the factor's fill grows linearly, the rest is "
              f"cache: at ~2,000 DOFs it no longer fits")


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
        tester = BendingTester(10, "5mm", steps=20, cells=cells, tolerance=tolerance,
                               adaptive=False)
        t, r = best_time(lambda: tester.run(design, 1), repeat)
        iterations = int(r.iterations.sum())
        status = "" if r.completed else f"  FAILED: {r.message}"
        print(f"{cells:>5} {r.num_free_dofs:>9} {tolerance:>9.0e} {iterations:>10} {t:>9.3f} "
              f"{1e3 * t / max(iterations, 1):>16.3f} {1e6 * t / max(iterations, 1) / r.num_free_dofs:>24.3f}{status}")


# Peak heap of one run, measured in a fresh process: glibc is told never to return memory
# to the system (no trimming) and to serve every allocation from its heap (no mmap), so the
# heap's size after the run is its high-water mark; the difference from before the run is
# what the run needed at most (the interpreter's resident set, ~100 MB after importing numpy
# and scipy, would hide it).
_MEMORY_PROBE = """
import ctypes, sys
libc = ctypes.CDLL("libc.so.6")
libc.mallopt(-1, 2**30)   # M_TRIM_THRESHOLD
libc.mallopt(-3, 2**30)   # M_MMAP_THRESHOLD
class Mallinfo2(ctypes.Structure):
    _fields_ = [(name, ctypes.c_size_t) for name in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks",
                 "uordblks", "fordblks", "keepcost")]
libc.mallinfo2.restype = Mallinfo2
from kresling import Design
from kresling.analyses import BendingTester
n, cells = int(sys.argv[1]), int(sys.argv[2])
tester = BendingTester(n, "5mm", cells=cells, steps=20 if cells > 4 else 350,
                       tolerance=1e-5 if cells >= 60 else 1e-6, adaptive=False)
design = Design(n, 0.9, 15)
before = libc.mallinfo2().arena
tester.run(design, 1)
print(before, libc.mallinfo2().arena)
"""


def peak_memory(quick):
    print("\n4. Peak heap of one run [MiB] (its tester already built; glibc arena high-water)")
    print(f"{'model':>22} {'free DOFs':>9} {'run needs':>10}")
    for n, cells in ((4, 4), (10, 4), (10, 16)) if quick else ((4, 4), (10, 4), (10, 16), (10, 60)):
        out = subprocess.run([sys.executable, "-c", _MEMORY_PROBE, str(n), str(cells)],
                             check=True, capture_output=True, text=True).stdout.split()
        before, after = (int(v) / 2**20 for v in out)
        dofs = 3 * (cells + 1) * (n + 1) - 6 * 3 - (n + 1)
        print(f"{f'n={n}, {cells} cells':>22} {dofs:>9} {after - before:>10.2f}")


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
