"""Where a report came from: the code's git commit and the versions it ran with.

Written into ``report.json`` (key ``provenance``) and shown in the page's header, so that a
number in a report can be traced back to the code and libraries that produced it.
"""

from __future__ import annotations

import platform
import subprocess
from pathlib import Path

import numpy
import scipy

from kresling import __version__

__all__ = ["provenance", "git_commit"]

#: The directory holding the ``kresling`` package: the repository's root in a checkout.
SOURCE_ROOT = Path(__file__).resolve().parents[2]


def git_commit(root=None):
    """The commit of the git checkout the package runs from, and whether it has changes.

    Parameters
    ----------
    root : str or Path, optional
        The directory holding the ``kresling`` package (default: this one's).

    Returns
    -------
    commit : str or None
        40 hex digits; ``None`` when ``root`` is not the top of a git checkout (an installed
        package, even inside some other repository), or git is not installed.
    dirty : bool or None
        Whether tracked files differ from that commit; ``None`` when there is no commit.
    """
    root = Path(root) if root is not None else SOURCE_ROOT
    top = _git(root, "rev-parse", "--show-toplevel")
    if top is None or Path(top).resolve() != root.resolve():
        return None, None
    commit = _git(root, "rev-parse", "--verify", "HEAD")
    if commit is None:
        return None, None
    status = _git(root, "status", "--porcelain", "--untracked-files=no")
    return commit, None if status is None else bool(status)


def provenance(root=None) -> dict:
    """What produced a report, as a JSON-ready dict.

    Returns
    -------
    dict
        ``git_commit`` (str or None, see :func:`git_commit`), ``git_dirty`` (bool or None),
        ``kresling``, ``numpy``, ``scipy`` (versions), ``python`` (e.g. ``"3.11.2"``),
        ``platform`` (e.g. ``"Linux-6.1.0-x86_64-with-glibc2.36"``).
    """
    commit, dirty = git_commit(root)
    return {"git_commit": commit, "git_dirty": dirty, "kresling": __version__,
            "numpy": numpy.__version__, "scipy": scipy.__version__,
            "python": platform.python_version(), "platform": platform.platform()}


def _git(root: Path, *arguments):
    """``git -C root ARGUMENTS``' output, stripped; ``None`` if it fails or git is missing."""
    try:
        result = subprocess.run(["git", "-C", str(root), *arguments], capture_output=True,
                                text=True, timeout=10, stdin=subprocess.DEVNULL)
    except (OSError, subprocess.SubprocessError):
        return None
    return result.stdout.strip() if result.returncode == 0 else None
