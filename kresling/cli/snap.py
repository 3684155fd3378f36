"""``kresling snap``: the snap-through test of one cell (thesis section 3.5); with
``--dynamic`` the snap in time under a step load, with ``--modes`` the cell's natural
frequencies in its states."""

from __future__ import annotations

import math
import sys

from kresling.cli._output import check_output_file, cli_names, print_json, print_table
from kresling.cli.bend import finite_or_none
from kresling.cli._specimen import (add_specimen_arguments, describe,
                                    specimen_parameters_from_args, summary_line)
from kresling.cli.design import add_design_arguments, design_from_args

# (key, unit, meaning) in the order the table prints them.
_ROWS = (
    ("snap_force", "N", "first local maximum of the force"),
    ("snap_displacement", "mm", "travel at that maximum"),
    ("energy_barrier", "N*mm", "strain energy at the unstable state (work up to it)"),
    ("unstable_displacement", "mm", "travel at the unstable state (force back at zero)"),
    ("minimum_force", "N", "smallest force after the peak"),
    ("bistable", "", "the released cell rests away from its extended state"),
    ("stable_height", "mm", "cell height of the second stable state"),
    ("stable_tilt", "rad", "its top polygon's tilt"),
    ("extended_height", "mm", "Le"),
    ("contracted_height", "mm", "Lc"),
)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "snap",
        help="snap-through force, energy barrier and bistability of one cell",
        description="Drive one cell from its extended to its contracted height (bottom "
                    "polygon fixed, top polygon pushed down, free to twist) and report the "
                    "snap force, the energy barrier and whether the model is bistable.",
    )
    add_design_arguments(parser)
    add_specimen_arguments(parser)
    parser.add_argument("--steps", type=int, default=100,
                        help="displacement increments from Le to Lc, a count (default 100); "
                             "too few to resolve the force peak draw a warning")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--plot", metavar="FILE.png",
                        help="write the force-travel figure (like thesis figure 3.16); with "
                             "--dynamic, the height against time")
    dynamic = parser.add_argument_group(
        "dynamics (masses: the thesis's PET laminate, see docs/dynamics.md)")
    dynamic.add_argument("--dynamic", action="store_true",
                         help="push the cell with a step load just above its snap force, "
                              "hold it, release it, and follow it in time: how long the jump "
                              "takes, the overshoot, where it comes to rest")
    dynamic.add_argument("--margin", type=float, default=0.05,
                         help="with --dynamic: the load's excess over the snap force, a "
                              "fraction (default 0.05: 5 %% above)")
    dynamic.add_argument("--damping", type=float, default=0.05,
                         help="with --dynamic: damping ratio of the cell's lowest extended "
                              "mode (mass-proportional damping; default 0.05)")
    dynamic.add_argument("--duration", type=float, default=2.0,
                         help="with --dynamic: time integrated over [s] (default 2)")
    dynamic.add_argument("--hold", type=float, default=0.3,
                         help="with --dynamic: how long the load is held [s] (default 0.3)")
    dynamic.add_argument("--eccentricity", type=float, default=0.1,
                         help="with --dynamic: the push's offset from the axis [mm] "
                              "(default 0.1; on the axis the cell stays level for a while)")
    dynamic.add_argument("--time-step", type=float, default=2e-4,
                         help="with --dynamic: [s] (default 2e-4)")
    dynamic.add_argument("--modes", type=int, nargs="?", const=6, metavar="K",
                         help="the K lowest natural frequencies (a count, default 6) of the "
                              "cell extended, contracted and in the state it snaps to")
    parser.add_argument("--view", metavar="FILE.html",
                        help="write an interactive page of the snap-through path beside the "
                             "force-travel curve (FILE.html#frame=K opens at increment K)")
    parser.set_defaults(func=run)


def run(args) -> int:
    from kresling.analyses import snap_through

    if args.dynamic and args.modes is not None:
        raise ValueError("dynamic: --dynamic and --modes are two analyses; give one")
    if (args.dynamic or args.modes is not None) and args.view:
        raise ValueError("view: --view shows the static path; leave it out with "
                         "--dynamic or --modes")
    if args.modes is not None and args.plot:
        raise ValueError("plot: --plot draws the static or the dynamic test, not --modes")
    if args.dynamic:
        return _run_dynamic(args)
    if args.modes is not None:
        return _run_modes(args)
    design = design_from_args(args)
    # Every output file is checked before the run, not after it.
    if args.plot:
        check_output_file("--plot", args.plot)
    if args.view:
        from kresling.view import check_writable

        check_writable(args.view)
    parameters = specimen_parameters_from_args(args)
    with cli_names({"steps": "--steps"}):
        result = snap_through(design, steps=args.steps, parameters=parameters)
    summary = {key: finite_or_none(value) for key, value in result.summary().items()}
    summary["design"] = {"n": design.n, "lam": design.lam, "Lc": design.Lc, "R": design.R}
    summary["kf"] = parameters.kf
    summary["parameters"] = describe(parameters)
    summary["stable_tilt_deg"] = finite_or_none(math.degrees(result.stable_tilt))
    if args.json:
        print_json(summary)
    else:
        partial = (f" - PARTIAL: the run stopped at {result.travel_fraction:.0%} of its travel"
                   if result.partial else "")
        rows = []
        for key, unit, meaning in _ROWS:
            value = summary[key]
            if unit == "rad" and value is not None:
                value, unit = f"{value:.10g} ({math.degrees(value):.4g} deg)", unit
            rows.append((key, value, unit, meaning + partial))
        print_table(rows, ("quantity", "value", "unit", "meaning"))
        print(f"\n{result.bistability}")
        print(summary_line(parameters))
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")  # files only: never open a window
        from kresling.analyses.plots import plot_snap_through

        plot_snap_through(result).figure.savefig(args.plot, dpi=150)
        print(f"wrote {args.plot} (force-travel figure)",
              file=sys.stderr if args.json else sys.stdout)
    if args.view:
        from kresling.view import view_snap_through, write_html

        write_html(view_snap_through(design, steps=args.steps, result=result,
                                     parameters=parameters), args.view)
        print(f"wrote {args.view} (interactive page)",
              file=sys.stderr if args.json else sys.stdout)
    if result.resolution:
        advice = result.resolution.replace("raise steps", "raise --steps")
        print(f"kresling snap: warning: {advice}", file=sys.stderr)
    if not result.completed:
        print(f"kresling snap: warning: the run stopped at {result.travel_fraction:.0%} of its "
              f"travel, so the values are partial: {result.message}", file=sys.stderr)
        return 1
    return 0


_DYNAMIC_ROWS = (
    ("snap_force", "N", "the static test's snap force"),
    ("load", "N", "the step load"),
    ("jump_time", "s", "from the step to the stable state's travel, first reached"),
    ("peak_travel", "mm", "the largest travel (under the held load)"),
    ("overshoot", "mm", "how far the cell swings past its stable state's travel"),
    ("loaded_travel", "mm", "travel when the load is removed"),
    ("rebound", "mm", "after the release, the swing back above the stable height"),
    ("settling_time", "s", "last time outside 2 % of the stable travel about the end"),
    ("settled_height", "mm", "where the cell comes to rest"),
    ("stable_height", "mm", "the static test's second stable state"),
    ("height_error", "mm", "settled minus static"),
    ("settled_tilt", "rad", "the top polygon's tilt at rest"),
    ("final_kinetic", "N*mm", "kinetic energy at the end"),
)


def _run_dynamic(args) -> int:
    from kresling.analyses.snap_dynamics import plot_snap_in_time, snap_in_time

    design = design_from_args(args)
    if args.plot:
        check_output_file("--plot", args.plot)
    parameters = specimen_parameters_from_args(args)
    names = {"time_step": "--time-step", "margin": "--margin",
             "damping": "--damping", "duration": "--duration", "hold": "--hold",
             "eccentricity": "--eccentricity"}
    with cli_names(names):
        result = snap_in_time(design, margin=args.margin, damping=args.damping,
                              eccentricity=args.eccentricity, hold=args.hold,
                              duration=args.duration, time_step=args.time_step,
                              parameters=parameters, steps=args.steps)
    summary = {key: finite_or_none(value) if isinstance(value, float) else value
               for key, value in result.summary().items()}
    summary["design"] = {"n": design.n, "lam": design.lam, "Lc": design.Lc, "R": design.R}
    summary["mass"] = _cell_mass(design, parameters)
    if args.json:
        print_json(summary)
    else:
        print_table([(key, summary[key], unit, meaning) for key, unit, meaning in _DYNAMIC_ROWS],
                    ("quantity", "value", "unit", "meaning"))
        print(f"\ncell mass {summary['mass'] * 1e6:.4g} g (PET laminate); mass damping "
              f"alpha = {result.mass_damping:.4g} 1/s")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")  # files only: never open a window
        plot_snap_in_time(result).figure.savefig(args.plot, dpi=150)
        print(f"wrote {args.plot} (height against time)",
              file=sys.stderr if args.json else sys.stdout)
    if result.completed and not result.at_rest:
        print(f"kresling snap: warning: the cell has not come to rest (kinetic energy "
              f"{result.final_kinetic:.3g} N*mm at the end, {result.height_error:+.3g} mm from "
              "the static stable height): raise --duration or --damping, or lower "
              "--time-step", file=sys.stderr)
    elif result.completed and abs(result.height_error) > 1e-3:
        print(f"kresling snap: warning: the cell came to rest at {result.settled_height:.4g} mm, "
              f"not in the static stable state ({result.static.stable_height:.4g} mm): hold "
              "the load longer (--hold) or raise --margin", file=sys.stderr)
    if not result.completed:
        print(f"kresling snap: warning: the integration stopped at t = {result.time[-1]:.4g} s: "
              f"{result.message}", file=sys.stderr)
        return 1
    return 0


def _cell_mass(design, parameters) -> float:
    from kresling.analyses.snap_dynamics import snap_test_cell

    return float(snap_test_cell(design, parameters)[1].sum())


def _run_modes(args) -> int:
    from kresling.analyses.cell_frequencies import cell_frequencies

    design = design_from_args(args)
    with cli_names({"k": "--modes"}):
        f = cell_frequencies(design, k=args.modes, parameters=specimen_parameters_from_args(args))
    rows = f.rows()
    out = {"design": {"n": design.n, "lam": design.lam, "Lc": design.Lc, "R": design.R},
           "mass": f.mass, "ratio": f.ratio, "snapped_ratio": finite_or_none(f.snapped_ratio),
           "modes": rows}
    if args.json:
        print_json(out)
        return 0
    print_table([(r["mode"], r["extended_hz"], r["contracted_hz"],
                  "" if r["snapped_hz"] is None else r["snapped_hz"],
                  f"{r['extended_mass_x']:.2f} {r['extended_mass_y']:.2f} "
                  f"{r['extended_mass_z']:.2f}") for r in rows],
                ("mode", "extended [Hz]", "contracted [Hz]", "snapped [Hz]",
                 "effective mass x y z (extended)"))
    print(f"\nlowest frequency extended / contracted: {f.ratio:.4g} (stiffness ratio "
          f"{f.ratio ** 2:.4g})")
    if f.snapped is not None:
        print(f"lowest frequency extended / snapped: {f.snapped_ratio:.4g}")
    print(f"cell mass {f.mass * 1e6:.4g} g (PET laminate), bottom polygon held")
    return 0
