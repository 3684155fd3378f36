"""The views: one state of a model (:func:`view_model`) and a whole path, animated, with
its load-displacement curve (:func:`view_path`)."""

from __future__ import annotations

import numpy as np
import plotly.graph_objects as go

from kresling.view.animation import (check_curve, default_curve, frame_name, play_buttons,
                                     select_rows, slider)
from kresling.view.fields import FIELDS, check_field, edge_values, field_edges, \
    significant_decimals
from kresling.view.inputs import view_inputs
from kresling.view.surface import (crease_groups, family_style, line_trace, mesh_trace,
                                   rounded, segments_xyz)

__all__ = ["view_model", "view_path"]

_FIELD_WIDTH = 7  # px


class _Scene:
    """The traces of the 3D scene for one model, in a fixed order: the panels, then the
    creases by family (or, with a field, the field's edges and the boundary)."""

    def __init__(self, inputs, field, values, scene="scene", colorbar_x=None):
        self.inputs, self.field, self.scene = inputs, field, scene
        model = inputs.model
        self.groups = crease_groups(model.hinges, inputs.hinge_family, inputs.triangles)
        if field is not None:
            self.edges_of_field = field_edges(model, field)
            shown = {tuple(e) for e in self.edges_of_field[0].tolist()}
            boundary = self.groups.get("boundary", np.zeros((0, 2), dtype=np.int64))
            boundary = boundary[[tuple(e) not in shown for e in boundary.tolist()]] \
                if len(boundary) else boundary
            self.groups = {"boundary": boundary} if len(boundary) else {}
            spec = FIELDS[field]
            values = np.asarray(values, dtype=float)
            largest = float(np.abs(values).max()) if values.size else 0.0
            largest = largest if largest > 0 else 1.0
            self.decimals = significant_decimals(values)
            largest = float(np.ceil(largest * 10.0 ** self.decimals) / 10.0 ** self.decimals)
            self.crange = (-largest, largest) if spec.signed else \
                (min(0.0, float(values.min()) if values.size else 0.0), largest)
            self.colorbar = dict(title=dict(text=spec.label, side="right"), len=0.75,
                                 thickness=14)
            if colorbar_x is not None:
                self.colorbar.update(x=colorbar_x, xanchor="left")

    def traces(self, points, values=None, *, coordinates_only=False):
        """The scene's traces at node positions ``points`` (N, 3) [mm] (and the field's
        edge values)."""
        out = []
        if len(self.inputs.triangles):
            out.append(mesh_trace(points, self.inputs.triangles, scene=self.scene,
                                  coordinates_only=coordinates_only))
        others = []
        for family, edges in self.groups.items():
            colour, width, dash = family_style(family, others)
            out.append(line_trace(points, edges, name=family, colour=colour, width=width,
                                  dash=dash, scene=self.scene,
                                  coordinates_only=coordinates_only))
        if self.field is not None:
            out.append(self._field_trace(points, values, coordinates_only))
        return out

    def _field_trace(self, points, values, coordinates_only):
        x, y, z = segments_xyz(points, self.edges_of_field[0])
        colour = rounded(np.repeat(np.asarray(values, dtype=float), 3), self.decimals)
        if coordinates_only:  # a frame: the colour scale and its range stay
            return go.Scatter3d(x=x, y=y, z=z, line=dict(color=colour))
        line = dict(color=colour, colorscale=FIELDS[self.field].colorscale,
                    cmin=self.crange[0], cmax=self.crange[1], width=_FIELD_WIDTH,
                    showscale=True, colorbar=self.colorbar)
        return go.Scatter3d(x=x, y=y, z=z, mode="lines", line=line,
                            name=FIELDS[self.field].label, hoverinfo="name",
                            scene=self.scene, connectgaps=False)


def _describe(model):
    return (f"{len(model.nodes)} nodes, {len(model.bars)} bars, {len(model.hinges)} hinges")


def _points(model, u):
    return np.asarray(model.nodes, dtype=float) + np.asarray(u, dtype=float).reshape(-1, 3)


def _box(points_list):
    """Corners of the box around every frame's nodes, padded by 3 % of its largest side."""
    stacked = np.vstack(points_list)
    low, high = stacked.min(axis=0), stacked.max(axis=0)
    pad = 0.03 * max(float((high - low).max()), 1e-9)
    return low - pad, high + pad


def _box_trace(points_list, scene="scene"):
    """Two invisible points at the box's corners: with ``aspectmode="data"`` the scene's
    scale then stays the same in every frame (the view holds still while playing)."""
    low, high = _box(points_list)
    return go.Scatter3d(x=rounded([low[0], high[0]]), y=rounded([low[1], high[1]]),
                        z=rounded([low[2], high[2]]), mode="markers",
                        marker=dict(size=1, opacity=0), hoverinfo="skip", showlegend=False,
                        name="extent", scene=scene)


def _scene_layout(points_list):
    """Equal scales on x, y, z (``aspectmode="data"``), axes fixed to the box of every
    frame."""
    low, high = _box(points_list)
    axes = {}
    for k, a in enumerate("xyz"):
        axes[f"{a}axis"] = dict(title=dict(text=f"{a} [mm]"),
                                range=rounded([low[k], high[k]]))
    # plotly scales the box to sides span / (geometric mean of the spans); the camera
    # steps back by the longest side so that a tall or wide model fits.
    span = np.maximum(high - low, 1e-12)
    longest = float(span.max() / np.exp(np.log(span).mean()))
    eye = np.array([1.0, 1.0, 0.7]) / np.linalg.norm([1.0, 1.0, 0.7]) * max(1.4 * longest, 2.2)
    return dict(aspectmode="data", camera=dict(eye=dict(zip("xyz", rounded(eye, 3)))), **axes)


def _check_u(model, name, u):
    u = np.asarray(u, dtype=float)
    if u.size != 3 * len(model.nodes):
        raise ValueError(f"{name} has {u.size} entries: must have one per DOF "
                         f"({3 * len(model.nodes)}), shape (3N,) or (N, 3)")
    return u.ravel()


def view_model(model, u=None, *, triangles=None, hinge_family=None, field=None,
               title=None) -> go.Figure:
    """An interactive 3D view of a model in one state.

    Panels are shaded (flat), creases drawn as lines coloured by family: mountain red,
    valley blue, flat/unassigned grey, bend light grey dashed, cut black, boundary dark
    grey, join cyan (a Kresling specimen's polygon edges purple, its polygon spokes light
    grey dashed); other names get colours of their own. With a ``field``, the edges are
    coloured by it instead (the family lines are then left out), with a colour bar.
    Coordinates are rounded to 1e-4 mm in the figure.

    Parameters
    ----------
    model : kresling.model.Model or an object with ``.model`` and ``.hinge_family``
        A :class:`kresling.model.KreslingSpecimen` (or a crease pattern's model) brings its
        own hinge families and triangles.
    u : array_like, shape (3N,) or (N, 3), optional
        Displacement [mm] (DOF ``3 i + k`` is coordinate ``k`` of node ``i``); default zero.
    triangles : array_like of int, shape (T, 3), optional
        The panels' triangles (e.g. ``kresling.model.panel_topology(...).triangles``);
        default: a carrier's (see ``model``), else those the hinges join, each hinge
        ``(a, b, c, d)`` giving ``(a, b, c)`` and ``(a, b, d)``.
    hinge_family : sequence of str, shape (H,), optional
        Family of every hinge: "mountain", "valley", "flat", "bend", "cut", "boundary" or
        any other name (drawn in a colour of its own).
    field : {None, "bar_strain", "hinge_angle_change", "energy"}
        Colour the edges by bar strain [-], hinge angle change [deg] or stored energy
        [N*mm] (see :mod:`kresling.view.fields`).
    title : str, optional

    Returns
    -------
    plotly.graph_objects.Figure
        Displays itself in Jupyter; ``.show()`` opens it elsewhere, and
        :func:`kresling.view.write_html` saves it as an offline page.

    Raises
    ------
    ValueError
        For a ``u`` of the wrong size, an unknown field, or bad triangles or families.
    """
    check_field(field)
    inputs = view_inputs(model, triangles=triangles, hinge_family=hinge_family)
    model = inputs.model
    u = np.zeros(3 * len(model.nodes)) if u is None else _check_u(model, "u", u)
    points = _points(model, u)
    values = edge_values(model, field, u) if field is not None else None
    scene = _Scene(inputs, field, values)
    fig = go.Figure(scene.traces(points, values) + [_box_trace([points])])
    default = f"Bar-and-hinge model: {_describe(model)}" + \
        (", displaced" if np.any(u) else ", reference state")
    fig.update_layout(
        title=dict(text=title or default, x=0.5, xanchor="center"),
        scene=_scene_layout([points]), template="plotly_white", height=650,
        margin=dict(l=10, r=10, t=90, b=10), uirevision="view",
        legend=dict(orientation="h", x=0.0, y=1.0, yanchor="bottom"))
    return fig


def view_path(model, path, *, triangles=None, hinge_family=None, field=None, curve=None,
              frame_stride=None, max_frames=200, title=None) -> go.Figure:
    """An animated 3D view of an equilibrium path beside its load-displacement curve.

    Left, the folded surface (as in :func:`view_model`) at one increment; right, the curve,
    with a marker at that increment. A slider ("increment K / S") and play/pause buttons
    step through the increments; frame ``"K"`` shows increment K, row ``K - 1`` of the
    path's arrays. To keep the figure (and an HTML file of it) small, at most
    ``max_frames`` increments become frames, and coordinates are rounded to 1e-4 mm
    (field values to 6 significant digits of the largest) in the figure; the curve keeps
    every increment.

    Parameters
    ----------
    model : kresling.model.Model or an object with ``.model`` and ``.hinge_family``
        As in :func:`view_model`.
    path : kresling.solvers.PathResult
        ``displacement`` (S, 3N) [mm] and ``load_factor`` (S,).
    triangles, hinge_family, field
        As in :func:`view_model`. A field's colour range is fixed over the frames.
    curve : (array_like, array_like, str, str), optional
        ``(x, y, x_label, y_label)`` with x and y of shape (S,). Default: the load factor
        against the displacement of the DOF that moves most over the path [mm].
    frame_stride : int, optional
        Show every ``frame_stride``-th increment (and the last). Default: up to
        ``max_frames`` evenly spaced increments, the first and last included.
    max_frames : int, default 200
        Upper bound on the number of frames.
    title : str, optional

    Returns
    -------
    plotly.graph_objects.Figure
        With one frame per shown increment; displays itself in Jupyter, ``.show()``
        elsewhere, :func:`kresling.view.write_html` for an offline page.

    Raises
    ------
    ValueError
        For a path of another model (its displacement's width is not 3N), an empty path,
        a bad curve, field, stride, triangles or families.

    Examples
    --------
    >>> fig = view_path(model, path, field="energy")         # doctest: +SKIP
    >>> write_html(fig, "path.html")                          # doctest: +SKIP
    """
    from plotly.subplots import make_subplots

    check_field(field)
    inputs = view_inputs(model, triangles=triangles, hinge_family=hinge_family)
    model = inputs.model
    displacement = np.asarray(path.displacement, dtype=float)
    num_steps = len(displacement)
    if num_steps == 0:
        raise ValueError("path has no increments: nothing to show")
    if displacement.ndim != 2 or displacement.shape[1] != 3 * len(model.nodes):
        raise ValueError(f"path.displacement has shape {displacement.shape}: must be "
                         f"(S, {3 * len(model.nodes)}) for this model")
    x, y, x_label, y_label = check_curve(curve if curve is not None
                                         else default_curve(model, path), num_steps)
    rows = select_rows(num_steps, frame_stride, max_frames)
    names = [frame_name(r) for r in rows]
    points = [_points(model, displacement[r]) for r in rows]
    values = None
    if field is not None:
        edges = field_edges(model, field)
        values = [edge_values(model, field, displacement[r], edges=edges) for r in rows]

    domain_end = 0.56
    fig = make_subplots(rows=1, cols=2, specs=[[{"type": "scene"}, {"type": "xy"}]],
                        column_widths=[0.62, 0.38], horizontal_spacing=0.14)
    scene = _Scene(inputs, field, np.concatenate(values) if values else None,
                   colorbar_x=domain_end + 0.005)
    first = scene.traces(points[0], values[0] if values else None)
    for trace in first:
        fig.add_trace(trace, row=1, col=1)
    moving = list(range(len(first)))
    fig.add_trace(_box_trace(points), row=1, col=1)
    curve_decimals = (significant_decimals(x), significant_decimals(y))
    fig.add_trace(go.Scatter(
        x=rounded(x, curve_decimals[0]), y=rounded(y, curve_decimals[1]), mode="lines",
        name="path", line=dict(color="#444444", width=2), showlegend=False,
        hovertemplate=f"{x_label}: %{{x}}<br>{y_label}: %{{y}}<extra></extra>"), row=1, col=2)

    def marker(row, full=False):
        args = dict(x=rounded(x[[row]], curve_decimals[0]), y=rounded(y[[row]], curve_decimals[1]))
        if not full:
            return go.Scatter(**args)
        return go.Scatter(**args, mode="markers", name="increment shown", showlegend=False,
                          cliponaxis=False,
                          marker=dict(color="#d62728", size=12, line=dict(color="white",
                                                                          width=1.5)),
                          hovertemplate="shown: %{x}, %{y}<extra></extra>")

    fig.add_trace(marker(rows[0], full=True), row=1, col=2)
    marker_index = len(fig.data) - 1
    fig.frames = [go.Frame(name=name,
                           data=scene.traces(p, v, coordinates_only=True) + [marker(r)],
                           traces=moving + [marker_index])
                  for name, r, p, v in zip(names, rows, points, values or [None] * len(rows))]
    fig.update_xaxes(title_text=x_label, row=1, col=2)
    fig.update_yaxes(title_text=y_label, row=1, col=2)
    default = f"Equilibrium path of a bar-and-hinge model ({_describe(model)}), " \
              f"{num_steps} increments"
    if field is not None:
        default += f": {FIELDS[field].label}"
    fig.update_layout(
        title=dict(text=title or default, x=0.5, xanchor="center"),
        scene=_scene_layout(points), template="plotly_white", height=700,
        margin=dict(l=10, r=20, t=100, b=130), uirevision="view",
        legend=dict(orientation="h", x=0.0, y=1.0, yanchor="bottom"),
        sliders=[slider(names, num_steps)], updatemenus=[play_buttons()])
    fig.layout.scene.domain.x = [0.0, domain_end]
    fig.layout.xaxis.domain = [domain_end + 0.14, 1.0]
    return fig
