"""The design explorer: one offline page to move through the thesis's design space.

Sliders choose n (4, 6, 8, 10), lambda and Lc on a grid over the thesis's design space
(lambda in [0.7, 0.9], Lc in [R/2, 2R]); the page shows the cell in both stable states
(:meth:`kresling.Design.vertices`, on one scale), its flat crease pattern, and a marker on
the maps of the K_B ratio (the thesis's 0.001 rad bending protocol) and of the snap-through
force over (Lc, lambda) for that n. Clicking a map moves there too. The maps come from a
sweep (:func:`kresling.sweeps.sweep`) at the grid's resolution, which the page states; the
slider positions are the grid's points.

``explorer.html#n=8&lam=0.8&Lc=30`` opens at that design (the nearest grid point), and the
address follows the sliders.

Build it in two steps: :func:`explorer_data` (the sweep, the cells and the patterns, a
JSON-ready dict) and :func:`write_explorer` (the page, plotly's JavaScript inlined once);
``kresling explore -o explorer.html`` does both. The flat pattern is drawn by a function
given to :func:`explorer_data` (the command line gives :func:`kresling.fabrication.crease_pattern`'s);
without it the page leaves the pattern out.
"""

from __future__ import annotations

import html as _html
import json
import time
from pathlib import Path

import numpy as np
import plotly.graph_objects as go

from kresling.geometry import Design
from kresling.sweeps.designs import THESIS_LAM, THESIS_N, design_grid
from kresling.view.surface import polyline_order
from kresling.view.symbols import subscripted

__all__ = ["explorer_data", "explorer_figure", "write_explorer", "DEFAULT_SIZE", "MAPS",
           "DIV_ID"]

#: Grid points along Lc and lambda: Lc every 2.5 mm over 15-60 mm, lambda every 0.01 over
#: 0.7-0.9 (so the thesis's designs, e.g. n = 8, lambda = 0.8, Lc = 30, are grid points).
DEFAULT_SIZE = (19, 21)

#: The maps the page shows: sweep metric -> (title in plain text, colour scale). The page
#: sets the title's symbols with subscripts (:func:`kresling.view.symbols.subscripted`).
MAPS = {"kb_ratio": ("K_B ratio K_ext / K_con (0.001 rad)", "Viridis"),
        "snap_force": ("snap-through force [N]", "Plasma")}

#: The id of the figure's element in the page.
DIV_ID = "kresling-explorer"

#: Decimals of the cells' and patterns' coordinates in the page [mm]: 1e-3 mm, well below
#: what the page can show.
_DECIMALS = 3

#: Line style of the cells' edges and the pattern's lines: (colour, width, dash).
LINE_STYLES = {"mountain": ("#d62728", 4, "solid"), "valley": ("#1f77b4", 4, "solid"),
           "polygon_edge": ("#6a3d9a", 4, "solid"), "tab": ("#6a3d9a", 2, "solid"),
           "seam": ("#8c8c8c", 2, "dash"), "boundary": ("#3b3b3b", 2, "solid")}
CELL_STATES = ((1, "extended"), (0, "contracted"))


def cell_topology(n: int) -> dict:
    """Triangles and edge families of a cell whose points are ``B_0..B_(n-1), T_0..T_(n-1)``
    (:meth:`Design.vertices` flattened): facets ``(B_i, B_(i+1), T_(i+1))`` and
    ``(B_i, T_(i+1), T_i)``, valley ``B_i T_(i+1)``, mountain ``B_i T_i`` (as the flat
    pattern folds, chirality +1)."""
    i = np.arange(n)
    b, t, b1, t1 = i, n + i, (i + 1) % n, n + (i + 1) % n
    triangles = np.vstack([np.column_stack([b, b1, t1]), np.column_stack([b, t1, t])])
    lines = {"polygon_edge": np.vstack([np.column_stack([b, b1]), np.column_stack([t, t1])]),
             "valley": np.column_stack([b, t1]), "mountain": np.column_stack([b, t])}
    return {"i": triangles[:, 0].tolist(), "j": triangles[:, 1].tolist(),
            "k": triangles[:, 2].tolist(),
            "lines": {name: polyline_order(edges).tolist() for name, edges in lines.items()}}


def _rounded(values) -> list:
    return (np.round(np.asarray(values, dtype=float), _DECIMALS) + 0.0).ravel().tolist()


def _grid_values(values) -> list:
    """A map as nested lists, NaN -> None (JSON null: a gap in the heat map)."""
    return [[None if not np.isfinite(v) else float(v) for v in row] for row in values]


def explorer_data(n=THESIS_N, size=DEFAULT_SIZE, *, Lc=None, lam=THESIS_LAM, R=30.0,
                  workers=None, flat_pattern=None, progress=False, parameters=None) -> dict:
    """Everything the explorer page shows, as a JSON-ready dict.

    Runs a sweep of the K_B ratio (0.001 rad protocol) and the snap-through test over the
    grid (:func:`kresling.sweeps.design_grid` with these arguments; about 8 s for the
    default 4 x 19 x 21 designs on two cores), and computes every grid design's vertices in
    both states and, with ``flat_pattern``, its flat pattern.

    Parameters
    ----------
    n : sequence of int, default (4, 6, 8, 10)
        Even (the bending test pins opposite vertices).
    size : int or (int, int), default :data:`DEFAULT_SIZE`
        Grid points along Lc and lambda.
    Lc, lam, R
        The design space, as for :func:`kresling.sweeps.design_grid` (default Lc in
        [R/2, 2R], lambda in [0.7, 0.9], R = 30 mm).
    workers : int, optional
        Sweep workers (default every core).
    flat_pattern : callable, optional
        ``flat_pattern(design) -> (points (V, 2), edges (E, 2), kinds (E,))`` [mm], the
        same edges and kinds for every design of one n (e.g. from
        :func:`kresling.fabrication.crease_pattern`: ``points``, ``edges``,
        ``edge_kinds``). None: the page has no pattern.
    progress : bool, default False
        The sweep's progress bar.
    parameters : SpecimenParameters, optional
        The specimens' material and model for the maps (default the thesis's).

    Returns
    -------
    dict
        ``n``, ``Lc``, ``lam``, ``R``; ``maps[metric][str(n)]`` (lists of lists
        ``[lambda][Lc]``, ``None`` where the metric has no value: a monostable cell has no
        snap force); ``cells[str(n)]`` (triangles, lines, and per state the vertices of
        every design, ``Lc``-major, 1e-3 mm); ``patterns[str(n)]`` (the same for the flat
        pattern, or ``None``); ``height`` (the tallest cell [mm]); ``sweep`` (designs,
        seconds, workers, metrics, and the specimen parameters as a dict).

    Raises
    ------
    ValueError
        For an odd n, a bad grid, or a ``flat_pattern`` whose lines differ between designs
        of one n.

    Examples
    --------
    >>> data = explorer_data((8,), (3, 3), workers=1)
    >>> data["Lc"], data["lam"]
    ([15.0, 37.5, 60.0], [0.7, 0.8, 0.9])
    >>> round(data["maps"]["kb_ratio"]["8"][2][0], 2)    # n = 8, lambda = 0.9, Lc = 15
    21.34
    """
    from kresling.sweeps import sweep

    grid = design_grid(n, size, Lc=Lc, lam=lam, R=R)
    ns = sorted({int(v) for v in grid.n})
    start = time.perf_counter()
    table = sweep(grid, list(MAPS), workers=workers, progress=progress, parameters=parameters)
    seconds = time.perf_counter() - start
    Lc_values = sorted({float(v) for v in grid.Lc})
    lam_values = sorted({float(v) for v in grid.lam})
    data = {"n": ns, "Lc": Lc_values, "lam": lam_values, "R": float(grid.R[0]),
            "maps": {metric: {} for metric in MAPS}, "cells": {}, "patterns": {},
            "sweep": {"designs": len(grid), "seconds": round(seconds, 1),
                      "workers": int(table.attrs.get("workers", 0) or 0),
                      "failed": int((table["status"] != "ok").sum()),
                      "metrics": list(MAPS),
                      "parameters": table.attrs.get("parameters")}}
    tallest = 0.0
    for k in ns:
        for metric in MAPS:
            _, _, values = table.grid(metric, k)
            data["maps"][metric][str(k)] = _grid_values(values)
        designs = [Design(k, a, c, data["R"]) for c in Lc_values for a in lam_values]
        cell = cell_topology(k)
        cell["states"] = {}
        for state, _ in CELL_STATES:
            vertices = [d.vertices(state).reshape(-1, 3) for d in designs]
            tallest = max(tallest, max(float(v[:, 2].max()) for v in vertices))
            cell["states"][str(state)] = [_rounded(v) for v in vertices]
        data["cells"][str(k)] = cell
        data["patterns"][str(k)] = None if flat_pattern is None else \
            _patterns(k, designs, flat_pattern)
    data["height"] = tallest
    return data


def _patterns(n, designs, flat_pattern) -> dict:
    first_edges = first_kinds = None
    points = []
    for design in designs:
        p, edges, kinds = flat_pattern(design)
        edges = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
        kinds = [str(kind) for kind in kinds]
        if first_edges is None:
            first_edges, first_kinds = edges, kinds
        elif not (np.array_equal(edges, first_edges) and kinds == first_kinds):
            raise ValueError(f"flat_pattern gives different lines for designs of n = {n}: "
                             "the explorer needs one topology per n")
        points.append(_rounded(np.asarray(p, dtype=float)[:, :2]))
    lines = {}
    for kind in dict.fromkeys(first_kinds):
        chosen = first_edges[[k == kind for k in first_kinds]]
        lines[kind] = polyline_order(chosen).tolist()
    return {"lines": lines, "points": points}


def _nearest(values, value) -> int:
    return int(np.argmin(np.abs(np.asarray(values, dtype=float) - float(value))))


def _xyz(flat, order, dims=3):
    """Coordinates of the polylines ``order`` (-1: a gap) from flat coordinates."""
    points = np.asarray(flat, dtype=float).reshape(-1, dims)
    out = [[None if v < 0 else float(points[v, k]) for v in order] for k in range(dims)]
    return out


def explorer_figure(data, n=None, lam=None, Lc=None) -> go.Figure:
    """The explorer's figure at one design (the nearest grid point to ``n``, ``lam``,
    ``Lc``; default the middle of the grid for the largest n): the cell in both states,
    its flat pattern, the two maps with a marker.

    The page's script redraws the same traces from ``data`` when a slider moves; their
    order is fixed (see :func:`write_explorer`).

    Parameters
    ----------
    data : dict
        From :func:`explorer_data`.
    n : int, optional
    lam, Lc : float, optional
        Angle ratio and contracted height [mm].

    Returns
    -------
    plotly.graph_objects.Figure
    """
    ns = data["n"]
    n = ns[-1] if n is None else ns[_nearest(ns, n)]
    a = len(data["lam"]) // 2 if lam is None else _nearest(data["lam"], lam)
    c = len(data["Lc"]) // 2 if Lc is None else _nearest(data["Lc"], Lc)
    index = c * len(data["lam"]) + a
    cell = data["cells"][str(n)]
    fig = go.Figure()
    for scene, (state, name) in zip(("scene", "scene2"), CELL_STATES):
        flat = cell["states"][str(state)][index]
        x, y, z = _xyz(flat, range(len(flat) // 3))
        fig.add_trace(go.Mesh3d(x=x, y=y, z=z, i=cell["i"], j=cell["j"], k=cell["k"],
                                color="#e9dcc0", flatshading=True, name=f"{name} cell",
                                hoverinfo="skip", scene=scene, showlegend=False,
                                lighting=dict(ambient=0.6, diffuse=0.6, specular=0.05,
                                              roughness=0.9, fresnel=0.05),
                                lightposition=dict(x=25000, y=50000, z=100000)))
        for family, order in cell["lines"].items():
            colour, width, dash = LINE_STYLES[family]
            x, y, z = _xyz(flat, order)
            fig.add_trace(go.Scatter3d(x=x, y=y, z=z, mode="lines", name=family, scene=scene,
                                       line=dict(color=colour, width=width, dash=dash),
                                       hoverinfo="name", showlegend=False))
    pattern = data["patterns"].get(str(n))
    for kind in (pattern or {"lines": {}})["lines"]:
        colour, width, dash = LINE_STYLES.get(kind, ("#8c8c8c", 2, "solid"))
        x, y = _xyz(pattern["points"][index], pattern["lines"][kind], dims=2)
        fig.add_trace(go.Scatter(x=x, y=y, mode="lines", name=kind, xaxis="x", yaxis="y",
                                 line=dict(color=colour, width=width / 2 + 0.5, dash=dash),
                                 hoverinfo="name", showlegend=False))
    for k, (metric, (label, scale)) in enumerate(MAPS.items()):
        label = subscripted(label)
        axes = dict(xaxis=f"x{k + 2}", yaxis=f"y{k + 2}")
        fig.add_trace(go.Heatmap(
            x=data["Lc"], y=data["lam"], z=data["maps"][metric][str(n)], colorscale=scale,
            name=metric, colorbar=dict(title=dict(text=label, side="right"), len=0.4, y=0.2,
                                       x=0.445 if k == 0 else 1.0, thickness=12),
            hovertemplate="Lc %{x} mm, λ %{y}<br>" + label + ": %{z:.4g}<extra></extra>",
            **axes))
        fig.add_trace(go.Scatter(
            x=[data["Lc"][c]], y=[data["lam"][a]], mode="markers", name=f"{metric} design",
            marker=dict(size=13, color="white", symbol="circle",
                        line=dict(color="black", width=2.5)),
            hoverinfo="skip", showlegend=False, **axes))
    _layout(fig, data)
    return fig


def _layout(fig, data) -> None:
    R, top = data["R"], data["height"]
    box = dict(range=[-1.05 * R, 1.05 * R])
    scene = dict(xaxis=dict(title=dict(text="x [mm]"), **box),
                 yaxis=dict(title=dict(text="y [mm]"), **box),
                 zaxis=dict(title=dict(text="z [mm]"), range=[0.0, 1.02 * top]),
                 aspectmode="manual",
                 aspectratio=dict(x=1.0, y=1.0, z=1.02 * top / (2.1 * R)),
                 camera=dict(eye=dict(x=1.6, y=1.6, z=1.0)))
    fig.update_layout(
        template="plotly_white", height=900, margin=dict(l=10, r=10, t=40, b=40),
        uirevision="explorer", showlegend=False,
        scene=dict(domain=dict(x=[0.0, 0.3], y=[0.5, 0.98]), **scene),
        scene2=dict(domain=dict(x=[0.31, 0.61], y=[0.5, 0.98]), **scene),
        xaxis=dict(domain=[0.67, 1.0], anchor="y", title=dict(text="flat pattern x [mm]")),
        yaxis=dict(domain=[0.55, 0.97], anchor="x", scaleanchor="x", scaleratio=1.0,
                   title=dict(text="y [mm]")),
        xaxis2=dict(domain=[0.0, 0.4], anchor="y2", title=dict(text="contracted height Lc [mm]")),
        yaxis2=dict(domain=[0.0, 0.4], anchor="x2", title=dict(text="angle ratio λ")),
        xaxis3=dict(domain=[0.55, 0.955], anchor="y3",
                    title=dict(text="contracted height Lc [mm]")),
        yaxis3=dict(domain=[0.0, 0.4], anchor="x3", title=dict(text="angle ratio λ")),
        annotations=[
            dict(text="<b>extended (1)</b>", x=0.15, y=1.0, **_TITLE),
            dict(text="<b>contracted (0)</b>", x=0.46, y=1.0, **_TITLE),
            dict(text="<b>flat crease pattern</b>" if any(data["patterns"].values())
                 else "<b>flat crease pattern</b> (not computed)", x=0.835, y=1.0, **_TITLE),
            dict(text=f"<b>{subscripted(MAPS['kb_ratio'][0])}</b>", x=0.2, y=0.43, **_TITLE),
            dict(text=f"<b>{subscripted(MAPS['snap_force'][0])}</b>", x=0.75, y=0.43,
                 **_TITLE)])


_TITLE = dict(xref="paper", yref="paper", xanchor="center", yanchor="bottom", showarrow=False,
              font=dict(size=14))

_STYLE = """
body { font: 14px/1.4 system-ui, sans-serif; margin: 0.6em 1em; color: #222; }
#explorer-controls { display: flex; flex-wrap: wrap; gap: 0.4em 1.6em; align-items: center; }
#explorer-controls label { display: flex; align-items: center; gap: 0.5em; }
#explorer-controls input { width: 16em; }
#explorer-controls output { font-variant-numeric: tabular-nums; min-width: 4.5em; }
#explorer-values { font-variant-numeric: tabular-nums; }
.note { color: #555; font-size: 12.5px; margin: 0.3em 0; }
"""

# The page's script. EXPLORER: the data; TRACES: which trace is which.
_SCRIPT = """
(function () {
  var gd = document.getElementById('{plot_id}');
  var D = __DATA__;
  var T = __TRACES__;
  var sliders = {n: document.getElementById('n-slider'), lam: document.getElementById('lam-slider'),
                 Lc: document.getElementById('Lc-slider')};
  var outputs = {n: document.getElementById('n-value'), lam: document.getElementById('lam-value'),
                 Lc: document.getElementById('Lc-value')};
  var info = document.getElementById('explorer-values');
  var revision = 0;
  sliders.n.max = D.n.length - 1; sliders.lam.max = D.lam.length - 1; sliders.Lc.max = D.Lc.length - 1;
  function nearest(values, v) {
    var best = 0;
    for (var i = 1; i < values.length; i++) {
      if (Math.abs(values[i] - v) < Math.abs(values[best] - v)) { best = i; }
    }
    return best;
  }
  function lines(flat, order, dims) {
    var out = [];
    for (var d = 0; d < dims; d++) { out.push([]); }
    for (var i = 0; i < order.length; i++) {
      for (var d2 = 0; d2 < dims; d2++) {
        out[d2].push(order[i] < 0 ? null : flat[dims * order[i] + d2]);
      }
    }
    return out;
  }
  function fmt(v, digits) { return v === null || v === undefined ? '–' : v.toFixed(digits); }
  function state() {
    return {n: parseInt(sliders.n.value, 10), lam: parseInt(sliders.lam.value, 10),
            Lc: parseInt(sliders.Lc.value, 10)};
  }
  function draw(writeHash) {
    var s = state(), n = D.n[s.n], key = String(n), index = s.Lc * D.lam.length + s.lam;
    var cell = D.cells[key];
    var data = gd.data.map(function (t) { return Object.assign({}, t); });
    outputs.n.textContent = n;
    outputs.lam.textContent = D.lam[s.lam].toFixed(3);
    outputs.Lc.textContent = D.Lc[s.Lc].toFixed(2) + ' mm';
    T.cells.forEach(function (c) {
      var flat = cell.states[c.state][index];
      var all = [];
      for (var i = 0; i < flat.length / 3; i++) { all.push(i); }
      var xyz = lines(flat, all, 3);
      var mesh = data[c.mesh];
      mesh.x = xyz[0]; mesh.y = xyz[1]; mesh.z = xyz[2];
      mesh.i = cell.i; mesh.j = cell.j; mesh.k = cell.k;
      c.lines.forEach(function (l) {
        var p = lines(flat, cell.lines[l.family], 3);
        data[l.trace].x = p[0]; data[l.trace].y = p[1]; data[l.trace].z = p[2];
      });
    });
    var pattern = D.patterns[key];
    T.pattern.forEach(function (l) {
      var p = pattern ? lines(pattern.points[index], pattern.lines[l.kind] || [], 2) : [[], []];
      data[l.trace].x = p[0]; data[l.trace].y = p[1];
    });
    var values = [];
    T.maps.forEach(function (m) {
      var z = D.maps[m.metric][key];
      data[m.heatmap].z = z;
      data[m.marker].x = [D.Lc[s.Lc]]; data[m.marker].y = [D.lam[s.lam]];
      values.push(z[s.lam][s.Lc]);
    });
    var heights = [cell.states['1'][index], cell.states['0'][index]].map(function (f) {
      return f[f.length - 1];
    });
    // innerHTML for the subscript (K<sub>B</sub>): every value in it is a number formatted here.
    info.innerHTML = 'Le = ' + fmt(heights[0], 2) + ' mm, Lc = ' + fmt(heights[1], 2) +
      ' mm;  K<sub>B</sub> ratio ' + fmt(values[0], 2) + ';  snap force ' +
      (values[1] === null ? 'none (monostable)' : fmt(values[1], 2) + ' N');
    if (writeHash) {
      var hash = '#n=' + n + '&lam=' + D.lam[s.lam].toFixed(3).replace(/0+$/, '').replace(/\\.$/, '') +
                 '&Lc=' + D.Lc[s.Lc].toFixed(2).replace(/0+$/, '').replace(/\\.$/, '');
      if (window.location.hash !== hash) { history.replaceState(null, '', hash); }
    }
    revision += 1;
    return Plotly.react(gd, data, Object.assign({}, gd.layout, {datarevision: revision}));
  }
  function fromHash() {
    var h = window.location.hash.replace(/^#/, ''), found = false;
    h.split('&').forEach(function (part) {
      var kv = part.split('='), v = parseFloat(kv[1]);
      if (kv.length !== 2 || !isFinite(v) || !sliders[kv[0]]) { return; }
      sliders[kv[0]].value = nearest(D[kv[0]], v);
      found = true;
    });
    return found;
  }
  ['n', 'lam', 'Lc'].forEach(function (k) {
    sliders[k].addEventListener('input', function () { draw(true); });
  });
  window.addEventListener('hashchange', function () { if (fromHash()) { draw(false); } });
  gd.on('plotly_click', function (event) {
    var p = event.points && event.points[0];
    if (!p || !p.data || p.data.type !== 'heatmap') { return; }
    sliders.Lc.value = nearest(D.Lc, p.x); sliders.lam.value = nearest(D.lam, p.y);
    draw(true);
  });
  window.kreslingExplorerShow = function (n, lam, Lc) {
    sliders.n.value = nearest(D.n, n); sliders.lam.value = nearest(D.lam, lam);
    sliders.Lc.value = nearest(D.Lc, Lc);
    return draw(true);
  };
  fromHash();
  window.kreslingExplorerReady = draw(false);
})();
"""


def _trace_map(fig) -> dict:
    """Which trace of :func:`explorer_figure` is which, for the page's script."""
    names = [trace.name for trace in fig.data]
    cells = []
    for state, name in CELL_STATES:
        mesh = names.index(f"{name} cell")
        scene = fig.data[mesh].scene
        lines = [{"family": t.name, "trace": i} for i, t in enumerate(fig.data)
                 if t.type == "scatter3d" and t.scene == scene]
        cells.append({"state": str(state), "mesh": mesh, "lines": lines})
    pattern = [{"kind": t.name, "trace": i} for i, t in enumerate(fig.data)
               if t.type == "scatter" and t.xaxis == "x"]
    maps = [{"metric": m, "heatmap": names.index(m), "marker": names.index(f"{m} design")}
            for m in MAPS]
    return {"cells": cells, "pattern": pattern, "maps": maps}


def write_explorer(data, path, *, n=None, lam=None, Lc=None) -> Path:
    """Write the explorer page: self-contained, offline (plotly's JavaScript inlined once).

    Parameters
    ----------
    data : dict
        From :func:`explorer_data`.
    path : str or os.PathLike
        The page (parent folders are created).
    n, lam, Lc : optional
        The design it opens at when its address names none (default: the middle of the
        grid for the largest n); ``explorer.html#n=8&lam=0.8&Lc=30`` opens at the grid point
        nearest that design.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    path = Path(path)
    fig = explorer_figure(data, n, lam, Lc)
    ns, Lcs, lams = data["n"], data["Lc"], data["lam"]
    start = {"n": len(ns) - 1 if n is None else _nearest(ns, n),
             "lam": len(lams) // 2 if lam is None else _nearest(lams, lam),
             "Lc": len(Lcs) // 2 if Lc is None else _nearest(Lcs, Lc)}
    script = _SCRIPT.replace("__DATA__", json.dumps(data, separators=(",", ":"))) \
        .replace("__TRACES__", json.dumps(_trace_map(fig)))
    page = fig.to_html(include_plotlyjs=True, full_html=True, div_id=DIV_ID,
                       post_script=script, config={"responsive": True, "displaylogo": False})
    sweep = data["sweep"]
    lam_step = (lams[-1] - lams[0]) / max(len(lams) - 1, 1)
    Lc_step = (Lcs[-1] - Lcs[0]) / max(len(Lcs) - 1, 1)
    resolution = (
        f"Maps: a sweep of {sweep['designs']} designs ({len(ns)} n × {len(Lcs)} Lc × "
        f"{len(lams)} λ: Lc {Lcs[0]:g}-{Lcs[-1]:g} mm every {Lc_step:g} mm, λ "
        f"{lams[0]:g}-{lams[-1]:g} every {lam_step:g}; R = {data['R']:g} mm) computed in "
        f"{sweep['seconds']:g} s on {sweep['workers']} workers"
        + (f", {sweep['failed']} failed" if sweep["failed"] else "")
        + ". K_B ratio: the thesis's 0.001 rad bending protocol on two modules; snap-through "
        "force: the first local maximum of the force driving one cell from extended to "
        "contracted (blank: none, the cell is monostable). The sliders move on this grid; "
        "click a map to jump there. The address (#n=8&lam=0.8&Lc=30) names the design.")
    controls = (
        f"<style>{_STYLE}</style>"
        "<h2 style=\"margin:0.2em 0\">Generalized Kresling cell: design explorer</h2>"
        '<div id="explorer-controls">'
        f'<label>n <input type="range" id="n-slider" min="0" step="1" value="{start["n"]}">'
        '<output id="n-value"></output></label>'
        f'<label>λ <input type="range" id="lam-slider" min="0" step="1" value="{start["lam"]}">'
        '<output id="lam-value"></output></label>'
        f'<label>Lc <input type="range" id="Lc-slider" min="0" step="1" value="{start["Lc"]}">'
        '<output id="Lc-value"></output></label>'
        '<span id="explorer-values"></span></div>'
        f'<p class="note">{subscripted(_html.escape(resolution))}</p>')
    page = page.replace("<body>", "<body>\n" + controls, 1)
    page = page.replace("<head>", "<head>\n    <title>kresling: design explorer</title>", 1)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(page, encoding="utf-8")
    return path
