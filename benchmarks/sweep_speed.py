"""How fast the parametric study runs: designs per second per core for each metric, the
speed-up from 1 to 2 workers (threads and processes), the time per design against MERLIN2
under Octave (kresling/data/merlin2/timing_octave.csv), and the time of the full K_B-ratio
map (4 x 100 x 100 designs x 2 states): extrapolated from a measured subset, or measured
with --full; and the map's CPU time per design against the same designs' bending tests run
alone (``map_overhead``, ``--overhead`` alone).

Run: ``python benchmarks/sweep_speed.py [--size 8] [--workers 2] [--full]``

The machine is shared: the load average before and after is printed; ratios measured in
one run (the speed-up) are more trustworthy than absolute rates.
"""

import argparse
import csv
import multiprocessing
import os
import time
from concurrent.futures import ProcessPoolExecutor

import numpy as np

from kresling import Design, data
from kresling.analyses import BendingTester, bending_test
from kresling.sweeps import design_grid, sweep

THESIS_GRID = 100 * 100  # designs per n
# One metric per analysis (energy_barrier and bistable come from the snap_force run).
MEASURED = ("kb_ratio", "kb_ratio_5mm", "kb_ratio_linear", "psi_ratio", "snap_force")


def timed_sweep(grid, metric, workers, executor="threads"):
    start = time.perf_counter()
    table = sweep(grid, [metric], workers=workers, executor=executor, progress=False)
    seconds = time.perf_counter() - start
    assert table.ok.all(), f"{(~table.ok).sum()} designs failed"
    return seconds, table


def metric_rates(size: int, workers: int) -> dict:
    """Designs/s/core for each metric, with the speed-up from 1 to ``workers`` workers
    (threads, and a process pool started and warmed beforehand: its start-up, about a
    second, is paid once per sweep)."""
    rows, per_n = [], {}
    pool = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("spawn"))
    for name in MEASURED:
        n_size = max(2, size // 3) if name.endswith("5mm") else size
        grid = design_grid(size=n_size)
        timed_sweep(design_grid(size=2), name, workers, pool)  # start and warm the workers
        one, table = timed_sweep(grid, name, 1)
        many, _ = timed_sweep(grid, name, workers)
        procs, _ = timed_sweep(grid, name, workers, pool)
        rows.append((name, len(grid), len(grid) / one, one / many, one / procs,
                     len(grid) / many / workers))
        per_n[name] = {n: float(table.where(n=n)["seconds"].mean()) for n in (4, 6, 8, 10)}
    pool.shutdown()
    print(f"\n{'metric':14s} {'designs':>7s} {'designs/s, 1 core':>18s} "
          f"{'speed-up threads':>17s} {'speed-up processes':>19s} {'designs/s/core at W':>20s}")
    for name, count, rate, up_threads, up_procs, rate_w in rows:
        print(f"{name:14s} {count:7d} {rate:18.1f} {up_threads:17.2f} {up_procs:19.2f} "
              f"{rate_w:20.1f}")
    return per_n


def against_merlin2(per_n: dict) -> None:
    """Our 5 mm runs of MERLIN2's reference designs, run by run, against its Octave times;
    and an estimate for the 0.001 rad study's runs."""
    path = data.path("merlin2/timing_octave.csv")
    with open(path, newline="") as f:
        reference = list(csv.DictReader(f))
    testers, ratios = {}, []
    print(f"\n{'5 mm, 350 steps':22s} {'state':>5s} {'MERLIN2 s':>9s} {'its it/incr':>11s} "
          f"{'ours ms':>8s} {'our it/incr':>11s} {'faster':>7s}")
    for row in reference:
        n, Lc, lam = int(row["n"]), float(row["Lc_mm"]), float(row["lambda"])
        state = int(row["state"])
        tester = testers.setdefault(n, BendingTester(n, "5mm"))
        design = Design(n, lam, Lc)
        result = tester.run(design, state)  # also warms up
        repeats = 5
        start = time.perf_counter()
        for _ in range(repeats):
            tester.run(design, state)
        ours = (time.perf_counter() - start) / repeats
        merlin = float(row["wall_s"])
        ratios.append(merlin / ours)
        print(f"n={n:<2d} Lc={Lc:<4g} lam={lam:<5g} {state:5d} {merlin:9.2f} "
              f"{float(row['iters_per_incr']):11.2f} {1e3 * ours:8.1f} "
              f"{result.iterations.mean():11.2f} {merlin / ours:6.0f}x")
    print(f"geometric mean: {np.exp(np.mean(np.log(ratios))):.0f}x faster per run, one core each")
    # MERLIN2 was timed on 5 mm runs only; its cost per increment times the 0.001 rad
    # protocol's 10 increments estimates what the thesis's study cost per design.
    per_increment = {}
    for row in reference:
        per_increment.setdefault(int(row["n"]), []).append(float(row["wall_s"]) / 350)
    print("0.001 rad study, per design (both states), MERLIN2 estimated as 10 x its time per "
          "increment:")
    for n in sorted(per_increment):
        merlin = 2 * 10 * float(np.mean(per_increment[n]))
        ours = per_n["kb_ratio"][n]
        print(f"  n={n:<2d}: MERLIN2 ~{merlin:.2f} s, ours {1e3 * ours:.2f} ms: "
              f"~{merlin / ours:.0f}x")


def map_overhead(size: int, repeat: int = 3) -> float:
    """The K_B-ratio map's CPU time per design against the same designs' bending tests run
    alone (``bending_test`` in both states, 0.001 rad), side by side, best of ``repeat``
    each; returns the ratio."""
    grid = design_grid(size=size)
    designs = list(grid)

    def sweep_cpu():
        start = time.process_time()
        sweep(grid, ["kb_ratio"], workers=1, progress=False)
        return time.process_time() - start

    def alone_cpu():
        start = time.process_time()
        for design in designs:
            for state in (0, 1):
                bending_test(design, state, "0.001rad")
        return time.process_time() - start

    sweep_cpu(), alone_cpu()    # warm both (imports, the first tester's set-up)
    mapped = min(sweep_cpu() for _ in range(repeat))
    alone = min(alone_cpu() for _ in range(repeat))
    ratio = mapped / alone
    print(f"\nK_B-ratio map against the bending tests alone ({len(designs)} designs, both "
          f"states, CPU time, best of {repeat}): map {1e3 * mapped / len(designs):.2f} ms "
          f"per design, alone {1e3 * alone / len(designs):.2f} ms: {ratio:.2f}x")
    return ratio


def full_map(per_n: dict, workers: int, measure: bool) -> None:
    """The full K_B-ratio map: extrapolated from the per-design times, or measured."""
    single = sum(per_n["kb_ratio"][n] * THESIS_GRID for n in (4, 6, 8, 10))
    print(f"\nfull K_B-ratio map (40000 designs, 80000 bending runs): {single:.0f} s of "
          f"single-core work (extrapolated from the measured per-design times)")
    snap = [m for m in ("snap_force",) if m in per_n]
    if snap:
        extra = sum(per_n[snap[0]][n] * THESIS_GRID for n in (4, 6, 8, 10))
        print(f"all three metrics (K_B ratio, Psi ratio, snap force): {single + extra:.0f} s "
              f"single-core")
    if measure:
        for w in (1, workers):
            seconds, table = timed_sweep(design_grid(), "kb_ratio", w)
            print(f"measured, {w} worker(s): {seconds:.1f} s "
                  f"({len(table) / seconds:.0f} designs/s)")
        start = time.perf_counter()
        sweep(design_grid(), ["kb_ratio", "psi_ratio", "snap_force"], workers=workers,
              progress=False)
        print(f"measured, all three metrics, {workers} workers: "
              f"{time.perf_counter() - start:.1f} s")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--size", type=int, default=8, help="grid points per axis per n for "
                        "the rates (default 8: 256 designs; a third of that for 5 mm)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--full", action="store_true", help="also time the full map")
    parser.add_argument("--overhead", action="store_true",
                        help="only the map against the bending tests alone")
    args = parser.parse_args()
    if args.overhead:
        map_overhead(max(2, args.size // 2))
        return
    print(f"{os.cpu_count()} cores; load average before: "
          f"{', '.join(f'{v:.2f}' for v in os.getloadavg())}")
    per_n = metric_rates(args.size, args.workers)
    print("\nmean time per design [ms] by n (1 worker):")
    for name, times in per_n.items():
        print(f"  {name:14s} " + "  ".join(f"n={n}: {1e3 * t:7.2f}" for n, t in times.items()))
    against_merlin2(per_n)
    map_overhead(max(2, args.size // 2))
    full_map(per_n, args.workers, args.full)
    print(f"\nload average after: {', '.join(f'{v:.2f}' for v in os.getloadavg())}")


if __name__ == "__main__":
    main()
