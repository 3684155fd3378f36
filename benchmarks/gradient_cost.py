"""What the exact design derivatives cost beside the tests they differentiate.

For each design, side by side in one run (best of ``--repeat``):

- ``bend``: the bending test in both states as ``kresling bend`` runs it (adaptive
  increments between the protocol's samples);
- ``bend fixed``: the same in the protocol's equal increments (MERLIN2's way: 350 for 5 mm);
- ``gradient``: K_B of both states with their derivatives by all five design variables
  (``bending_gradient``: the test's adaptive run converged to 1e-10 mm, its knots
  differentiated and the samples' derivatives read off the same Hermite curves);
- ``snap`` and ``snap gradient``: the snap-through test, and its snap force and energy
  barrier with their derivatives.

The bound asked of the gradients is twice the bending test (both states); the table prints
the ratio to it.

Run: ``python benchmarks/gradient_cost.py`` (``--quick``: one design, one repeat).
"""

from __future__ import annotations

import argparse
import time

from kresling.analyses import bending_test, snap_through
from kresling.analyses.design_sensitivity import bending_gradient, snap_through_gradient
from kresling.geometry import Design

DESIGNS = ((8, 0.8, 30.0), (10, 0.9, 15.0), (6, 0.75, 20.0))


def best_time(function, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--protocol", default="5mm", choices=("5mm", "0.001rad"))
    args = parser.parse_args()
    designs = DESIGNS[:1] if args.quick else DESIGNS
    repeat = 1 if args.quick else args.repeat
    header = ("n", "lam", "Lc", "bend [s]", "bend fixed [s]", "gradient [s]", "/bend",
              "/fixed", "snap [s]", "snap gradient [s]", "/snap")
    print(f"protocol {args.protocol}; five design variables; best of {repeat}")
    print("  ".join(f"{h:>16}" for h in header))
    for n, lam, Lc in designs:
        design = Design(n, lam, Lc, 30.0)
        bend = best_time(lambda: [bending_test(design, s, args.protocol) for s in (0, 1)],
                         repeat)
        fixed = best_time(lambda: [bending_test(design, s, args.protocol, adaptive=False)
                                   for s in (0, 1)], repeat)
        gradient = best_time(lambda: [bending_gradient(design, s, args.protocol)
                                      for s in (0, 1)], repeat)
        snap = best_time(lambda: snap_through(design), repeat)
        snap_gradient = best_time(lambda: snap_through_gradient(design), repeat)
        row = (n, lam, Lc, f"{bend:.4f}", f"{fixed:.4f}", f"{gradient:.4f}",
               f"{gradient / bend:.1f}", f"{gradient / fixed:.1f}", f"{snap:.4f}",
               f"{snap_gradient:.4f}", f"{snap_gradient / snap:.1f}")
        print("  ".join(f"{str(c):>16}" for c in row), flush=True)


if __name__ == "__main__":
    main()
