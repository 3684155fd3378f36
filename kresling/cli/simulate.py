"""``kresling simulate``: run a problem file on any crease pattern."""

from __future__ import annotations

import sys

from kresling.cli._output import check_output_folder, log_to_stderr, print_json, print_table


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "simulate",
        help="simulate any crease pattern (FOLD or OBJ) from a TOML problem file",
        description="Build the bar-and-hinge model of the pattern a problem file names "
                    "(panel split, material calibration, hinge laws), apply its supports and "
                    "loads, follow the equilibrium path (displacement control, force control, "
                    "MGDCM, or folding by crease actuation with [[actuation]] tables and "
                    "method = \"fold\") and write history.csv, displacements.csv, path.fold, "
                    "summary.json and view.html; or compute vibration modes (method = "
                    "\"modes\": modes.csv), or integrate the motion in time (method = "
                    "\"dynamic\" with a [dynamics] table: scheme \"newmark\", \"hht\" or "
                    "\"explicit\", time_step, duration, damping, gravity; each [[load]]'s "
                    "time \"step\", \"ramp\", a [t, factor] table or a harmonic; history.csv "
                    "with time and the energies, velocities.csv, a view played in scaled real "
                    "time). Node indices are 0-based in the pattern's "
                    "vertex order; N5B8 centre nodes follow the vertices. Exits 0 when the "
                    "path ran to its end (a fold: with every driven crease within 1 deg of "
                    "its target), 1 when it stopped early or a fold fell short (the files "
                    "still hold every converged increment), 2 for a bad problem, 130 when "
                    "Ctrl-C or a kill (SIGTERM) ended the path at its next increment (the "
                    "files hold the path so far; a second Ctrl-C stops at once). A path's "
                    "files are written as it goes (history.csv and displacements.csv row by "
                    "row, summary.json and path.fold rewritten whole), so a run killed any "
                    "other way leaves them too, its summary.json saying \"completed\": "
                    "false and \"interrupted\": true.",
    )
    parser.add_argument("problem", metavar="PROBLEM.toml", help="the problem file")
    parser.add_argument("--out", metavar="DIR",
                        help="output directory (default: a folder named after the problem "
                             "file, beside it)")
    parser.add_argument("--json", action="store_true",
                        help="print the summary as one JSON object")
    parser.add_argument("--no-view", action="store_true", help="do not write view.html")
    parser.add_argument("--every", type=int, metavar="K",
                        help="keep every K-th increment in the output files (the last "
                             "always; default: the problem's [output] every, else 1)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--fold-percent", type=float, metavar="P", dest="fold_percent",
                        help="method = \"fold\": fold every crease to P [%%] of its target "
                             "(in (0, 100]; replaces [analysis] fold_percent)")
    parser.add_argument("--snap-tolerance", type=float, metavar="PX", dest="snap_tolerance",
                        help="an SVG pattern: merge points closer than PX [the drawing's "
                             "units, CSS px] (replaces [pattern] snap_tolerance; default 3, or "
                             "1/200 of the drawing's size if less)")
    parser.set_defaults(func=run)


def run(args) -> int:
    from pathlib import Path

    from kresling.simulate import simulate

    problem = Path(args.problem)
    out = Path(args.out) if args.out else problem.with_suffix("")
    check_output_folder("--out", out)   # before the run, not after
    if args.every is not None and args.every < 1:
        raise ValueError(f"--every = {args.every} is invalid: must be an integer >= 1 (keep "
                         "every K-th increment, the last always)")
    overrides = {}
    if args.fold_percent is not None:
        overrides["analysis"] = {"fold_percent": args.fold_percent}
    if args.snap_tolerance is not None:
        overrides["pattern"] = {"snap_tolerance": args.snap_tolerance}
    if args.every is not None:   # the files written as the path goes keep the same rows
        overrides["output"] = {"every": args.every}
    with log_to_stderr("kresling.simulate", "simulate"):
        # The files are written as the path goes (a kill leaves the path so far), and
        # rewritten whole at its end.
        simulation = simulate(problem, overrides=overrides,
                              progress=False if args.quiet else None, stream=out)
        written = simulation.write(out, view=not args.no_view, every=args.every)
    summary = simulation.summary()
    summary["outputs"] = {name: str(path) for name, path in written.items()}
    if args.json:
        print_json(summary)
    else:
        rows = [(key, "" if summary[key] is None else summary[key])
                for key in ("method", "stepping", "nodes", "bars", "hinges", "supported_dofs",
                            "increments", "newton_iterations", "attempted_increments",
                            "attempted_newton_iterations", "final_load_factor", "time_step",
                            "stable_time_step", "final_time", "completed")
                if key in summary]   # (a modes run has no path: no increments)
        rows += [(f"mode {j + 1} [Hz]", f"{f:.6g}")
                 for j, f in enumerate(summary.get("frequencies_hz", []))]
        rows += [(f"stage {stage['name']}", f"{stage['method']}, "
                  + ("completed" if stage["completed"] else "stopped"))
                 for stage in summary.get("stages", [])]
        for key, value in summary.get("fold", {}).items():
            if key == "rigid_closure" and value:
                rows.append(("fold: rigid closure",
                             f"{value['incompatible']} of {value['vertices_checked']} interior "
                             f"vertices open by more than {value['tolerance_deg']:g} deg"
                             + (f" (worst {value['worst_deg']:.3g} deg, vertex "
                                f"{value['worst_vertex']})" if value["incompatible"] else "")))
            elif key != "worst":
                rows.append((f"fold: {key.replace('_', ' ')}", value))
        print_table(rows, ("quantity", "value"))
        print(f"\noutputs in {out}: " + ", ".join(Path(p).name for p in written.values()))
    if getattr(simulation, "interrupted", ""):
        print(f"kresling simulate: {simulation.message} in {out}", file=sys.stderr)
        return 130
    if not simulation.completed:
        if simulation.path.completed:   # a fold that ran to its end short of its targets
            print(f"kresling simulate: {simulation.message}", file=sys.stderr)
        else:
            print(f"kresling simulate: the path stopped early: {simulation.message}",
                  file=sys.stderr)
        return 1
    return 0
