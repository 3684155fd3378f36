"""``kresling bend``: the three-point bending test in both states, the K_B ratio and the
snap force of one design (thesis sections 3.4-3.5)."""

from __future__ import annotations

import math
import sys

from kresling.cli._output import check_output_file, cli_names, print_json, print_table
from kresling.cli._specimen import (add_specimen_arguments, describe,
                                    specimen_parameters_from_args, summary_line)
from kresling.cli.design import add_design_arguments, design_from_args


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
    add_specimen_arguments(parser)
    parser.add_argument("--deflection-rad", type=float, metavar="ANGLE",
                        help="drive to this deflection angle [rad] in 10 steps instead (the "
                             "thesis's parametric study used 0.001 rad = 0.057 deg)")
    parser.add_argument("--gradient", action="store_true",
                        help="also the exact derivatives of K_ext, K_con, their ratio, the snap "
                             "force and the energy barrier with respect to lam, Lc [mm], R "
                             "[mm], the facet sheet's thickness [mm] and kf [N/rad] (the tests "
                             "run again with their whole paths differentiated)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--plot", metavar="FILE.png",
                        help="write the moment-angle figure (like thesis figures 3.5-3.7)")
    parser.add_argument("--view", metavar="FILE.html",
                        help="write an interactive page of the bending test in both states "
                             "(two specimens animated together beside both moment-angle "
                             "curves; FILE.html#frame=K opens at increment K)")
    parser.add_argument("--view-frames", type=int, default=100, metavar="M",
                        help="at most M increments in the page, a count (default 100)")
    parser.set_defaults(func=run)


def finite_or_none(value):
    """A float for JSON, or None where the analysis has no value (NaN)."""
    return None if value is None or (isinstance(value, float) and math.isnan(value)) else value


def run(args) -> int:
    from kresling.analyses import bending_stiffness, snap_through

    design = design_from_args(args)
    parameters = specimen_parameters_from_args(args)
    # Every output file is checked before the runs (a bad path fails in a second, not after
    # the analysis).
    if args.plot:
        check_output_file("--plot", args.plot)
    if args.view:
        from kresling.view import check_writable

        check_writable(args.view)
    if args.deflection_rad is None:
        protocol, options = "5mm", {}
    else:
        if not (math.isfinite(args.deflection_rad) and args.deflection_rad > 0):
            raise ValueError(f"--deflection-rad = {args.deflection_rad!r} is invalid: must be a "
                             "positive angle [rad]")
        protocol, options = "0.001rad", {"deflection_angle": args.deflection_rad}
    with cli_names(BEND_OPTIONS):
        bending = bending_stiffness(design, protocol, parameters=parameters, **options)
    snap = snap_through(design, parameters=parameters)
    runs = {"extended": bending.extended, "contracted": bending.contracted,
            "snap_through": snap}
    partial = {name: r.travel_fraction for name, r in runs.items() if not r.completed}
    notes = _notes(bending, partial)
    result = {
        "design": {"n": design.n, "lam": design.lam, "Lc": design.Lc, "R": design.R},
        "kf": parameters.kf,
        "parameters": describe(parameters),
        "protocol": protocol if args.deflection_rad is None else f"{args.deflection_rad:g} rad",
        "K_ext": bending.extended.stiffness, "K_con": bending.contracted.stiffness,
        "ratio": bending.ratio, "snap_force": finite_or_none(snap.snap_force),
        "snap_displacement": finite_or_none(snap.snap_displacement), "bistable": snap.bistable,
        "completed": not partial,
        # Runs that stopped early, with the fraction of their travel reached: values read
        # from them are partial.
        "partial": partial,
        "notes": notes,
    }
    if args.gradient:
        from kresling.analyses import design_gradient

        with cli_names(BEND_OPTIONS):
            result["gradient"] = design_gradient(design, protocol, parameters=parameters,
                                                 **options).as_dict()["gradient"]
    if args.json:
        print_json(result)
    else:
        def mark(meaning, *names):
            stopped = [f"{name} run stopped at {partial[name]:.0%} of its travel"
                       for name in names if name in partial]
            return meaning + (f" - PARTIAL: {'; '.join(stopped)}" if stopped else "")

        rows = [("K_ext", result["K_ext"], "N*m/rad",
                 mark("bending stiffness, extended (1)", "extended")),
                ("K_con", result["K_con"], "N*m/rad",
                 mark("bending stiffness, contracted (0)", "contracted")),
                ("ratio", result["ratio"], "", mark("K_ext / K_con (eqn 23)", "extended",
                                                    "contracted")),
                ("snap_force", result["snap_force"], "N",
                 mark("first local maximum (section 3.5)", "snap_through")),
                ("bistable", result["bistable"], "", mark(snap.bistability, "snap_through"))]
        if args.deflection_rad is None:
            print("protocol: the middle polygon driven 5 mm in 350 increments (Table 3)")
        else:
            print(f"protocol: driven to a deflection of {args.deflection_rad:g} rad "
                  f"({math.degrees(args.deflection_rad):.4g} deg) in 10 increments")
        print_table(rows, ("quantity", "value", "unit", "meaning"))
        if args.gradient:
            _print_gradient(result["gradient"])
        print(f"\n{summary_line(parameters)}")
        for note in notes:
            print(f"\nnote: {note}")
    if args.plot:
        _plot(bending, args.plot)
        print(f"wrote {args.plot} (moment-angle figure)", file=sys.stderr if args.json
              else sys.stdout)
    if args.view:
        from kresling.view import view_bending, write_html

        with cli_names(BEND_OPTIONS):
            # The results mark a run that stopped early on the page as in the table.
            page = view_bending(design, protocol if args.deflection_rad is None else "0.001rad",
                                results=bending, max_frames=args.view_frames,
                                parameters=parameters, **options)
        write_html(page, args.view)
        print(f"wrote {args.view} (interactive page)", file=sys.stderr if args.json
              else sys.stdout)
    for name, run_result in runs.items():
        if not run_result.completed:
            print(f"kresling bend: warning: the {name.replace('_', '-')} run stopped at "
                  f"{partial[name]:.0%} of its travel, so the values read from it are partial: "
                  f"{run_result.message}", file=sys.stderr)
    return 0 if result["completed"] else 1


def _print_gradient(gradient) -> None:
    """One row per quantity, one column per design variable."""
    variables = list(next(iter(gradient.values())))
    units = {"lam": "1", "Lc": "mm", "R": "mm", "thickness": "mm", "kf": "N/rad"}
    print("\nderivatives (per unit of each variable: " +
          ", ".join(f"{v} [{units.get(v, '')}]" for v in variables) + ")")
    rows = [(q, *(math.nan if row[v] is None else row[v] for v in variables))
            for q, row in gradient.items()]
    print_table(rows, ("quantity", *(f"d/d{v}" for v in variables)))


#: The library's names of the bending test's options and the command's.
BEND_OPTIONS = {"deflection_angle": "--deflection-rad", "view_frames": "--view-frames",
                "max_frames": "--view-frames"}


def _notes(bending, partial) -> list:
    """What a reader should know about the numbers beyond their values."""
    notes = []
    if "extended" not in partial and "contracted" not in partial and bending.ratio < 1:
        stable = bending.extended.stable and bending.contracted.stable
        notes.append(
            f"K_con > K_ext (ratio {bending.ratio:.3g} < 1): this design is stiffer contracted "
            f"than extended, unlike every design of the thesis's study (n = 4 to 10, lambda "
            f"0.7 to 0.9, Lc = R/2 to 2R: ratios 1.5 to 22), where the contracted state is "
            f"the compliant one. Both runs completed"
            + (" on stable equilibria" if stable else ", but not every increment ended on a "
               "stable equilibrium") + ": this is what the model predicts, but look at the "
            "moment-angle curves (--plot) before relying on it")
    return notes


def _plot(bending, path) -> None:
    import matplotlib

    matplotlib.use("Agg")  # files only: never open a window
    from kresling.analyses.plots import plot_moment_angle

    d = bending.extended.design
    ax = plot_moment_angle(bending, title=f"n = {d.n}, Lc = {d.Lc:g} mm, λ = {d.lam:g}: "
                                          f"K_B ratio {bending.ratio:.2f}")
    ax.figure.savefig(path, dpi=150)
