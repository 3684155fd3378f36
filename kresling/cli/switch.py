"""``kresling switch``: switch one cell between its stable states by its creases."""

from __future__ import annotations

import math

from kresling.cli._output import print_json, print_table
from kresling.cli._specimen import (add_specimen_arguments, describe,
                                    specimen_parameters_from_args, summary_line)
from kresling.cli.bend import finite_or_none
from kresling.cli.design import add_design_arguments, design_from_args

#: The thesis's optimum (n, lam, Lc [mm]).
_OPTIMUM = (10, 0.9, 15.0)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "switch",
        help="switch one cell between its stable states by driving its creases' rest angles",
        description="Crease actuation of the snap-through test's cell (bottom polygon held): "
                    "for each crease group (valley, mountain, polygon edges, all folds) the "
                    "rest angles are driven away from their stress-free values, each crease "
                    "towards its angle in the other stable state, until the start state "
                    "ceases to exist (the snap, located by bisection); the cell snaps, the "
                    "rest angles are released and energy descent finds where it rests. "
                    "Both ways: extended to contracted, and contracted to extended (which a "
                    "tendon cannot do). Reports the rest-angle change and the summed crease "
                    "moment at the snap, the work of the actuation (the integral of the "
                    "moment over the change; it equals the strain energy the actuation added) "
                    "beside "
                    "the snap-through test's energy barrier, and the landing height. The "
                    "default design is the thesis's optimum.",
        epilog="On the thesis's optimum with the thesis's stiffness, no crease group "
               "switches the cell from extended to contracted before a rest angle leaves "
               "(0, 360) deg (the bars resist more than the creases can push; with "
               "--valley-ratio 1.5 the valleys do, at 157.6 deg); back from contracted to "
               "extended, all folds together need the least change (75.5 deg) and the "
               "valleys alone the least summed moment (115 N*mm).",
    )
    add_design_arguments(parser, defaults=_OPTIMUM)
    add_specimen_arguments(parser)
    parser.add_argument("--resolution", type=float, default=1e-5, metavar="DEG",
                        help="resolution of the rest-angle change at the snap [deg] "
                             "(default 1e-5)")
    parser.add_argument("--scan-step", type=float, default=0.25, metavar="DEG",
                        help="increment of the rest-angle change while following the start "
                             "state [deg] (default 0.25)")
    parser.add_argument("--max-change", type=float, default=170.0, metavar="DEG",
                        help="largest rest-angle change tried [deg] (default 170; a change "
                             "never takes a rest angle out of (0, 360) deg)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(func=run)


def _row(s, barrier):
    """One group's line: the change and moment at the snap (or where the scan ended)."""
    ratio = s.work / barrier if barrier > 0 else math.nan
    reached = not math.isnan(s.snap_change)
    return (s.group, s.creases, "yes" if s.switched else "no",
            f"{s.snap_change_deg:.5f}" if reached else "-",
            f"{s.moment:.5g}" if reached else "-",
            f"{s.max_crease_moment:.4g}" if reached else "-",
            f"{s.work:.5g} ({ratio:.3g} Eb)" if reached else "-",
            f"{s.landing_height:.9f}" if s.switched else "-", s.message)


def _summary(s) -> dict:
    out = {key: finite_or_none(getattr(s, key)) for key in (
        "snap_change", "resolution", "moment", "max_crease_moment", "work", "snap_energy",
        "start_height", "snap_height", "landing_height", "landing_energy", "landing_tilt")}
    out.update(group=s.group, creases=s.creases, switched=s.switched, message=s.message,
               snap_change_deg=finite_or_none(s.snap_change_deg))
    return out


def run(args) -> int:
    from kresling.analyses.switching import switching

    design = design_from_args(args)
    parameters = specimen_parameters_from_args(args)
    result = switching(design, parameters=parameters, resolution_deg=args.resolution,
                       scan_step_deg=args.scan_step, max_change_deg=args.max_change)
    snap = result.snap
    answer = {(by, forward): result.least_actuation(by, forward)
              for by in ("snap_change", "moment") for forward in (True, False)}
    if args.json:
        print_json({"design": {"n": design.n, "lam": design.lam, "Lc": design.Lc,
                               "R": design.R},
                    "parameters": describe(parameters), "bistable": snap.bistable,
                    "energy_barrier": finite_or_none(snap.energy_barrier),
                    "extended_height": snap.extended_height,
                    "stable_height": finite_or_none(snap.stable_height),
                    "forward": [_summary(s) for s in result.forward],
                    "backward": [_summary(s) for s in result.backward],
                    "least_change": {"forward": answer["snap_change", True],
                                     "backward": answer["snap_change", False]},
                    "least_moment": {"forward": answer["moment", True],
                                     "backward": answer["moment", False]}})
        return 0
    print(f"snap-through test: {snap.bistability}; energy barrier Eb = "
          f"{snap.energy_barrier:.6g} N*mm; extended height {snap.extended_height:.6f} mm")
    if not snap.bistable:
        print("the cell is not bistable: there is no other state to switch to")
        return 0
    header = ("group", "creases", "switched", "change [deg]", "moment [N*mm]", "max crease [N*mm]",
              "work [N*mm]", "lands at [mm]", "")
    for title, switches, target in (
            ("extended -> contracted", result.forward, snap.stable_height),
            ("contracted -> extended", result.backward, snap.extended_height)):
        print(f"\n{title} (the other state's height {target:.6f} mm)")
        print_table([_row(s, snap.energy_barrier) for s in switches], header)
    print("\nchange: of the rest angles at the snap (or where the scan ended); moment: summed "
          "over the driven creases there; work: of the actuation up to it (= the strain "
          "energy it added), beside the energy barrier Eb")
    for forward, title in ((True, "extended -> contracted"), (False, "contracted -> extended")):
        if answer["snap_change", forward]:
            print(f"least actuation, {title}: smallest rest-angle change: "
                  f"{answer['snap_change', forward]}; smallest summed moment: "
                  f"{answer['moment', forward]}")
        else:
            print(f"least actuation, {title}: no crease group switches the cell")
    print(summary_line(parameters))
    return 0
