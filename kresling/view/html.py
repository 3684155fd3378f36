"""A view as one self-contained, offline HTML page.

The page holds plotly's JavaScript once, inline, and needs no network. Its address can
name the increment to open at: ``view.html#frame=K`` shows increment K (the nearest one
that has a frame), and changing the hash later moves the view there too.
"""

from __future__ import annotations

import html as _html
import json
import os
from pathlib import Path

import plotly.graph_objects as go

from kresling._validation import as_integer

__all__ = ["write_html", "check_writable", "DIV_ID"]

#: The id of the figure's element in the page.
DIV_ID = "kresling-view"
#: The plot's height on the page (CSS): the window's, at least 560 px.
PAGE_HEIGHT = "max(100vh, 560px)"

# Run once the figure is drawn ({plot_id} is the figure's element). NAMES: the frames'
# names (increments), in slider order; START: the increment to show when the address has
# no "#frame=K".
_HASH_SCRIPT = """
(function () {
  var gd = document.getElementById('{plot_id}');
  var names = __NAMES__;
  var start = __START__;
  if (!gd || !names.length) { return; }
  function nearest(k) {
    var best = 0;
    for (var i = 1; i < names.length; i++) {
      if (Math.abs(parseInt(names[i], 10) - k) < Math.abs(parseInt(names[best], 10) - k)) {
        best = i;
      }
    }
    return best;
  }
  function show(k) {
    var i = nearest(k);
    return Plotly.animate(gd, [names[i]], {mode: 'immediate', transition: {duration: 0},
                                           frame: {duration: 0, redraw: true}})
      .then(function () { return Plotly.relayout(gd, {'sliders[0].active': i}); });
  }
  function fromHash() {
    var m = /(?:^#|&)frame=(\\d+)/.exec(window.location.hash);
    return m ? parseInt(m[1], 10) : null;
  }
  window.kreslingShowIncrement = show;
  window.addEventListener('hashchange', function () {
    var k = fromHash();
    if (k !== null) { show(k); }
  });
  var k = fromHash();
  if (k === null) { k = start; }
  if (k !== null) { show(k); }
})();
"""


def write_html(figure, path, *, initial_frame=None) -> Path:
    """Write a view as one self-contained HTML page that works offline.

    plotly's JavaScript is inlined once (about 4.8 MB); nothing is loaded from the
    network. The page reads its address's ``#frame=K`` and opens at increment K (the
    nearest increment that has a frame), and follows later changes of it.

    Parameters
    ----------
    figure : plotly.graph_objects.Figure
        From :func:`kresling.view.view_path` or :func:`kresling.view.view_model` (any
        figure works; ``#frame=`` applies to figures with frames).
    path : str or os.PathLike
        The file to write (parent folders are created).
    initial_frame : int, optional
        Increment K to open at when the address names none (default: the first frame).

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    path = Path(path)
    fig = go.Figure(figure)
    names = [frame.name for frame in fig.frames]
    start = None
    if initial_frame is not None and names:
        k = as_integer("initial_frame", initial_frame, minimum=0)
        index = min(range(len(names)), key=lambda i: abs(int(names[i]) - k))
        start = int(names[index])
        _show_frame(fig, index)
    script = _HASH_SCRIPT.replace("__NAMES__", json.dumps(names)) \
        .replace("__START__", json.dumps(start))
    # The page's plot fills the window (a fixed height cropped the 3D scenes' bottom on
    # short windows and left them small on tall ones); the figure's own height stays for
    # notebooks.
    fig.layout.height = None
    fig.layout.autosize = True
    page = fig.to_html(include_plotlyjs=True, full_html=True, div_id=DIV_ID,
                       post_script=script, auto_play=False, default_height=PAGE_HEIGHT,
                       config={"responsive": True, "displaylogo": False})
    page = page.replace("<body>", "<body style=\"margin: 0\">", 1)
    title = fig.layout.title.text or "kresling view"
    page = page.replace("<head>", f"<head>\n    <title>{_html.escape(_plain(title))}</title>",
                        1)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(page, encoding="utf-8")
    return path


def check_writable(path) -> Path:
    """Check, before any computation, that a page can be written at ``path``.

    The file may exist (it is replaced) or not; missing parent folders are fine if they can
    be made. Nothing is left behind: a probe file made to test the folder is removed.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    ValueError
        Naming the path and why it cannot be written (a folder, a parent that is a file, a
        folder without write permission).

    Examples
    --------
    >>> check_writable("/")
    Traceback (most recent call last):
    ...
    ValueError: cannot write '/': it is a folder
    """
    path = Path(path)
    if path.is_dir():
        raise ValueError(f"cannot write {str(path)!r}: it is a folder")
    ancestor = path.parent
    while not ancestor.exists() and ancestor != ancestor.parent:
        ancestor = ancestor.parent
    if not ancestor.is_dir():
        raise ValueError(f"cannot write {str(path)!r}: {str(ancestor)!r} is not a folder")
    if ancestor != path.parent:
        if not os.access(ancestor, os.W_OK | os.X_OK):
            raise ValueError(f"cannot write {str(path)!r}: no permission to make folders in "
                             f"{str(ancestor)!r}")
        return path
    existed = path.exists()
    try:
        with open(path, "a", encoding="utf-8"):
            pass
    except OSError as error:
        raise ValueError(f"cannot write {str(path)!r}: {error.strerror or error}") from None
    if not existed:
        path.unlink()
    return path


def _plain(text: str) -> str:
    """A figure title without plotly's HTML-like tags."""
    import re

    return re.sub(r"<[^>]+>", " ", text).strip()


def _show_frame(fig, index):
    """Make frame ``index`` the figure's initial state (its data and the slider)."""
    frame = fig.frames[index]
    traces = frame.traces if frame.traces is not None else range(len(frame.data))
    for trace_index, update in zip(traces, frame.data):
        fig.data[trace_index].update(update.to_plotly_json())
    if fig.layout.sliders:
        fig.layout.sliders[0].active = index
