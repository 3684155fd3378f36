"""Print reference geometry values beside ours, with the difference: Le of the optimum as
thesis Appendix E uses it, Le of the paper specimens as the MERLIN2 reference runs give it (to
6 decimals) and Psi of the MERLIN2 golden model.

Run: ``python studies/geometry_values.py``
"""

import math

from kresling import Design

# (n, lam, Lc, quantity, reference value, absolute tolerance: half a unit of its last printed
# digit)
CHECKS = [
    (10, 0.9, 15.0, "Le", 55.8194667799374, 1e-9),
    (8, 0.8, 30.0, "Le", 55.317649, 5e-7),
    (8, 0.8, 15.0, "Le", 48.836895, 5e-7),
    (4, 0.7, 30.0, "Le", 41.068587, 5e-7),
    (4, 0.7, 30.0, "psi_ext", 1.2878022801111912, 1e-12),  # MERLIN2 golden hinge 1
]


def main() -> int:
    failures = 0
    print(f"{'design':22s} {'quantity':9s} {'reference':>20s} {'kresling':>20s} {'diff':>10s}  ok")
    for n, lam, Lc, key, expected, tol in CHECKS:
        value = getattr(Design(n, lam, Lc), key)
        ok = abs(value - expected) <= tol
        failures += not ok
        print(f"n={n:<2d} lam={lam:<4g} Lc={Lc:<5g} {key:9s} {expected:20.13f} {value:20.13f} "
              f"{value - expected:10.2e}  {'yes' if ok else 'NO'}")
    d = Design(10, 0.9 + 0.0999999999999, 0.0)
    limit = 2 * d.R * math.cos(math.pi / d.n)
    print(f"traditional limit lam->1, Lc=0, n=10: Le = {d.Le:.9f}, 2R cos(pi/n) = {limit:.9f}")
    return failures


if __name__ == "__main__":
    raise SystemExit(main())
