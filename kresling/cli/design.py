"""``kresling design``: the derived geometry of one generalized Kresling cell."""

from __future__ import annotations

from kresling.cli._output import print_json, print_table
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


def add_design_arguments(parser) -> None:
    """The design variables every design-based subcommand takes."""
    parser.add_argument("--n", type=int, required=True, help="sides of the base polygon (>= 3)")
    parser.add_argument("--lam", type=float, required=True, help="angle ratio, 0.5 < lam < 1")
    parser.add_argument("--Lc", type=float, required=True, help="contracted height [mm], >= 0")
    parser.add_argument("--R", type=float, default=30.0, help="circumradius [mm] (default 30)")
    parser.add_argument("--chirality", type=int, default=1, choices=(1, -1),
                        help="handedness (default +1)")


def design_from_args(args) -> Design:
    return Design(args.n, args.lam, args.Lc, args.R, args.chirality)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "design",
        help="derived geometry of a generalized Kresling cell",
        description="Print every derived quantity of a generalized Kresling cell "
                    "(thesis eqns 1-9; mm, rad).",
    )
    add_design_arguments(parser)
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.set_defaults(func=run)


def run(args) -> int:
    quantities = design_from_args(args).quantities()
    if args.json:
        print_json(quantities)
    else:
        print_table([(k, quantities[k], unit, meaning) for k, unit, meaning in _ROWS],
                    ("quantity", "value", "unit", "meaning"))
    return 0


def add_stiffness_argument(parser) -> None:
    """``--kf``: the crease stiffness the specimen's elements scale with."""
    parser.add_argument("--kf", type=float, default=0.047, metavar="N/RAD",
                        help="crease stiffness per unit length [N/rad] (default 0.047, the "
                             "thesis's); the bars and the other hinges keep their ratios to it")


def specimen_parameters_from_args(args):
    """The specimen's stiffnesses from ``--kf`` (the thesis's ratios to it)."""
    import math

    from kresling.model import SpecimenParameters

    if not (math.isfinite(args.kf) and args.kf > 0):
        raise ValueError(f"--kf = {args.kf!r} is invalid: must be a finite stiffness > 0 [N/rad]")
    return SpecimenParameters(kf=args.kf)
