"""Chapter 4 and Appendix E of the thesis: the manipulator's kinematics, motor counts,
Table 5, the marker comparison (on the synthetic measured set) and the inverse kinematics.

Run: ``python studies/manipulator.py [--out DIR] [--full]``
     ``python studies/manipulator.py --write-synthetic kresling/data/synthetic_manipulator_markers.csv``
"""

import argparse
import time
from pathlib import Path

import numpy as np

from kresling.manipulator import (Manipulator, TendonDrive, configuration_name, forward_kinematics,
                                  joint_length_table, pseudo_linkage, solve_configuration,
                                  synthetic_markers, write_markers)
from kresling.report.sections.manipulator import reproduce


def appendix_e(arm: Manipulator, drive: TendonDrive) -> None:
    print("Appendix E, config [1 0 1], L1 = 10 (k = 10): markers (x, z) [mm] in eqn 26's frame")
    for i, (x, _, z) in enumerate(pseudo_linkage(arm, "101", [10]).markers[0]):
        print(f"  Coord{i + 1}: ({x:10.4f}, {z:10.4f})")
    counts = drive.motor_counts(arm, "101", [10.0, 40.0, 40.0])
    print("  " + ", ".join(f"Counts {m + 1} = {c:.4f}" for m, c in enumerate(counts)))
    print(f"  counts per mm = {drive.counts_per_mm:.6f}, snapCounts = {drive.snap_counts(arm):.4f}")
    print(f"(1 1 1) tip: z = {forward_kinematics(arm, '111').tip[2]:.6f} mm (3 x 111.6389 = {3 * 111.6389:.4f})")


def table5(arm: Manipulator) -> None:
    print("\nTable 5: measured module length ranges vs the model (mm)")
    print(f"  {'config':6s} {'joint':>5s} {'state':>5s} {'min':>7s} {'max':>7s} {'model':>8s} {'outside by':>10s}")
    for row in joint_length_table(arm):
        print(f"  {row['config']:6s} {row['joint']:5d} {row['state']:5d} {row['min_mm']:7.1f} "
              f"{row['max_mm']:7.1f} {row['predicted_max_mm']:8.3f} {row['outside_by_mm']:10.2f}")


def inverse_kinematics_accuracy(arm: Manipulator, per_configuration: int) -> None:
    rng = np.random.default_rng(0)
    print(f"\nInverse kinematics, {per_configuration} FK-sampled targets per configuration:")
    for configuration in arm.configurations[:-1]:
        lengths = rng.uniform(*arm.tendon_bounds, (per_configuration, 3))
        targets = np.array([forward_kinematics(arm, configuration, l).tip for l in lengths])
        start = time.perf_counter()
        solved = solve_configuration(arm, configuration, targets)
        seconds = time.perf_counter() - start
        print(f"  ({configuration_name(configuration)}): reached {solved['converged'].mean():6.1%}, "
              f"worst {solved['distance'].max():.1e} mm, mean iterations "
              f"{solved['iterations'].mean():5.1f}, {1e3 * seconds / per_configuration:.2f} ms/target")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out/manipulator"))
    parser.add_argument("--full", action="store_true", help="more IK targets, finer workspaces")
    parser.add_argument("--write-synthetic", type=Path, metavar="CSV",
                        help="write the synthetic measured-marker set and stop")
    args = parser.parse_args()
    if args.write_synthetic:
        write_markers(args.write_synthetic, synthetic_markers())
        print(f"wrote {args.write_synthetic}")
        return 0
    arm, drive = Manipulator(), TendonDrive()
    appendix_e(arm, drive)
    table5(arm)
    inverse_kinematics_accuracy(arm, 500 if args.full else 50)
    section = reproduce(args.out, quick=not args.full)
    failed = [c for c in section.checks if not c.passed]
    print(f"\nreport section: {len(section.checks) - len(failed)}/{len(section.checks)} checks "
          f"passed; figures and tables in {args.out}")
    for check in failed:
        print(f"  FAILED {check.name}: {check.value} vs {check.reference}")
    return len(failed)


if __name__ == "__main__":
    raise SystemExit(main())
