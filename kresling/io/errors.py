"""Error messages that point at the offending element of a pattern file.

Every reader of :mod:`kresling.io` raises :class:`PatternFileError` (a :class:`ValueError`)
for bad content. Its message starts with where the problem is, in the style of a compiler:

- ``FILE:LINE:COLUMN: message`` for line-based formats (OBJ) and JSON syntax errors; lines
  and columns count from 1, the column is that of the offending token;
- ``FILE: key 'faces_vertices'[3]: message`` for a key of a FOLD document and the index of
  the entry in it;
- ``FILE: message`` for the file as a whole (a missing key, a panel's geometry).
"""

from __future__ import annotations

__all__ = ["MISSING", "PatternFileError", "describe", "file_error", "key_error", "line_error"]

#: Default of ``value`` arguments: no value to show.
MISSING = object()


class PatternFileError(ValueError):
    """Bad content in a pattern file (or bad arrays given in memory).

    A :class:`ValueError`: catch that. The attributes say where the problem is, for a program
    that wants to show it (an editor jumping to the line); each is ``None`` when not known.

    Attributes
    ----------
    source : str
        The file name as given to the reader (``""`` for arrays given in memory).
    line, column : int or None
        1-based position of the offending token (line-based formats, JSON syntax).
    key : str or None
        The FOLD key (``"faces_vertices"``) or argument name (``"faces"``).
    index : int or None
        0-based index of the entry in ``key``.
    """

    def __init__(self, message: str, *, source: str = "", line: int | None = None,
                 column: int | None = None, key: str | None = None,
                 index: int | None = None) -> None:
        super().__init__(message)
        self.source = source
        self.line = line
        self.column = column
        self.key = key
        self.index = index


def describe(value, limit: int = 60) -> str:
    """``repr`` of a value read from a file, shortened to about ``limit`` characters."""
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 4] + " ..."


def file_error(source: str, message: str) -> PatternFileError:
    """``FILE: message`` (just ``message`` when ``source`` is empty)."""
    return PatternFileError(f"{source}: {message}" if source else message, source=source)


def line_error(source: str, line: int, column: int, message: str) -> PatternFileError:
    """``FILE:LINE:COLUMN: message``; ``line`` and ``column`` count from 1."""
    return PatternFileError(f"{source}:{line}:{column}: {message}", source=source, line=line,
                            column=column)


def key_error(source: str, key: str, message: str, index: int | None = None, *,
              value=MISSING, sub: str = "") -> PatternFileError:
    """An error in an entry of a FOLD key (or, with ``source=""``, of an argument).

    ``FILE: key 'KEY'[INDEX]SUB: message``, or with ``value`` given
    ``FILE: key 'KEY'[INDEX]SUB = VALUE is invalid: message``; without an index or ``sub``
    the message is a predicate: ``FILE: key 'KEY' is missing: ...``. ``sub`` names a part
    of the entry (``"['vertices_coords'][4]"`` inside a frame). With ``source=""`` (arrays
    given in memory) ``KEY`` is an argument name and the ``FILE: key`` prefix is left out.
    """
    name = f"'{key}'" if source else key
    where = name + (f"[{index}]" if index is not None else "") + sub
    if source:
        where = f"key {where}"
    if value is not MISSING:
        text = f"{where} = {describe(value)} is invalid: {message}"
    elif index is None and not sub:
        text = f"{where} {message}"         # a predicate: "key 'x' is missing: ..."
    else:
        text = f"{where}: {message}"
    return PatternFileError(f"{source}: {text}" if source else text, source=source, key=key,
                            index=index)
