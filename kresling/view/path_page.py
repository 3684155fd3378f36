"""A path's animated page written straight from its arrays: the figure of the first frame
as plain JSON, every frame's node positions as one compressed binary block, and a small
script that updates the panels, the crease lines and the curve's marker from them.

:func:`kresling.view.view_path` builds a plotly figure with one frame object per increment,
which a notebook needs; for a page that is most of the cost (the figure objects are
validated value by value) and most of the size (every frame repeats every coordinate as
decimal text). Here nothing of plotly's Python is imported: the page holds plotly's
JavaScript once, deflated (:mod:`kresling.view.plotly_js`), the positions as 16-bit
integers on the scene's box (1/65535 of the box's side along each axis: 1 micrometre on a
65 mm sheet, far below a pixel), differenced twice along the path (a smooth path then
leaves small numbers that deflate well) and deflated. The page looks and behaves as
:func:`kresling.view.write_html` of :func:`kresling.view.view_path`: the same scene and
curve, a slider "increment K / S", play/pause, ``#frame=K``.
"""

from __future__ import annotations

import json
import re
import zlib
from pathlib import Path

import numpy as np

from kresling._validation import as_integer, as_positive_real
from kresling.view.animation import (FRAME_DURATION_MS, check_curve, default_curve,
                                     partial_line, play_buttons, select_rows, slider)
from kresling.view.fields import significant_decimals
from kresling.view.inputs import view_inputs
from kresling.view.page_script import PAGE_SCRIPT
from kresling.view.plotly_js import DECODE_JS, encode85, packed_plotly_js, plotly_js_path
from kresling.view.scene_box import box, check_path, describe, node_points, scene_layout
from kresling.view.surface import (MESH_LIGHTING, PANEL_COLOUR, crease_groups, family_style,
                                   polyline_order, rounded)
from kresling.view.symbols import subscripted

__all__ = ["write_path_page", "encode_frames"]

_LEVELS = 65535          # the positions' 16-bit grid on each side of the box
_MARKER_COLOUR = "#d62728"
_SCENES_END = 0.56       # the scene's share of the width (the curve's axes start 0.14 on)


def encode_frames(points, low, high) -> bytes:
    """Node positions of every frame as the page reads them.

    Parameters
    ----------
    points : ndarray, shape (F, N, 3)
        Positions [mm].
    low, high : ndarray, shape (3,)
        The box holding every position [mm].

    Returns
    -------
    bytes
        zlib-deflated: the low bytes, then the high bytes, of the 16-bit grid values
        ``round((p - low) / (high - low) * 65535)``, frame-major, each differenced twice
        along the frames modulo 2**16 (the page sums them back).
    """
    span = np.maximum(np.asarray(high, dtype=float) - low, 1e-300)
    grid = np.rint((np.asarray(points, dtype=float) - low) / span * _LEVELS)
    values = np.clip(grid, 0, _LEVELS).astype(np.int64).reshape(len(points), -1)
    for _ in range(2):  # differences along the path (the first frame stays as it is)
        values = np.diff(values, axis=0, prepend=np.zeros((1, values.shape[1]), np.int64))
    words = (values % 65536).astype("<u2").ravel()
    planes = words.view(np.uint8).reshape(-1, 2).T   # low bytes, then high bytes
    return zlib.compress(np.ascontiguousarray(planes).tobytes(), 6)


def _scene(inputs):
    """The crease lines by family: (family, style, polyline order) each."""
    groups = {**crease_groups(inputs.model.hinges, inputs.hinge_family, inputs.triangles),
              **inputs.lines}
    others = []
    return [(family, family_style(family, others), polyline_order(edges))
            for family, edges in groups.items()]


def _traces(inputs, lines, low, high, curve):
    """The figure's traces: panels, crease lines, the box, the curve and its marker (the
    coordinates of the 3D traces are filled in by the page)."""
    tri = inputs.triangles
    data = []
    if len(tri):
        data.append(dict(type="mesh3d", i=tri[:, 0].tolist(), j=tri[:, 1].tolist(),
                         k=tri[:, 2].tolist(), color=PANEL_COLOUR, flatshading=True,
                         opacity=1.0, lighting=MESH_LIGHTING,
                         lightposition=dict(x=25000, y=50000, z=100000), name="panels",
                         showlegend=True, hoverinfo="skip", legendgroup="panels",
                         scene="scene"))
    for family, (colour, width, dash), _ in lines:
        data.append(dict(type="scatter3d", mode="lines", name=family,
                         line=dict(color=colour, width=width, dash=dash), hoverinfo="name",
                         connectgaps=False, legendgroup=family, scene="scene"))
    data.append(dict(type="scatter3d", x=rounded([low[0], high[0]], 4),
                     y=rounded([low[1], high[1]], 4), z=rounded([low[2], high[2]], 4),
                     mode="markers", marker=dict(size=1, opacity=0), hoverinfo="skip",
                     showlegend=False, name="extent", scene="scene"))
    if curve is not None:
        x, y, x_label, y_label = curve
        data.append(dict(type="scatter", x=x, y=y, mode="lines", name="path",
                         line=dict(color="#444444", width=2), showlegend=False,
                         xaxis="x", yaxis="y",
                         hovertemplate=f"{x_label}: %{{x}}<br>{y_label}: %{{y}}<extra></extra>"))
        data.append(dict(type="scatter", x=x[:1], y=y[:1], mode="markers",
                         name="increment shown", showlegend=False, cliponaxis=False,
                         xaxis="x", yaxis="y",
                         marker=dict(color=_MARKER_COLOUR, size=12,
                                     line=dict(color="white", width=1.5)),
                         hovertemplate="shown: %{x}, %{y}<extra></extra>"))
    return data


def _template():
    path = plotly_js_path().parent / "templates" / "plotly_white.json"
    return json.loads(path.read_text(encoding="utf-8"))


def _layout(title, points, names, total, curve):
    # Two title lines above the legend; each further line pushes the plots down.
    top = 100 + 30 * max(0, title.count("<br>") - 1)
    scene = scene_layout(points)
    scene["domain"] = dict(x=[0.0, _SCENES_END if curve is not None else 1.0], y=[0.0, 1.0])
    layout = dict(title=dict(text=title, x=0.5, xanchor="center"), template=_template(),
                  autosize=True, margin=dict(l=10, r=20, t=top, b=100), uirevision="view",
                  legend=dict(orientation="h", x=0.0, y=1.0, yanchor="bottom"),
                  sliders=[slider(names, total, method="skip")],
                  updatemenus=[play_buttons(method="skip")], scene=scene)
    if curve is not None:
        layout["xaxis"] = dict(domain=[round(_SCENES_END + 0.14, 4), 1.0], anchor="y",
                               title=dict(text=curve[2]))
        layout["yaxis"] = dict(domain=[0.0, 1.0], anchor="x", title=dict(text=curve[3]))
    return layout


def _curve(model, path, curve, num_steps):
    if curve is False:
        return None
    x, y, x_label, y_label = check_curve(curve if curve is not None
                                         else default_curve(model, path), num_steps)
    return (rounded(x, significant_decimals(x, 10)), rounded(y, significant_decimals(y, 10)),
            subscripted(x_label), subscripted(y_label))


def write_path_page(model, path, file, *, triangles=None, hinge_family=None, curve=None,
                    frame_stride=None, max_frames=200, title=None, increments=None,
                    total=None, times=None, time_scale=None,
                    contact_pairs=None) -> Path:
    """Write a path's animated view as one offline page, straight from its arrays.

    The page shows what ``write_html(view_path(model, path, ...), file)`` shows (without
    a field's colours): the folded surface at one increment beside the curve, whose marker
    follows the slider. Its node positions are held to 1/65535 of the scene's box along
    each axis; the curve keeps every value to 10 significant digits of its largest one.

    Parameters
    ----------
    model : kresling.model.Model or an object with ``.model`` and ``.hinge_family``
        As in :func:`kresling.view.view_model`.
    path : kresling.solvers.PathResult or an object with ``displacement`` (S, 3N)
        ``displacement`` [mm] (and ``load_factor`` for the default curve); ``completed``
        False and ``message`` add a red "PARTIAL" line under the title.
    file : str or os.PathLike
        The page to write (parent folders are created).
    triangles, hinge_family, curve, frame_stride, max_frames, title
        As in :func:`kresling.view.view_path`.
    increments : array_like of int, shape (S,), optional
        The increment number of each row of the path (a path thinned to every k-th
        increment), ascending: the frames' names and ``#frame=K``. Default: 1 to S.
    total : int, optional
        The run's increments, shown as "increment K / total". Default: the last increment.
    times : array_like, shape (S,), optional
        The time of each row [s], ascending (a motion in time): play then shows the frames
        at these times, scaled by ``time_scale``, instead of one every 60 ms.
    time_scale : float, optional
        Wall seconds per second of the motion (with ``times``; e.g. 25: a 0.2 s motion
        plays in 5 s).
    contact_pairs : sequence of array_like, optional
        One entry per row of the path: its contact pairs as segments between their closest
        points, shape (K, 6) [mm] (K may differ from row to row); drawn as the lines
        "contact pairs". Default: none.

    Returns
    -------
    pathlib.Path
        ``file``.

    Raises
    ------
    ValueError
        As :func:`kresling.view.view_path`.
    ImportError
        When plotly (whose JavaScript the page holds) is not installed.
    """
    inputs = view_inputs(model, triangles=triangles, hinge_family=hinge_family)
    model = inputs.model
    displacement = check_path(model, path)
    num_steps = len(displacement)
    shown_curve = _curve(model, path, curve, num_steps)
    rows = select_rows(num_steps, frame_stride, max_frames)
    numbers = _increments(increments, num_steps)
    names = [str(numbers[r]) for r in rows]
    total = int(numbers[-1]) if total is None else as_integer("total", total, minimum=1)
    points = np.stack([node_points(model, displacement[r]) for r in rows])
    lines = _scene(inputs)
    if contact_pairs is not None:
        points, order = _with_segments(points, [contact_pairs[r] for r in rows])
        if order is not None:
            lines.append(("contact pairs", (_MARKER_COLOUR, 6, "solid"), order))
    low, high = box(list(points))
    shown = subscripted(title or f"Equilibrium path of a bar-and-hinge model "
                                 f"({describe(model)}), {total} increments")
    if getattr(path, "completed", True) is False:
        shown += partial_line(total, getattr(path, "message", ""))
    spec = dict(data=_traces(inputs, lines, low, high, shown_curve),
                layout=_layout(shown, list(points), names, total, shown_curve),
                config=dict(responsive=True, displaylogo=False),
                frames=dict(names=names, rows=[int(r) for r in rows], nodes=points.shape[1],
                            low=low.tolist(), span=(high - low).tolist(),
                            mesh=bool(len(inputs.triangles)),
                            orders=[order.tolist() for _, _, order in lines],
                            curve=shown_curve is not None, duration=FRAME_DURATION_MS,
                            **_timing(times, time_scale, rows, num_steps)))
    return _write(Path(file), shown, spec, encode85(encode_frames(points, low, high)))


def _timing(times, time_scale, rows, num_steps) -> dict:
    """The frames' times [s] and the playback's scale, for the page (none: {})."""
    if times is None:
        if time_scale is not None:
            raise ValueError("time_scale applies only with times")
        return {}
    values = np.asarray(times, dtype=float)
    if values.shape != (num_steps,) or not np.isfinite(values).all() or \
            (num_steps > 1 and np.any(np.diff(values) < 0)):
        raise ValueError(f"times has shape {values.shape}: must be {num_steps} finite, "
                         "ascending times [s], one per row of the path")
    scale = as_positive_real("time_scale", 1.0 if time_scale is None else time_scale)
    return {"times": [float(values[r]) for r in rows], "scale": scale}


def _with_segments(points, segments):
    """Append each frame's segments to its points as pairs of extra points (the most any
    frame has; a frame with fewer repeats its first node for the rest, segments of zero
    length that draw nothing), and the polyline order that draws them."""
    segments = [np.asarray(s, dtype=float).reshape(-1, 6) for s in segments]
    most = max((len(s) for s in segments), default=0)
    if most == 0:
        return points, None
    extra = np.repeat(points[:, :1, :], 2 * most, axis=1)
    for f, s in enumerate(segments):
        extra[f, :2 * len(s)] = s.reshape(-1, 3)
    first = points.shape[1]
    order = np.full(3 * most, -1, dtype=np.int64)
    order[0::3] = first + 2 * np.arange(most)
    order[1::3] = first + 2 * np.arange(most) + 1
    return np.concatenate([points, extra], axis=1), order


def _increments(increments, num_steps):
    if increments is None:
        return np.arange(1, num_steps + 1)
    numbers = np.asarray(increments)
    if numbers.shape != (num_steps,) or not np.issubdtype(numbers.dtype, np.integer) or \
            (num_steps > 1 and np.any(np.diff(numbers) <= 0)) or numbers.min() < 1:
        raise ValueError(f"increments has shape {numbers.shape}: must be {num_steps} "
                         "ascending integers >= 1, one per row of the path")
    return numbers


def _escape(text: str) -> str:
    """``text`` with ``&``, ``<``, ``>``, ``"`` and ``'`` as HTML entities (as
    ``html.escape`` writes them, without importing its table of every entity)."""
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
            .replace('"', "&quot;").replace("'", "&#x27;"))


def _write(file: Path, title: str, spec: dict, frames: str) -> Path:
    plain = re.sub(r"<[^>]+>", " ", title).strip()
    figure = json.dumps(spec, separators=(",", ":")).replace("</", "<\\/")
    # Each part encoded on its own: plotly's 1.8 MB stay ASCII, never copied into a wider
    # string by a title's non-ASCII character.
    parts = [
        '<!DOCTYPE html>\n<html>\n<head>\n<meta charset="utf-8">\n',
        f"<title>{_escape(plain)}</title>\n",
        "<style>html, body { margin: 0; } #kresling-view { width: 100%; height: 100vh; "
        "min-height: 520px; }</style>\n</head>\n<body>\n",
        '<div id="kresling-view"></div>\n',
        '<script type="text/plain" id="kresling-plotly">', packed_plotly_js(), "</script>\n",
        f'<script type="application/json" id="kresling-figure">{figure}</script>\n',
        f'<script type="text/plain" id="kresling-frames">{frames}</script>\n',
        f"<script>{DECODE_JS}{PAGE_SCRIPT}</script>\n</body>\n</html>\n"]
    file.parent.mkdir(parents=True, exist_ok=True)
    part = file.with_name(file.name + ".part")
    with part.open("wb") as handle:
        handle.writelines(text.encode("utf-8") for text in parts)
    part.replace(file)
    return file
