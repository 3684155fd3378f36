"""``kresling design``: the derived geometry of one generalized Kresling cell."""

from __future__ import annotations

from kresling.cli._output import degrees, print_json, print_table
from kresling.geometry import Design

# (key, unit, meaning) in the order the table prints them.
_ROWS = (
    ("n", "", "sides of the base polygon"),
    ("R", "mm", "circumradius"),
    ("lam", "", "angle ratio lambda"),
    ("Lc", "mm", "contracted height"),
    ("chirality", "", "handedness (+1/-1)"),
    ("phi", "rad", "pi / n"),
    ("gamma", "rad", "half the polygon's internal angle (eqn 2)"),
    ("P", "mm", "polygon side (eqn 1)"),
    ("V", "mm", "traditional valley crease (eqn 3)"),
    ("M", "mm", "traditional mountain crease (eqn 4)"),
    ("Vg", "mm", "generalized valley crease (eqn 6)"),
    ("Mg", "mm", "generalized mountain crease (eqn 7)"),
    ("theta_g", "rad", "flat-pattern facet angle (eqn 5)"),
    ("alpha0", "rad", "twist, contracted state"),
    ("alpha_e", "rad", "twist, extended state"),
    ("Le", "mm", "extended height"),
    ("Psi_con", "rad", "facet angle vs base polygon, contracted"),
    ("Psi_ext", "rad", "facet angle vs base polygon, extended"),
    ("Psi_ratio", "", "Psi_ext / Psi_con"),
)


def add_design_arguments(parser, defaults=None, chirality=True) -> None:
    """The design variables every design-based subcommand takes.

    ``defaults``, ``(n, lam, Lc, ...)``, makes them optional with those values (the arm's
    subcommands default to the thesis's optimum); without it they are required. The
    handedness is left out with ``chirality=False`` (the arm alternates it cell by cell)."""
    variables = (("--n", int, "sides of the base polygon, a count (>= 3)"),
                 ("--lam", float, "angle ratio lambda, dimensionless: 0.5 < lam < 1"),
                 ("--Lc", float, "contracted height [mm], >= 0"))
    for k, (name, kind, text) in enumerate(variables):
        if defaults is None:
            parser.add_argument(name, type=kind, required=True, help=text)
        else:
            parser.add_argument(name, type=kind, default=defaults[k],
                                help=f"{text} (default {defaults[k]:g})")
    parser.add_argument("--R", type=float, default=30.0, help="circumradius [mm] (default 30)")
    if chirality:
        parser.add_argument("--chirality", type=int, default=1, choices=(1, -1),
                            help="handedness, +1 or -1 (default +1)")


def design_from_args(args) -> Design:
    return Design(args.n, args.lam, args.Lc, args.R, args.chirality)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "design",
        help="derived geometry of a generalized Kresling cell",
        description="Print every derived quantity of a generalized Kresling cell "
                    "(thesis eqns 1-9; lengths in mm, angles in rad with degrees beside "
                    "them). With --json, angles are in rad and a quantity that is infinite "
                    "(Psi_ratio at Lc = 0, where Psi_con = 0) is the string \"inf\".",
    )
    add_design_arguments(parser)
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(func=run)


def run(args) -> int:
    quantities = design_from_args(args).quantities()
    if args.json:
        print_json(quantities, infinite_as_text=True)
    else:
        print_table([(k, quantities[k], unit, degrees(quantities[k]) if unit == "rad" else "",
                      meaning) for k, unit, meaning in _ROWS],
                    ("quantity", "value", "unit", "[deg]", "meaning"))
    return 0
