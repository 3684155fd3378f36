"""How precisely the arm reaches a point: open loop (constant-curvature and structural
models) and closed loop on the structural model's tip Jacobian, with a true arm that
differs from the model and a camera with 0.2 mm of error.

Targets: the nominal arm's tips for eight pull patterns (bending toward each tendon, between
two, a shortening) in each configuration with one contracted (bending) module, so that
every target is reachable and the constant-curvature model has an answer too. Each target
gets its own draw of the true arm (seed = its index). Prints, over the targets, the median
and 95th percentile of the tip error in mm and in % of the arm's length.

Run: ``python studies/arm_reach.py [--iterations 5] [--quick]``
"""

import argparse

import numpy as np

from kresling.arm import build_arm, tip_load
from kresling.arm.closed_loop import CAMERA_ERROR, PERTURBATION, closed_loop

CONFIGURATIONS = ("110", "101", "011")
PULLS = ((4, 0, 0), (0, 4, 0), (0, 0, 4), (6, 2, 0), (0, 6, 2), (2, 0, 6), (3, 3, 3), (8, 1, 1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--iterations", type=int, default=5)
    parser.add_argument("--quick", action="store_true", help="one configuration, three targets")
    args = parser.parse_args()
    configurations = CONFIGURATIONS[:1] if args.quick else CONFIGURATIONS
    patterns = PULLS[:3] if args.quick else PULLS
    print(f"true arm: kf, Lc and tendon radius drawn with spreads {PERTURBATION}; camera "
          f"error {CAMERA_ERROR} mm per coordinate")
    rows = []
    for configuration in configurations:
        arm = build_arm(configuration)
        for pulls in patterns:
            target = tip_load(arm, [0.0, 0.0, 0.0], pulls=pulls).state.tip_position
            run = closed_loop(target, seed=len(rows), iterations=args.iterations)
            rows.append(run)
            print(f"  {configuration} pulls {pulls}: planned {run.configuration}, open loop "
                  f"{run.open_loop_kinematic:.2f} (cc) / {run.open_loop_structural:.3f} mm, "
                  f"closed {np.round(run.closed_loop, 3).tolist()} mm", flush=True)
    length = np.array([r.arm_length for r in rows])
    columns = [("open loop, constant curvature", np.array([r.open_loop_kinematic for r in rows])),
               ("open loop, structural model", np.array([r.open_loop_structural for r in rows]))]
    for k in (1, 3, 5):
        if k <= args.iterations:
            columns.append((f"closed loop, {k} correction{'s' if k > 1 else ''}",
                            np.array([r.closed_loop[k - 1] for r in rows])))
    print(f"\n{len(rows)} targets; tip error over them:")
    print(f"{'':32s} {'median mm':>10s} {'95% mm':>8s} {'median %':>9s} {'95% %':>7s}")
    for name, error in columns:
        ok = np.isfinite(error)
        mm = error[ok]
        pct = 100 * error[ok] / length[ok]
        print(f"{name:32s} {np.median(mm):10.3f} {np.percentile(mm, 95):8.3f} "
              f"{np.median(pct):9.3f} {np.percentile(pct, 95):7.3f}")


if __name__ == "__main__":
    main()
