"""How long planning a reach takes on the thesis's three-module arm.

For targets made by pulling the arm in a configuration, times (best of ``--repeat``):
``reach`` over every configuration (those too short skipped), ``reach`` told the
configuration, and one closed-loop run (plan, five corrections on a perturbed arm). Prints
the equilibria each needed and the tip error.

Run: ``python benchmarks/arm_reach.py [--repeat 3]``
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from kresling.arm import build_arm, tip_load
from kresling.arm.closed_loop import closed_loop
from kresling.arm.reach import reach

CASES = (("111", (4.0, 1.0, 0.5)), ("101", (6.0, 2.0, 0.0)), ("011", (0.0, 3.0, 3.0)))


def best(function, repeat):
    times, result = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return min(times), result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print(f"{'made by':>8s} {'pulls':>16s} {'all [s]':>8s} {'one [s]':>8s} {'error mm':>9s} "
          f"{'closed loop [s]':>15s}")
    for configuration, pulls in CASES:
        target = tip_load(build_arm(configuration), [0, 0, 0], pulls=pulls).state.tip_position
        every, r = best(lambda: reach(target), args.repeat)
        one, _ = best(lambda: reach(target, configurations=[r.configuration]), args.repeat)
        loop, _ = best(lambda: closed_loop(target, configurations=[r.configuration]), 1)
        print(f"{configuration:>8s} {str(pulls):>16s} {every:8.3f} {one:8.3f} {r.error:9.2e} "
              f"{loop:15.3f}", flush=True)


if __name__ == "__main__":
    main()
