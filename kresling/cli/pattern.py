"""``kresling pattern``: the cut file (SVG, DXF), crease pattern (FOLD) or preview (PNG) of a
cell or a two-cell module; or, with ``--from``, any crease pattern file (FOLD, SVG, OBJ)
converted to a FOLD file in mm with FOLD's assignments."""

from __future__ import annotations

from kresling.cli._output import check_output_file, print_json
from kresling.cli.design import add_design_arguments, design_from_args

# Optional parameters: (option, destination, help). Only those given reach the library, so
# its defaults (documented with their sources) stay in one place.
_PARAMETERS = (
    ("--tab-height", "tab_height", "height of the triangular tabs [mm] (default 8)"),
    ("--closing-tab-width", "closing_tab_width", "width of the closing tab [mm] (default 6)"),
    ("--tab-clearance", "tab_clearance", "closing tab clearance from creases [mm] (default 1)"),
    ("--polygon-spacing", "polygon_spacing", "gap tabs to base polygon [mm] (default 5)"),
    ("--kerf", "kerf", "tool kerf [mm] (default 0, drag knife)"),
    ("--gap-width", "gap_width", "laminate: valley gap width [mm] (default 1, thesis App. C)"),
    ("--bridge-width", "bridge_width", "laminate: base-polygon bridge length [mm] (default 1)"),
    ("--dash-length", "dash_length", "paper: perforation cut length [mm] (default 1)"),
    ("--tie-length", "tie_length", "paper: perforation tie length [mm] (default 1)"),
    ("--mountain-bridge", "mountain_bridge", "paper: uncut end of mountain cuts [mm] (default 1)"),
    ("--panel-inset", "panel_inset", "paper: reinforcement panel inset [mm] (default 1.5)"),
    ("--panel-spacing", "panel_spacing", "paper: gap strip to panels [mm] (default 5)"),
)


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "pattern",
        help="cut file / crease pattern of a cell (SVG, DXF, FOLD, PNG), or a pattern "
             "file converted to FOLD",
        description="Write the flat pattern of a generalized Kresling cell at true scale "
                    "(mm) for the thesis's paper or PET-laminate process. The format comes "
                    "from the output file's extension: .svg and .dxf (cut files, one layer "
                    "per cut pass), .fold (crease pattern with both stable states), .png "
                    "(preview). Laminate cut files are drawn from the inside of the cell, "
                    "as the plotter sees the sheet. With --from FILE (.fold, .svg in Origami "
                    "Simulator's colours, or .obj) no design is needed: the pattern is "
                    "converted to a FOLD file (-o FILE.fold) in mm, with FOLD's "
                    "assignments (an SVG's facet creases become joins, J), after the checks "
                    "'kresling simulate' makes: a pattern it would refuse is not converted "
                    "(exit 1, with its reason, as --check says it).",
    )
    add_design_arguments(parser)
    # With --from the design is not needed: the three design variables are checked in run.
    for action in parser._actions:
        if action.dest in ("n", "lam", "Lc"):
            action.required = False
    parser.add_argument("--from", dest="source", metavar="FILE",
                        help="convert this crease pattern (.fold, .svg, .obj) to the FOLD "
                             "file -o names, instead of drawing a cell")
    parser.add_argument("--unit", metavar="UNIT",
                        help="with --from: the unit of the file's coordinates (mm, cm, m, in, "
                             "pt, um, nm, or unit with --scale), replacing the file's own")
    parser.add_argument("--scale", type=float,
                        help="with --from and --unit unit: [mm] per unit")
    parser.add_argument("--check", metavar="FILE",
                        help="build this crease pattern's model as 'kresling simulate' would "
                             "fold it (the pattern, its creases driven to the file's fold "
                             "angles) and print what it repaired, or why it would refuse it "
                             "(exit 1); nothing is written")
    parser.add_argument("--split", default="N5B8", choices=("N5B8", "N4B5"),
                        help="with --check or --from: how panels become triangles, as "
                             "simulate would build them (default N5B8)")
    parser.add_argument("--snap-tolerance", type=float, dest="snap_tolerance", metavar="PX",
                        help="with --check or --from an SVG drawing: merge points closer than "
                             "PX [its units, CSS px] (default 3, or 1/200 of its size if "
                             "less)")
    parser.add_argument("--frame", type=int, default=0,
                        help="with --from a FOLD file: the index of the frame to convert "
                             "(default 0, the key frame)")
    parser.add_argument("--process", default="laminate", metavar="{laminate,paper}",
                        help="fabrication process (default laminate); any other name is "
                             "rejected with the list of processes")
    parser.add_argument("-o", "--output", metavar="FILE",
                        help="output file: .svg, .dxf, .fold or .png")
    parser.add_argument("--module", action="store_true",
                        help="cut a module: the cell and its mirror image on one sheet")
    parser.add_argument("--polygon-bridges", type=int, dest="polygon_bridges",
                        help="laminate: bridges on the base polygon in cut layer 1, a count "
                             "(default 2)")
    for option, destination, text in _PARAMETERS:
        parser.add_argument(option, type=float, dest=destination, help=text)
    parser.add_argument("--dpi", type=float, default=96.0,
                        help="PNG resolution [dots per inch] (default 96)")
    parser.add_argument("--json", action="store_true",
                        help="print the summary as JSON (width_mm, height_mm: the pattern's "
                             "extent; page_width_mm, page_height_mm: the SVG or PNG page with "
                             "its margins)")
    parser.set_defaults(func=run)


def convert(args) -> int:
    """``--from``: read any crease pattern, write it as FOLD (mm, FOLD's letters)."""
    from pathlib import Path

    from kresling.io import as_fold_assignments, read_pattern, write_fold

    if Path(args.output).suffix.lower() != ".fold":
        raise ValueError(f"--output = {args.output!r} is invalid with --from: a pattern file "
                         "is converted to FOLD (.fold)")
    check_output_file("--output", args.output)
    # What simulate would refuse is not converted: the same reading, the same message.
    from kresling.cli.pattern_check import examine, refuse

    _, _, refusal = examine(args.source, split=args.split, snap_tolerance=args.snap_tolerance,
                            unit=args.unit, scale=args.scale, frame=args.frame)
    if refusal is not None:
        return refuse(refusal)
    pattern = read_pattern(args.source, unit=args.unit, scale=args.scale, frame=args.frame,
                           snap_tolerance=args.snap_tolerance)
    if Path(args.source).suffix.lower() == ".svg":
        pattern = as_fold_assignments(pattern)
    write_fold(args.output, pattern, frame_title=Path(args.source).name,
               metadata={"file_title": f"crease pattern converted from {Path(args.source).name}"})
    summary = {"file": args.output, "format": "FOLD", "from": args.source,
               "vertices": pattern.num_vertices, "faces": pattern.num_faces,
               "edges": pattern.num_edges, "frames": len(pattern.frames)}
    if args.json:
        print_json(summary)
    else:
        print(f"wrote {args.output} (FOLD, mm: {pattern.num_vertices} vertices, "
              f"{pattern.num_faces} faces, {pattern.num_edges} edges from {args.source})")
    return 0


def run(args) -> int:
    if args.check is not None:
        if args.source is not None or args.output is not None:
            raise ValueError("--check reads a pattern and writes nothing: give it without "
                             "--from and --output")
        from kresling.cli.pattern_check import check

        return check(args)
    if args.output is None:
        raise ValueError("--output is missing: the file to write (.svg, .dxf, .fold or .png)")
    if args.source is not None:
        return convert(args)
    missing = [f"--{name}" for name in ("n", "lam", "Lc") if getattr(args, name) is None]
    if missing:
        raise ValueError(f"{', '.join(missing)} {'is' if len(missing) == 1 else 'are'} "
                         "missing: the cell's design is needed (or --from FILE to convert a "
                         "crease pattern file)")
    for option in ("unit", "scale"):
        if getattr(args, option) is not None:
            raise ValueError(f"--{option} applies only with --from")
    from kresling.fabrication import FORMATS, cut_sheet, module_sheet, write_pattern
    from kresling.fabrication.export import file_format, write_sheet
    from kresling.fabrication.svg import MARGIN

    design = design_from_args(args)
    names = ["polygon_bridges"] + [destination for _, destination, _ in _PARAMETERS]
    parameters = {name: getattr(args, name) for name in names if getattr(args, name) is not None}
    suffix = file_format(args.output)
    check_output_file("--output", args.output)   # before the pattern is made
    summary = {"file": args.output, "format": FORMATS[suffix], "process": args.process,
               "module": args.module, "design": repr(design)}
    if suffix == ".fold":
        write_pattern(args.output, design, args.process, module=args.module, **parameters)
    else:
        sheet = (module_sheet if args.module else cut_sheet)(design, args.process, **parameters)
        write_sheet(sheet, args.output, dpi=args.dpi)
        width, height = sheet.size
        # The pattern's extent, and the page an SVG or PNG puts it on (with margins; a DXF
        # file has no page).
        margin = 0.0 if suffix == ".dxf" else MARGIN
        summary.update(width_mm=width, height_mm=height, margin_mm=margin,
                       page_width_mm=width + 2 * margin, page_height_mm=height + 2 * margin,
                       layers={layer.name: len(layer.paths) for layer in sheet.layers})
    if args.json:
        print_json(summary)
    else:
        size = ""
        if "width_mm" in summary:
            size = f"; pattern {summary['width_mm']:.1f} x {summary['height_mm']:.1f} mm"
            size += (f", page {summary['page_width_mm']:.1f} x {summary['page_height_mm']:.1f} "
                     f"mm with {margin:g} mm margins" if margin else ", no margins")
        print(f"wrote {args.output} ({summary['format']}{size})")
    return 0
