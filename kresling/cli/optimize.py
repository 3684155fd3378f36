"""``kresling optimize``: the best design of one n over Lc x lambda, on the tests' exact
derivatives, under bounds on other metrics."""

from __future__ import annotations

import math
import sys

from kresling.cli._output import cli_names, print_json, print_table
from kresling.cli._specimen import add_specimen_arguments, specimen_parameters_from_args


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "optimize",
        help="the best design of one n, with bounds on other metrics (exact gradients)",
        description="Maximise a metric (default the K_B ratio of the 0.001 rad protocol) over "
                    "the contracted height Lc [mm] and the angle ratio lambda for one n, with "
                    "SLSQP on the bending and snap-through tests' exact derivatives, starting "
                    "from the best design of a coarse grid. Constraints bound other metrics, "
                    "e.g. --min kb_con 0.3 (a joint not too soft) or --max snap_force 5.",
    )
    parser.add_argument("--n", type=int, required=True,
                        help="sides of the base polygon, a count (even for the bending metrics)")
    parser.add_argument("--metric", default="kb_ratio",
                        help="the metric column to maximise (default kb_ratio)")
    parser.add_argument("--Lc", type=float, nargs=2, metavar=("MIN", "MAX"),
                        help="contracted-height bounds [mm] (default R/2 to 2R)")
    parser.add_argument("--lam", type=float, nargs=2, metavar=("MIN", "MAX"),
                        default=[0.7, 0.9], help="angle-ratio bounds (default 0.7 0.9)")
    parser.add_argument("--R", type=float, default=30.0, help="circumradius [mm] (default 30)")
    parser.add_argument("--min", nargs=2, action="append", default=[], metavar=("METRIC", "VALUE"),
                        help="a floor on a metric column (repeatable)")
    parser.add_argument("--max", nargs=2, action="append", default=[], metavar=("METRIC", "VALUE"),
                        help="a ceiling on a metric column (repeatable)")
    parser.add_argument("--differences", action="store_true",
                        help="forward differences instead of the exact derivatives (to compare)")
    add_specimen_arguments(parser)
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(func=run)


def _bounds(args) -> dict:
    """{column: (low, high)} from --min and --max."""
    constraints = {}
    for option, pairs, end in (("--min", args.min, 0), ("--max", args.max, 1)):
        for column, text in pairs:
            try:
                value = float(text)
            except ValueError:
                raise ValueError(f"{option} {column} {text!r} is invalid: the bound must be a "
                                 "number") from None
            if not math.isfinite(value):
                raise ValueError(f"{option} {column} {text!r} is invalid: must be finite")
            low, high = constraints.get(column, (None, None))
            constraints[column] = (value, high) if end == 0 else (low, value)
    return constraints


def run(args) -> int:
    from kresling.sweeps.optimize import optimize_design

    parameters = specimen_parameters_from_args(args)
    with cli_names({"n": "--n", "constraints": "--min/--max"}):
        best = optimize_design(args.n, args.metric, Lc=args.Lc, lam=tuple(args.lam), R=args.R,
                               constraints=_bounds(args), workers=1, parameters=parameters,
                               gradient="differences" if args.differences else "exact")
    d = best.design
    result = {"design": {"n": d.n, "lam": d.lam, "Lc": d.Lc, "R": d.R}, "metric": best.metric,
              "value": best.value, "values": {k: v for k, v in best.values.items()
                                              if isinstance(v, (int, float))},
              "active": list(best.active), "success": best.success, "message": best.message,
              "evaluations": best.evaluations}
    if args.json:
        print_json(result)
    else:
        rows = [("n", d.n, ""), ("Lc", d.Lc, "mm"), ("lam", d.lam, ""), ("R", d.R, "mm"),
                (best.metric, best.value, ""),
                *((k, v, "") for k, v in result["values"].items() if k != best.metric)]
        print_table(rows, ("quantity", "value", "unit"))
        print(f"\nactive bounds: {', '.join(best.active) or 'none'}; {best.evaluations} designs "
              f"evaluated by the optimiser; {best.message}")
    if not best.success:   # said on stderr too, as every command's exit 1
        print(f"kresling optimize: {best.message}", file=sys.stderr)
    return 0 if best.success else 1
