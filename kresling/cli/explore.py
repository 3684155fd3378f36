"""``kresling explore``: the design explorer page (sliders over n, lambda and Lc; the cell
in both states, its flat pattern, the K_B-ratio and snap-force maps)."""

from __future__ import annotations

from pathlib import Path

from kresling.cli._specimen import add_specimen_arguments, specimen_parameters_from_args


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "explore",
        help="design explorer page: sliders over n, lambda, Lc; cell, flat pattern, maps",
        description="Run a coarse sweep of the thesis's design space (n = 4, 6, 8, 10; "
                    "lambda 0.7-0.9; Lc 15-60 mm) for the K_B ratio (0.001 rad protocol) and "
                    "the snap-through force (about 10 s on two cores at the default "
                    "resolution), and write one self-contained, offline page: sliders for "
                    "n, lambda and Lc, the cell in both stable states, its flat crease "
                    "pattern, and a marker on both maps. EXPLORER.html#n=8&lam=0.8&Lc=30 "
                    "opens at that design (the nearest grid point). Nothing is cached.",
    )
    parser.add_argument("-o", "--out", metavar="FILE.html", default="explorer.html",
                        help="the page to write (default explorer.html)")
    parser.add_argument("--size", type=int, nargs=2, metavar=("N_LC", "N_LAM"),
                        default=None,
                        help="grid points along Lc and lambda (default 19 21: every 2.5 mm "
                             "and every 0.01)")
    parser.add_argument("--n", type=int, nargs="+", default=None, metavar="N",
                        help="polygon sizes, counts of sides (even; default 4 6 8 10)")
    parser.add_argument("--workers", type=int, default=None,
                        help="parallel workers of the sweep, a count (default: every core)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    add_specimen_arguments(parser)
    parser.set_defaults(func=run)


def _flat_pattern(design):
    from kresling.fabrication import crease_pattern

    pattern = crease_pattern(design)
    return pattern.points, pattern.edges, pattern.edge_kinds


def run(args) -> int:
    from kresling.sweeps import THESIS_N
    from kresling.view import check_writable
    from kresling.view.explorer import DEFAULT_SIZE, explorer_data, write_explorer

    parameters = specimen_parameters_from_args(args)
    out = check_writable(Path(args.out))
    data = explorer_data(args.n or THESIS_N, tuple(args.size or DEFAULT_SIZE),
                         workers=args.workers, flat_pattern=_flat_pattern,
                         progress=not args.quiet, parameters=parameters)
    write_explorer(data, out)
    sweep = data["sweep"]
    print(f"explorer: {out} ({sweep['designs']} designs swept in {sweep['seconds']:g} s)")
    return 0
