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
_COMMANDS = ("design", "bend", "snap", "simulate", "view", "sweep", "optimize", "explore",
             "pattern", "fit", "manipulator", "arm", "switch", "reproduce")


def build_parser(only=None) -> argparse.ArgumentParser:
    """The top-level parser with every subcommand registered (``only``: that one alone).

    A command's module imports what its options need (the sweep's metrics, the arm's and
    the manipulator's defaults, and through them the sweeps, the arm and the manipulator
    packages); running one command registers that command alone, so that it imports only
    what it uses.
    """
    from kresling import __version__

    parser = argparse.ArgumentParser(
        prog="kresling",
        description="Design, simulate, fabricate and drive generalized Kresling origami.",
    )
    parser.add_argument("--version", action="version", version=f"kresling {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    subparsers.required = True
    for name in _COMMANDS if only is None else (only,):
        importlib.import_module(f"kresling.cli.{name}").register(subparsers)
    return parser


def _command(argv):
    """The subcommand ``argv`` names (the first argument that is not an option: the
    top-level options take no value), or None (then every command is registered, for
    ``--help``, ``--version`` and the message naming the commands there are)."""
    first = next((a for a in argv if not a.startswith("-")), None)
    return first if first in _COMMANDS else None


def main(argv=None) -> int:
    """Entry point of the ``kresling`` script; returns the exit status."""
    parser = build_parser(_command(sys.argv[1:] if argv is None else argv))
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
