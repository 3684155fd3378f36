"""Reading a problem file's TOML: every way a file can be unreadable is a ValueError naming
the file (and the line and column where there is one), never an OSError, a
UnicodeDecodeError or a RecursionError."""

from __future__ import annotations

from pathlib import Path

from kresling._validation import read_input_file

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover - older Pythons use the same parser, tomli
    import tomli as tomllib

__all__ = ["read_toml", "MAX_NESTING"]

#: Deepest nesting of arrays and inline tables a problem file may have: a real one nests 3
#: levels (``vertices = [[x, y, z], ...]``); the TOML parser recurses once per level and
#: would exhaust Python's stack somewhere past 300.
MAX_NESTING = 50


def _decoded(data: bytes, source: str) -> str:
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        column = error.start - (data.rfind(b"\n", 0, error.start) + 1) + 1
        raise ValueError(f"{source}:{line}:{column}: not valid TOML: byte "
                         f"0x{data[error.start]:02x} is not UTF-8 text") from None


def _nesting(text: str) -> tuple:
    """(deepest nesting of ``[`` and ``{`` outside strings and comments, its line): a
    scan the parser's recursion cannot overflow. Table headers count one level, as they do
    not nest; strings are skipped by their quotes (a rough tokeniser: a deep nest is found
    wherever it is, a string holding brackets is not mistaken for one)."""
    depth = deepest = 0
    line = where = 1
    quote = None
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            if quote in ('"', "'"):
                quote = None  # a basic string ends at its line (the parser reports it)
        elif quote:
            if text.startswith(quote, i):
                i += len(quote)
                quote = None
                continue
            if c == "\\" and quote[0] == '"':
                i += 1  # an escaped character, whatever it is
        elif c in "\"'":
            quote = c * 3 if text.startswith(c * 3, i) else c
            i += len(quote)
            continue
        elif c == "#":
            end = text.find("\n", i)
            i = n if end < 0 else end
            continue
        elif c in "[{":
            depth += 1
            if depth > deepest:
                deepest, where = depth, line
        elif c in "]}":
            depth = max(depth - 1, 0)
        i += 1
    return deepest, where


def read_toml(path) -> tuple:
    """The tables of a TOML problem file and its text.

    Parameters
    ----------
    path : pathlib.Path

    Returns
    -------
    data : dict
    text : str

    Raises
    ------
    ValueError
        Naming the file: it is missing, unreadable, not a regular file, too large, not
        UTF-8, nested more than :data:`MAX_NESTING` levels deep, or not valid TOML.
    """
    source = str(path)
    try:
        raw = read_input_file(Path(path))
    except FileNotFoundError:
        raise ValueError(f"{source}: no such problem file") from None
    except OSError as error:
        raise ValueError(f"{source}: cannot be read ({error.strerror or error})") from None
    text = _decoded(raw, source)
    deepest, line = _nesting(text)
    if deepest > MAX_NESTING:
        raise ValueError(f"{source}:{line}: not valid TOML here: arrays or inline tables "
                         f"nested {deepest} levels deep (at most {MAX_NESTING})")
    try:
        return tomllib.loads(text), text
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{source}: not valid TOML: {error}") from None
    except RecursionError:  # a nest the scan missed: still the file's fault
        raise ValueError(f"{source}: not valid TOML here: nested too deeply") from None
