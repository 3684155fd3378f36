"""plotly's JavaScript packed for a page: compressed, as text a page can hold, and unpacked
by the page itself.

plotly.min.js is about 4.8 MB; deflated (zlib) it is about 1.47 MB, and written in the 85
characters of :data:`ALPHABET` (5 characters per 4 bytes) about 1.84 MB, so a page with
its frames stays under 2 MB. The page inflates it with the browser's
``DecompressionStream`` (Chromium 80, Firefox 113, Safari 16.4 and later) and runs it.

Deflating takes about 0.25 s, longer than many solves, so the packed text is kept: in
memory for the process, and in a cache file (``$XDG_CACHE_HOME/kresling``, default
``~/.cache/kresling``) named after the file's size and time, so each installation of
plotly is packed once. Where no cache can be written, it is packed once per
process.
"""

from __future__ import annotations

import importlib.util
import os
import zlib
from functools import lru_cache
from pathlib import Path

import numpy as np

__all__ = ["ALPHABET", "encode85", "packed_plotly_js", "plotly_js_path", "DECODE_JS"]

#: The 85 characters of the text encoding: printable ASCII without the quotes, the
#: backslash, ``<``, ``>``, ``&``, the backtick, ``=`` and ``~`` (so nothing in it can end
#: a script element or need escaping in HTML or a JavaScript string).
ALPHABET = "".join(c for c in map(chr, range(33, 127)) if c not in "\"'\\<>&`=~")
assert len(ALPHABET) == 85

_POWERS = 85 ** np.arange(4, -1, -1, dtype=np.uint64)

#: JavaScript: ``kreslingDecode85(text)`` -> Uint8Array of the bytes, and
#: ``kreslingInflate(bytes)`` -> Promise of the inflated Uint8Array.
DECODE_JS = """
var KRESLING_ALPHABET = %s;
function kreslingDecode85(text) {
  var value = new Uint8Array(128);
  for (var i = 0; i < 85; i++) { value[KRESLING_ALPHABET.charCodeAt(i)] = i; }
  var pad = parseInt(text.charAt(0), 10), n = (text.length - 1) / 5;
  var out = new Uint8Array(4 * n), o = 0;
  for (var k = 1; k < text.length; k += 5) {
    var v = 0;
    for (var j = 0; j < 5; j++) { v = v * 85 + value[text.charCodeAt(k + j)]; }
    out[o++] = v >>> 24; out[o++] = (v >>> 16) & 255; out[o++] = (v >>> 8) & 255;
    out[o++] = v & 255;
  }
  return out.subarray(0, out.length - pad);
}
function kreslingInflate(bytes) {
  var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate'));
  return new Response(stream).arrayBuffer().then(function (b) { return new Uint8Array(b); });
}
""" % repr(ALPHABET).replace("'", '"')


def encode85(data: bytes) -> str:
    """``data`` as text of :data:`ALPHABET`: a digit (the padding bytes, 0-3), then 5
    characters per 4 bytes (big-endian base 85).

    Parameters
    ----------
    data : bytes

    Returns
    -------
    str
        ``1 + 5 * ceil(len(data) / 4)`` characters.
    """
    pad = -len(data) % 4
    words = np.frombuffer(bytes(data) + b"\0" * pad, dtype=">u4").astype(np.uint64)
    digits = (words[:, None] // _POWERS) % 85
    table = np.frombuffer(ALPHABET.encode("ascii"), dtype=np.uint8)
    return str(pad) + table[digits.astype(np.intp)].tobytes().decode("ascii")


def plotly_js_path() -> Path:
    """plotly.min.js of the installed plotly package (found without importing plotly).

    Raises
    ------
    ImportError
        When plotly is not installed.
    """
    spec = importlib.util.find_spec("plotly")
    if spec is None or not spec.submodule_search_locations:
        raise ImportError("plotly is not installed (pip install plotly)")
    path = Path(list(spec.submodule_search_locations)[0]) / "package_data" / "plotly.min.js"
    if not path.is_file():
        raise ImportError(f"plotly's JavaScript is missing: {path} is not a file")
    return path


def _cache_folder() -> Path:
    root = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(root) / "kresling"


@lru_cache(maxsize=2)
def packed_plotly_js(path=None) -> str:
    """plotly.min.js deflated and encoded with :func:`encode85` (see the module's notes on
    the cache).

    Parameters
    ----------
    path : str or os.PathLike, optional
        Default: :func:`plotly_js_path`.

    Returns
    -------
    str
    """
    path = Path(path) if path is not None else plotly_js_path()
    stat = path.stat()
    cached = _cache_folder() / f"plotly-{stat.st_size}-{stat.st_mtime_ns}.deflate85"
    try:   # (bytes decoded at once: several times faster than a text file's reading)
        return cached.read_bytes().decode("ascii")
    except (OSError, UnicodeDecodeError):
        pass
    text = encode85(zlib.compress(path.read_bytes(), 9))
    import tempfile   # (once per installation of plotly: not at every page's start)

    try:
        cached.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", dir=cached.parent, delete=False,
                                         encoding="ascii", suffix=".part") as handle:
            handle.write(text)
        os.replace(handle.name, cached)   # never a half-written cache under its name
    except OSError:
        pass  # no cache where none can be written: packed again by the next process
    return text
