"""``kresling snap``: the snap-through test of one cell (thesis section 3.5)."""

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
                        help="write the force-travel figure (like thesis figure 3.16)")
    parser.add_argument("--view", metavar="FILE.html",
                        help="write an interactive page of the snap-through path beside the "
                             "force-travel curve (FILE.html#frame=K opens at increment K)")
    parser.set_defaults(func=run)


def run(args) -> int:
    from kresling.analyses import snap_through

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
