"""Data shipped with kresling: the thesis's tables and the MERLIN2 reference runs.

See ``README.md`` in this folder for what each file is and where it comes from.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["path"]

_HERE = Path(__file__).resolve().parent


def path(name: str) -> Path:
    """Absolute path of a shipped data file, e.g. ``path("merlin2/table3_reference.csv")``.

    Raises
    ------
    FileNotFoundError
        If no such file ships with the package.
    """
    result = _HERE / name
    if not result.is_file():
        available = sorted(str(p.relative_to(_HERE)) for p in _HERE.rglob("*.csv"))
        raise FileNotFoundError(f"no data file {name!r} in kresling; available: {available}")
    return result
