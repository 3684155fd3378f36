"""``kresling view``: an interactive page of any crease pattern file (FOLD, OBJ), its frames
animated."""

from __future__ import annotations

import sys
from pathlib import Path


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "view",
        help="interactive 3D page of a FOLD (or OBJ) file, its frames animated",
        description="Write one self-contained, offline HTML page showing a crease pattern "
                    "file's panels and creases (coloured by FOLD assignment: mountain red, "
                    "valley blue, boundary dark grey, cut black, flat and unassigned grey, "
                    "join cyan). A FOLD file's frames are animated (slider, play/pause): the "
                    "key frame is frame 0, file_frames[K-1] frame K, and PAGE.html#frame=K "
                    "opens at frame K; a file without frames shows its one state. A "
                    "'kresling simulate' run's path.fold has one frame per increment.",
    )
    parser.add_argument("pattern", metavar="PATH.fold", help="a .fold or .obj file")
    parser.add_argument("-o", "--out", metavar="FILE.html",
                        help="the page to write (default: beside the file, with .html)")
    parser.add_argument("--frame", type=int, metavar="K",
                        help="open at frame K (an index) when the address names none (out of "
                             "range: the nearest frame, said on stderr)")
    parser.add_argument("--max-frames", type=int, default=200, metavar="M",
                        help="at most M frames in the page, a count, evenly spaced (default "
                             "200)")
    parser.set_defaults(func=run)


def run(args) -> int:
    from kresling.io import read_pattern
    from kresling.view import check_writable, view_fold, write_html

    out = Path(args.out) if args.out else Path(args.pattern).with_suffix(".html")
    check_writable(out)
    pattern = read_pattern(args.pattern, planarity_tolerance=None)
    last = len(pattern.frames)
    frame = args.frame
    if frame is not None and not 0 <= frame <= last:
        nearest = min(max(frame, 0), last)
        what = f"frames 0 to {last}" if last else "only frame 0 (no frames: one state)"
        print(f"kresling view: --frame {frame} is out of range ({Path(args.pattern).name} has "
              f"{what}): opening frame {nearest}", file=sys.stderr)
        frame = nearest
    figure = view_fold(pattern, max_frames=args.max_frames)
    write_html(figure, out, initial_frame=frame if figure.frames else None)
    print(f"view: {out}")
    return 0
