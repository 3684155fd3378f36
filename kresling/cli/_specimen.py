"""The specimen's material and model options, shared by ``bend``, ``snap`` and ``sweep``:
the crease stiffness ``--kf``, the other elements' ratios to it, cut or intact mountain
creases and MERLIN2's duplicated elements or one element per edge.

Every option has the thesis's value as its default, so a command without them reproduces
the thesis; the ratios are to ``--kf``, so changing ``--kf`` alone scales every element.
"""

from __future__ import annotations

import math

# (option, SpecimenParameters field, default, help): stiffness ratios to kf.
_RATIOS = (
    ("--valley-ratio", "valley_factor", 1.0,
     "hinges on the valley creases: RATIO x kf (default 1)"),
    ("--polygon-edge-ratio", "polygon_edge_factor", 1.0,
     "hinges on the polygons' edges: RATIO x kf (default 1)"),
    ("--spoke-ratio", "spoke_factor", 10.0,
     "hinges on the polygons' spokes, the flat fan inside each polygon: RATIO x kf "
     "(default 10)"),
    ("--bar-ratio", "modulus_factor", 1e5,
     "bar modulus C0 = RATIO x kf, in N/mm^2 with kf in N/rad (default 1e5: C0 = 4700 "
     "N/mm^2 and EA = 4700 N for a bar of area 1 mm^2 at the default kf)"),
)

#: What ``--topology`` names: the value of ``SpecimenParameters.duplicate_shared_edges``.
TOPOLOGIES = {"duplicated": True, "single": False}


def add_specimen_arguments(parser) -> None:
    """``--kf``, the stiffness ratios, ``--mountain`` and ``--topology``, in one group."""
    group = parser.add_argument_group(
        "material and model (defaults: the thesis's Appendix B values)")
    group.add_argument("--kf", type=float, default=0.047, metavar="N/RAD",
                       help="crease stiffness per unit length of crease [N/rad] (default "
                            "0.047, the thesis's measured value); every other element keeps "
                            "its ratio to it unless set below")
    for option, _, _, text in _RATIOS:
        group.add_argument(option, type=float, metavar="RATIO", help=text)
    group.add_argument("--mountain", choices=("cut", "intact"), default="cut",
                       help="mountain creases cut through, as in the thesis's specimens (no "
                            "hinge, a bar of area 0.01 mm^2; default), or intact (a hinge of "
                            "kf per unit length and a bar of area 1 mm^2, like the valleys)")
    group.add_argument("--topology", choices=tuple(TOPOLOGIES), default="duplicated",
                       help="duplicated: MERLIN2's elements, coincident bars and hinges on "
                            "every edge shared by three triangles (the intermediate polygons "
                            "of a stack), the thesis's default; single: one bar per edge and "
                            "k-1 hinges on an edge of k triangles, softer. The choice moves K_con "
                            "of the Table 3 specimens by 1.8 to about 8 %% (5 mm protocol; up "
                            "to 8.4 %% for n = 10, Lc = 15 mm, lambda = 0.9, and 9.5 %% "
                            "linearised) and K_ext by under 1 %%; a single cell "
                            "(snap-through) not at all")


def specimen_parameters_from_args(args):
    """The :class:`~kresling.model.SpecimenParameters` of the parsed options.

    Raises
    ------
    ValueError
        Naming the option, its value and what is allowed.
    """
    from kresling.model import SpecimenParameters

    if not (math.isfinite(args.kf) and args.kf > 0):
        raise ValueError(f"--kf = {args.kf!r} is invalid: must be a finite stiffness > 0 [N/rad]")
    values = {"kf": args.kf, "duplicate_shared_edges": TOPOLOGIES[args.topology]}
    for option, name, _, _ in _RATIOS:
        value = getattr(args, name_of(option))
        if value is None:
            continue
        smallest = "> 0" if name == "modulus_factor" else ">= 0"
        if not (math.isfinite(value) and (value > 0 if name == "modulus_factor" else value >= 0)):
            raise ValueError(f"{option} = {value!r} is invalid: must be a finite ratio "
                             f"{smallest}")
        values[name] = value
    return SpecimenParameters(**values).with_mountain_creases(args.mountain)


def name_of(option: str) -> str:
    """argparse's destination of ``option`` (``--spoke-ratio`` -> ``spoke_ratio``)."""
    return option.lstrip("-").replace("-", "_")


def describe(parameters) -> dict:
    """The parameters as the commands print them in JSON: every field of
    ``SpecimenParameters`` plus ``mountain_creases`` (cut, intact or custom)."""
    return dict(parameters.as_dict(), mountain_creases=parameters.mountain_creases)


def summary_line(parameters) -> str:
    """One line saying which material and model the numbers are for: the thesis's, or what
    differs from it (``kf = 0.094 N/rad; mountain creases intact``)."""
    from kresling.model import SpecimenParameters

    thesis = SpecimenParameters()
    changes = []
    if parameters.kf != thesis.kf:
        changes.append(f"kf = {parameters.kf:g} N/rad")
    for option, name, _, _ in _RATIOS:
        if getattr(parameters, name) != getattr(thesis, name):
            changes.append(f"{name_of(option).replace('_', ' ')} = {getattr(parameters, name):g}")
    if parameters.mountain_creases != "cut":
        changes.append(f"mountain creases {parameters.mountain_creases}")
    if not parameters.duplicate_shared_edges:
        changes.append("one element per edge (--topology single)")
    if not changes:
        return ("material and model: the thesis's (kf = 0.047 N/rad, its stiffness ratios, "
                "cut mountain creases, MERLIN2's duplicated elements)")
    return "material and model: the thesis's but " + "; ".join(changes)
