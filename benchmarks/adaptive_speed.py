"""Fixed steps against adaptive increments with dense output, side by side in one run.

The bending test (both protocols) on the four Table 3 designs, both states, and their
snap-through test (100 increments): wall time (best of ``--repeat``), Newton iterations summed
over the samples (the adaptive mode's interpolated samples count 0; its increments' iterations
are not all on samples) and the largest difference of the sampled force, relative to the fixed
path's largest |force|.
Run: ``python benchmarks/adaptive_speed.py [--repeat 3]``.
"""

from __future__ import annotations

import argparse

import numpy as np

from kresling import Design
from kresling.analyses import BendingTester
from kresling.analyses.snap_through import SnapThroughTester
from solver_speed import best_time  # the same timing as the other benchmarks

TABLE3 = [(10, 0.9, 15.0), (8, 0.8, 30.0), (8, 0.8, 15.0), (4, 0.7, 30.0)]


def make_tester(n, protocol, adaptive):
    return BendingTester(n, protocol, adaptive=adaptive)


def make_snap_tester(n, adaptive):
    return SnapThroughTester(n, adaptive=adaptive)


def side_by_side(fixed_run, adaptive_run, repeat):
    """Best times and results of a fixed-step and an adaptive run, and the largest force
    difference relative to the fixed run's largest force (NaN if the samples differ)."""
    t_f, fixed = best_time(fixed_run, repeat)
    t_a, adaptive = best_time(adaptive_run, repeat)
    f, a = np.asarray(fixed.force), np.asarray(adaptive.force)
    error = np.abs(a - f).max() / np.abs(f).max() if len(a) == len(f) else float("nan")
    return t_f, fixed, t_a, adaptive, error


def print_header(header):
    print(header)
    print("-" * len(header))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print_header(f"{'n':>3} {'lam':>4} {'Lc':>4} {'protocol':>9} {'state':>10} {'fixed ms':>9} "
                 f"{'iters':>6} {'adaptive ms':>11} {'iters':>6} {'speed-up':>8} "
                 f"{'max dF/Fmax':>11}")
    for n, lam, Lc in TABLE3:
        design = Design(n, lam, Lc)
        for protocol in ("5mm", "0.001rad"):
            fixed_tester = make_tester(n, protocol, False)
            adaptive_tester = make_tester(n, protocol, True)
            for state in (1, 0):
                t_f, fixed, t_a, adaptive, error = side_by_side(
                    lambda: fixed_tester.run(design, state),
                    lambda: adaptive_tester.run(design, state), args.repeat)
                print(f"{n:>3} {lam:>4g} {Lc:>4g} {protocol:>9} "
                      f"{'extended' if state else 'contracted':>10} {t_f * 1e3:>9.1f} "
                      f"{fixed.iterations.sum():>6d} {t_a * 1e3:>11.1f} "
                      f"{adaptive.iterations.sum():>6d} {t_f / t_a:>8.2f} {error:>11.1e}")

    print("\nSnap-through (100 increments)")
    print_header(f"{'n':>3} {'lam':>4} {'Lc':>4} {'fixed ms':>9} {'adaptive ms':>11} "
                 f"{'speed-up':>8} {'max dF/Fmax':>11} {'snap force fixed':>16} {'adaptive':>12}")
    for n, lam, Lc in TABLE3:
        design = Design(n, lam, Lc)
        fixed_tester, adaptive_tester = make_snap_tester(n, False), make_snap_tester(n, True)
        t_f, fixed, t_a, adaptive, error = side_by_side(
            lambda: fixed_tester.run(design), lambda: adaptive_tester.run(design), args.repeat)
        print(f"{n:>3} {lam:>4g} {Lc:>4g} {t_f * 1e3:>9.1f} {t_a * 1e3:>11.1f} {t_f / t_a:>8.2f} "
              f"{error:>11.1e} {fixed.snap_force:>16.9f} {adaptive.snap_force:>12.9f}")


if __name__ == "__main__":
    main()
