"""The ``kresling`` command line.

Each subcommand lives in its own module of this package and exposes
``register(subparsers)``, which adds its parser and sets ``func(args) -> int``.
Bad input (a ``ValueError`` from the library) prints one line on stderr and exits 2; a
missing optional dependency (``ImportError``, naming the extra) exits 3. Neither shows a
traceback.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys

# Subcommand modules, in the order ``kresling --help`` lists them.
_COMMANDS = ("design", "bend", "snap", "simulate", "view", "sweep", "explore", "pattern", "fit",
             "manipulator", "arm", "reproduce")


def build_parser() -> argparse.ArgumentParser:
    """The top-level parser with every subcommand registered."""
    from kresling import __version__

    parser = argparse.ArgumentParser(
        prog="kresling",
        description="Design, simulate, fabricate and drive generalized Kresling origami.",
    )
    parser.add_argument("--version", action="version", version=f"kresling {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    subparsers.required = True
    for name in _COMMANDS:
        importlib.import_module(f"kresling.cli.{name}").register(subparsers)
    return parser


def main(argv=None) -> int:
    """Entry point of the ``kresling`` script; returns the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except BrokenPipeError:
        # The reader went away (e.g. `kresling design | head`): not an error of ours.
        sys.stdout = open(os.devnull, "w")
        return 0
    except (ValueError, OSError) as error:
        # Bad input, or a file that cannot be read or written (missing, a directory, ...).
        print(f"kresling {args.command}: error: {error}", file=sys.stderr)
        return 2
    except ImportError as error:
        # A missing optional extra: the message names what to install.
        print(f"kresling {args.command}: error: {error}", file=sys.stderr)
        return 3
    except KeyboardInterrupt:
        print(f"kresling {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
