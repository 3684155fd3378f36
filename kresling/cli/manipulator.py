"""``kresling manipulator``: markers, tendon lengths and motor counts of the thesis's arm at a
step of the section 4.3 protocol, or the configuration and inputs that reach a target."""

from __future__ import annotations

import math
import sys

from kresling.cli._output import degrees, print_json, print_table
from kresling.cli.design import add_design_arguments
from kresling.geometry import Design
from kresling.manipulator import (FRAMES, Manipulator, TendonDrive, configuration_name,
                                  forward_kinematics, inverse_kinematics, protocol_tendon_lengths)
from kresling.manipulator.model import THESIS_CELL


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "manipulator",
        help="manipulator kinematics: markers and motor counts, or inverse kinematics",
        description="Forward kinematics of the Kresling manipulator under the thesis's "
                    "pseudo-linkage protocol (l1 = 2Lc - 2k, l2 = l3 = 2Lc + k per flexible "
                    "module), or with --target, the configuration and tendon lengths that "
                    "reach a point. Positions in mm in the frame of eqn 26 (z along the "
                    "undeformed axis, tendon 1 on +x). With --target, a point beyond the "
                    "arm's reach prints the nearest one and exits with status 1.",
    )
    parser.add_argument("--config", default="101",
                        help="module states, base first: 0 contracted (flexible), 1 extended "
                             "(rigid) (default 101)")
    parser.add_argument("--k", type=float, default=10.0, metavar="MM",
                        help="protocol step [mm]: per flexible module, tendon 1 shortened by "
                             "2k and tendons 2 and 3 lengthened by k (default 10; the thesis "
                             "uses 0 to 10). Allowed: -2Lc <= k <= Lc (every tendon length "
                             ">= 0), i.e. -30 to 15 mm for the default cell")
    parser.add_argument("--target", type=float, nargs=3, metavar=("X", "Y", "Z"),
                        help="solve the inverse kinematics for this point [mm] instead")
    parser.add_argument("--modules", type=int, default=None,
                        help="number of modules, each two cells (default: the length of "
                             "--config)")
    add_design_arguments(parser, defaults=THESIS_CELL, chirality=False)
    parser.add_argument("--d", type=float, default=32.0, help="tendon radius [mm] (default 32)")
    parser.add_argument("--N", type=int, default=1,
                        help="tendon segments per module, a count (default 1)")
    parser.add_argument("--frame", choices=FRAMES, default="twist_free",
                        help="frame convention of flexible modules (markers do not depend on it)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(func=run)


def _model(args) -> Manipulator:
    digits = [c for c in str(args.config) if c not in "()[] ,"]  # "101", "(1 0 1)", "1,0,1"
    modules = args.modules if args.modules is not None else max(len(digits), 1)
    return Manipulator(modules=modules, design=Design(args.n, args.lam, args.Lc, args.R),
                       tendon_radius=args.d, segments=args.N, frame=args.frame)


def _counts(drive: TendonDrive, model, configuration, lengths) -> dict:
    counts = drive.motor_counts(model, configuration, lengths)
    return {f"motor{i + 1}": float(c) for i, c in enumerate(counts)}


def _check_step(k: float, model) -> None:
    """--k in the range where every tendon length ``rest - 2k``, ``rest + k`` is >= 0."""
    rest = model.rest_tendon_length
    if not (math.isfinite(k) and -rest <= k <= rest / 2):
        raise ValueError(f"--k = {k!r} is invalid: must be in [{-rest:g}, {rest / 2:g}] mm for "
                         f"this cell (Lc = {model.design.Lc:g} mm): tendon 1 is 2Lc - 2k = "
                         f"{rest:g} - 2k and tendons 2 and 3 are 2Lc + k long, and a length "
                         f"must be >= 0; the thesis's protocol uses 0 to 10")


def bend_direction_deg(phi: float) -> float:
    """Where an arc of eqn 26's angle ``phi`` [rad] bends, in its base frame [deg] from +x
    in (-180, 180]: towards ``phi - pi/2`` (the shortest tendon)."""
    towards = (math.degrees(phi) - 90.0) % 360.0
    return round(towards - 360.0 if towards > 180.0 else towards, 10) + 0.0


def run(args) -> int:
    model = _model(args)
    drive = TendonDrive()
    if args.target is not None:
        return _run_inverse(args, model, drive)
    _check_step(args.k, model)
    configuration = model.configuration(args.config)
    lengths = protocol_tendon_lengths(args.k, model.rest_tendon_length)
    state = forward_kinematics(model, configuration, lengths if 0 in configuration else None)
    flexible = [j + 1 for j, s in enumerate(configuration) if s == 0]
    result = {
        "config": configuration_name(configuration),
        "k": args.k,
        "frame": model.frame,
        "markers": state.markers,
        "plot_markers": state.plot_markers,
        "module_lengths": state.module_lengths,
        "arcs": {f"module{j}": state.arcs[j - 1] for j in flexible},
        "tendon_lengths": {f"module{j}": row for j, row in zip(flexible, state.tendon_lengths)},
        "tendon_shortening": drive.tendon_shortening(model, configuration, state.tendon_lengths),
        "motor_counts": _counts(drive, model, configuration, state.tendon_lengths),
        "counts_per_mm": drive.counts_per_mm,
        "snap_counts": drive.snap_counts(model),
    }
    if args.json:
        print_json(result)
        return 0
    print(f"configuration ({result['config']}), step k = {args.k:g}; markers [mm], frame of eqn 26")
    print_table([(i + 1, *p) for i, p in enumerate(state.markers)], ("marker", "x", "y", "z"))
    print()
    if not flexible:
        print("every module is extended (rigid): no tendon lengths or motor counts to set")
        return 0
    print_table([(name, *row) for name, row in result["tendon_lengths"].items()],
                ("module", "l1 [mm]", "l2 [mm]", "l3 [mm]"))
    print()
    # The arcs (arc length s, curvature kappa, eqn 26's angle phi): the bending angle
    # s kappa and phi in degrees beside radians, as people read angles, and where the bend
    # points, which phi is not (it is 90 deg ahead of it).
    print_table([(name, s, s * kappa, degrees(s * kappa), phi, degrees(phi),
                  bend_direction_deg(phi)) for name, (s, kappa, phi) in result["arcs"].items()],
                ("module", "arc [mm]", "bend [rad]", "[deg]", "phi (eqn 26) [rad]", "[deg]",
                 "bends towards [deg]"))
    print("(a module bends towards phi - 90 deg in its base frame: 0 deg is +x, tendon 1's "
          "side; 120 and 240 deg are tendons 2 and 3)")
    print()
    print_table(list(result["motor_counts"].items()), ("motor", "counts"))
    return 0


def _run_inverse(args, model, drive) -> int:
    found = inverse_kinematics(model, args.target)
    lengths = found.tendon_lengths if 0 in found.configuration else None
    result = {
        "target": found.target,
        "reachable": found.reachable,
        "config": configuration_name(found.configuration),
        "tendon_lengths": found.tendon_lengths,
        "position": found.position,
        "distance": found.distance,
        "markers": forward_kinematics(model, found.configuration, lengths).markers,
        "motor_counts": _counts(drive, model, found.configuration, found.tendon_lengths)
        if lengths is not None else {"motor1": 0.0, "motor2": 0.0, "motor3": 0.0},
    }
    status = 0 if found.reachable else 1
    if args.json:
        print_json(result)
    else:
        verdict = "reachable" if found.reachable else "NOT reachable; nearest point"
        print(f"target {found.target.tolist()} mm: {verdict} with configuration "
              f"({result['config']})")
        print_table([("l1, l2, l3 [mm]", *found.tendon_lengths), ("tip [mm]", *found.position)],
                    ("", "1", "2", "3"))
        print(f"distance {found.distance:.3g} mm")
    if not found.reachable:
        print(f"kresling manipulator: the target {found.target.tolist()} mm is beyond the arm's "
              f"reach: the nearest point reached is {found.distance:.3g} mm from it "
              f"(configuration {result['config']})", file=sys.stderr)
    return status
