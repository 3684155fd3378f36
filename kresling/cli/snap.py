"""``kresling snap``: the snap-through test of one cell (thesis section 3.5)."""

from __future__ import annotations

import sys

from kresling.cli._output import print_json, print_table
from kresling.cli.bend import finite_or_none
from kresling.cli.design import (add_design_arguments, add_stiffness_argument, design_from_args,
                                 specimen_parameters_from_args)

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
    add_stiffness_argument(parser)
    parser.add_argument("--steps", type=int, default=100,
                        help="displacement increments (default 100)")
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
    if args.view:
        from kresling.view import check_writable

        check_writable(args.view)   # before the run, not after
    parameters = specimen_parameters_from_args(args)
    result = snap_through(design, steps=args.steps, parameters=parameters)
    summary = {key: finite_or_none(value) for key, value in result.summary().items()}
    summary["design"] = {"n": design.n, "lam": design.lam, "Lc": design.Lc, "R": design.R}
    summary["kf"] = parameters.kf
    if args.json:
        print_json(summary)
    else:
        print_table([(k, summary[k], unit, meaning) for k, unit, meaning in _ROWS],
                    ("quantity", "value", "unit", "meaning"))
        print(f"\n{result.bistability}")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")  # files only: never open a window
        from kresling.analyses.plots import plot_snap_through

        plot_snap_through(result).figure.savefig(args.plot, dpi=150)
    if args.view:
        from kresling.view import view_snap_through, write_html

        write_html(view_snap_through(design, steps=args.steps, result=result,
                                     parameters=parameters), args.view)
    if not result.completed:
        print(f"kresling snap: warning: the run stopped early: {result.message}", file=sys.stderr)
        return 1
    return 0
