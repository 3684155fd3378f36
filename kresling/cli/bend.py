"""``kresling bend``: the three-point bending test in both states, the K_B ratio and the
snap force of one design (thesis sections 3.4-3.5)."""

from __future__ import annotations

import math
import sys

from kresling.cli._output import print_json, print_table
from kresling.cli.design import (add_design_arguments, add_stiffness_argument, design_from_args,
                                 specimen_parameters_from_args)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "bend",
        help="bending stiffness in both states, their ratio and the snap force",
        description="Run the thesis's three-point bending test on a four-cell specimen in "
                    "both stable states (5 mm in 350 steps, as for Table 3, unless "
                    "--deflection-rad is given) and the snap-through test of one cell. "
                    "K_B in N*m/rad, forces in N.",
    )
    add_design_arguments(parser)
    add_stiffness_argument(parser)
    parser.add_argument("--deflection-rad", type=float, metavar="ANGLE",
                        help="drive to this deflection angle in 10 steps instead (the thesis's "
                             "parametric study used 0.001)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--plot", metavar="FILE.png",
                        help="write the moment-angle figure (like thesis figures 3.5-3.7)")
    parser.add_argument("--view", metavar="FILE.html",
                        help="write an interactive page of the bending test in both states "
                             "(two specimens animated together beside both moment-angle "
                             "curves; FILE.html#frame=K opens at increment K)")
    parser.add_argument("--view-frames", type=int, default=100, metavar="M",
                        help="at most M increments in the page (default 100)")
    parser.set_defaults(func=run)


def finite_or_none(value):
    """A float for JSON, or None where the analysis has no value (NaN)."""
    return None if value is None or (isinstance(value, float) and math.isnan(value)) else value


def run(args) -> int:
    from kresling.analyses import bending_stiffness, snap_through

    design = design_from_args(args)
    parameters = specimen_parameters_from_args(args)
    if args.view:
        from kresling.view import check_writable

        check_writable(args.view)   # before the runs, not after
    if args.deflection_rad is None:
        protocol, options = "5mm", {}
    else:
        if not (math.isfinite(args.deflection_rad) and args.deflection_rad > 0):
            raise ValueError(f"--deflection-rad = {args.deflection_rad!r} is invalid: must be a "
                             "positive angle [rad]")
        protocol, options = "0.001rad", {"deflection_angle": args.deflection_rad}
    bending = bending_stiffness(design, protocol, parameters=parameters, **options)
    snap = snap_through(design, parameters=parameters)
    result = {
        "design": {"n": design.n, "lam": design.lam, "Lc": design.Lc, "R": design.R},
        "kf": parameters.kf,
        "protocol": protocol if args.deflection_rad is None else f"{args.deflection_rad:g} rad",
        "K_ext": bending.extended.stiffness, "K_con": bending.contracted.stiffness,
        "ratio": bending.ratio, "snap_force": finite_or_none(snap.snap_force),
        "snap_displacement": finite_or_none(snap.snap_displacement), "bistable": snap.bistable,
        "completed": bending.completed and snap.completed,
    }
    if args.json:
        print_json(result)
    else:
        rows = [("K_ext", result["K_ext"], "N*m/rad", "bending stiffness, extended (1)"),
                ("K_con", result["K_con"], "N*m/rad", "bending stiffness, contracted (0)"),
                ("ratio", result["ratio"], "", "K_ext / K_con (eqn 23)"),
                ("snap_force", result["snap_force"], "N", "first local maximum (section 3.5)"),
                ("bistable", result["bistable"], "", snap.bistability)]
        print_table(rows, ("quantity", "value", "unit", "meaning"))
    if args.plot:
        _plot(bending, args.plot)
    if args.view:
        from kresling.view import view_bending, write_html

        write_html(view_bending(design, protocol if args.deflection_rad is None else "0.001rad",
                                max_frames=args.view_frames, parameters=parameters, **options),
                   args.view)
    for name, run_result in (("extended", bending.extended), ("contracted", bending.contracted),
                             ("snap-through", snap)):
        if not run_result.completed:
            print(f"kresling bend: warning: the {name} run stopped early: {run_result.message}",
                  file=sys.stderr)
    return 0 if result["completed"] else 1


def _plot(bending, path) -> None:
    import matplotlib

    matplotlib.use("Agg")  # files only: never open a window
    from kresling.analyses.plots import plot_moment_angle

    d = bending.extended.design
    ax = plot_moment_angle(bending, title=f"n = {d.n}, Lc = {d.Lc:g} mm, λ = {d.lam:g}: "
                                          f"K_B ratio {bending.ratio:.2f}")
    ax.figure.savefig(path, dpi=150)
