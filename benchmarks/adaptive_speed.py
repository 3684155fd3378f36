"""Fixed steps against adaptive increments with dense output, side by side in one run.

The bending test (both protocols) on the four Table 3 designs, both states: wall time (best of
``--repeat``), Newton iterations summed over the samples (the adaptive mode's interpolated
samples count 0; its increments' iterations are not all on samples) and the largest difference
of the sampled force, relative to the fixed path's largest |force|.
Run: ``python benchmarks/adaptive_speed.py [--repeat 3]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from kresling import Design, _core
from kresling.analyses import BendingTester
from kresling.solvers.displacement_control import displacement_control_options

TABLE3 = [(10, 0.9, 15.0), (8, 0.8, 30.0), (8, 0.8, 15.0), (4, 0.7, 30.0)]


def make_tester(n, protocol, adaptive):
    t = BendingTester(n, protocol, extrapolation=2)
    options = displacement_control_options(extrapolation=2)
    options.adaptive = adaptive
    s = t.settings
    t._core = _core.analyses.BendingTest(n, s["deflection"], s["deflection_angle"], s["steps"],
                                         s["cells"], t.parameters.to_core(), options)
    return t


def best(function, repeat):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return min(times), result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    header = (f"{'n':>3} {'lam':>4} {'Lc':>4} {'protocol':>9} {'state':>10} {'fixed ms':>9} "
              f"{'iters':>6} {'adaptive ms':>11} {'iters':>6} {'speed-up':>8} {'max dF/Fmax':>11}")
    print(header)
    print("-" * len(header))
    for n, lam, Lc in TABLE3:
        design = Design(n, lam, Lc)
        for protocol in ("5mm", "0.001rad"):
            fixed_tester = make_tester(n, protocol, False)
            adaptive_tester = make_tester(n, protocol, True)
            for state in (1, 0):
                t_f, fixed = best(lambda: fixed_tester.run(design, state), args.repeat)
                t_a, adaptive = best(lambda: adaptive_tester.run(design, state), args.repeat)
                error = np.abs(adaptive.force - fixed.force).max() / np.abs(fixed.force).max()
                print(f"{n:>3} {lam:>4g} {Lc:>4g} {protocol:>9} "
                      f"{'extended' if state else 'contracted':>10} {t_f * 1e3:>9.1f} "
                      f"{fixed.iterations.sum():>6d} {t_a * 1e3:>11.1f} "
                      f"{adaptive.iterations.sum():>6d} {t_f / t_a:>8.2f} {error:>11.1e}")


if __name__ == "__main__":
    main()
