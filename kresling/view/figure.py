"""The views: one state of a model (:func:`view_model`) and a whole path, animated, with
its load-displacement curve (:func:`view_path`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import plotly.graph_objects as go

from kresling._validation import as_float_array

from kresling.view.animation import (PARTIAL_COLOUR, check_curve, default_curve, frame_name,
                                     partial_line, play_buttons, select_rows, slider)
from kresling.view.fields import FIELDS, check_field, edge_values, field_edges, \
    significant_decimals
from kresling.view.inputs import view_inputs
from kresling.view.scene_box import box, check_path, describe, node_points, scene_layout
from kresling.view.surface import (crease_groups, family_style, line_trace, mesh_trace,
                                   polyline_order, rounded, segments_xyz)
from kresling.view.symbols import subscripted

__all__ = ["view_model", "view_path", "PathPanel", "PathCurve", "animated_figure"]

_FIELD_WIDTH = 7  # px



class _Scene:
    """The traces of the 3D scene for one model, in a fixed order: the panels, then the
    creases by family (or, with a field, the field's edges and the boundary).

    ``values`` sets the field's colour range (every value the scene, or the scenes sharing
    the range, will show); ``show_scale`` draws its colour bar, ``show_legend`` puts the
    scene's traces in the legend (a second scene shares the first one's entries)."""

    def __init__(self, inputs, field, values, scene="scene", colorbar_x=None,
                 show_scale=True, show_legend=True):
        self.inputs, self.field, self.scene = inputs, field, scene
        self.show_legend = show_legend
        model = inputs.model
        self.groups = {**crease_groups(model.hinges, inputs.hinge_family, inputs.triangles),
                       **inputs.lines}
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
            self.show_scale = show_scale
            self.colorbar = dict(title=dict(text=subscripted(spec.label), side="right"),
                                 len=0.75, thickness=14)
            if colorbar_x is not None:
                self.colorbar.update(x=colorbar_x, xanchor="left")
        others = []
        self.styles = {family: family_style(family, others) for family in self.groups}
        self.orders = {family: polyline_order(edges) for family, edges in self.groups.items()}

    def traces(self, points, values=None, *, coordinates_only=False):
        """The scene's traces at node positions ``points`` (N, 3) [mm] (and the field's
        edge values)."""
        out = []
        legend = None if self.show_legend else False
        if len(self.inputs.triangles):
            mesh = mesh_trace(points, self.inputs.triangles, scene=self.scene,
                              coordinates_only=coordinates_only)
            if not coordinates_only:
                mesh.update(legendgroup="panels", showlegend=self.show_legend)
            out.append(mesh)
        for family, edges in self.groups.items():
            colour, width, dash = self.styles[family]
            out.append(line_trace(points, edges, name=family, colour=colour, width=width,
                                  dash=dash, scene=self.scene, order=self.orders[family],
                                  coordinates_only=coordinates_only, legendgroup=family,
                                  showlegend=legend))
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
                    showscale=self.show_scale, colorbar=self.colorbar)
        return go.Scatter3d(x=x, y=y, z=z, mode="lines", line=line,
                            name=subscripted(FIELDS[self.field].label), hoverinfo="name",
                            scene=self.scene, connectgaps=False,
                            legendgroup="field", showlegend=self.show_legend)


def _box_trace(points_list, scene="scene"):
    """Two invisible points at the box's corners: with ``aspectmode="data"`` the scene's
    scale then stays the same in every frame (the view holds still while playing)."""
    low, high = box(points_list)
    return go.Scatter3d(x=rounded([low[0], high[0]], 4), y=rounded([low[1], high[1]], 4),
                        z=rounded([low[2], high[2]], 4), mode="markers",
                        marker=dict(size=1, opacity=0), hoverinfo="skip", showlegend=False,
                        name="extent", scene=scene)


def _check_u(model, name, u):
    u = as_float_array(name, u)
    if not np.isfinite(u).all():
        raise ValueError(f"{name} contains NaN or inf")
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
    Coordinates are rounded to 1e-10 mm in the figure.

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
    points = node_points(model, u)
    values = edge_values(model, field, u) if field is not None else None
    scene = _Scene(inputs, field, values)
    fig = go.Figure(scene.traces(points, values) + [_box_trace([points])])
    default = f"Bar-and-hinge model: {describe(model)}" + \
        (", displaced" if np.any(u) else ", reference state")
    fig.update_layout(
        title=dict(text=subscripted(title or default), x=0.5, xanchor="center"),
        scene=scene_layout([points]), template="plotly_white", height=650,
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
    ``max_frames`` increments become frames, coordinates are rounded to 1e-10 mm (field
    values to 6 significant digits of the largest) and each crease family is drawn as few
    polylines as it allows; the curve keeps every increment.

    Parameters
    ----------
    model : kresling.model.Model or an object with ``.model`` and ``.hinge_family``
        As in :func:`view_model`.
    path : kresling.solvers.PathResult or an object with ``displacement`` (S, 3N)
        ``displacement`` [mm] and (for the default curve) ``load_factor`` (S,).
    triangles, hinge_family, field
        As in :func:`view_model`. A field's colour range is fixed over the frames.
    curve : (array_like, array_like, str, str) or False, optional
        ``(x, y, x_label, y_label)`` with x and y of shape (S,). Default: the load factor
        against the displacement of the DOF that moves most over the path [mm]. False: no
        curve (the scene alone).
    frame_stride : int, optional
        Show every ``frame_stride``-th increment (and the last). Default: up to
        ``max_frames`` evenly spaced increments, the first and last included.
    max_frames : int, default 200
        Upper bound on the number of frames.
    title : str, optional
        Default: the model and the increments. A path that stopped early (``completed``
        False) adds a red line below it (also below a given title): "PARTIAL: the solver
        stopped after S increments" and its ``message``.

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
    check_field(field)
    inputs = view_inputs(model, triangles=triangles, hinge_family=hinge_family)
    model = inputs.model
    displacement = check_path(model, path)
    num_steps = len(displacement)
    curves = []
    x_label = y_label = ""
    if curve is not False:
        x, y, x_label, y_label = check_curve(curve if curve is not None
                                             else default_curve(model, path), num_steps)
        curves = [PathCurve(x, y, "path", "#444444")]
    rows = select_rows(num_steps, frame_stride, max_frames)
    default = f"Equilibrium path of a bar-and-hinge model ({describe(model)}), " \
              f"{num_steps} increments"
    if field is not None:
        default += f": {FIELDS[field].label}"
    shown = title or default
    if getattr(path, "completed", True) is False:
        # A solver that stopped early: the page says so below any title, with the reason.
        shown += partial_line(num_steps, getattr(path, "message", ""))
    return animated_figure([PathPanel(inputs, displacement)], rows,
                           [frame_name(r) for r in rows], curves=curves, x_label=x_label,
                           y_label=y_label, field=field, title=shown, total=num_steps)


@dataclass(frozen=True)
class PathPanel:
    """One 3D scene of an animated figure: a model and its displacements.

    Attributes
    ----------
    inputs : kresling.view.inputs.ViewInputs
        The model, its triangles and families (:func:`kresling.view.inputs.view_inputs`).
    displacement : ndarray, shape (S, 3N)
        One row per increment [mm].
    title : str
        Shown above the scene (with two scenes or more).
    """

    inputs: object
    displacement: np.ndarray
    title: str = ""


@dataclass(frozen=True)
class PathCurve:
    """A curve beside the scenes, with a marker that follows the frame.

    Attributes
    ----------
    x, y : ndarray, shape (S,)
        One value per increment.
    name : str
        Legend name (a single curve is not put in the legend).
    colour : str
    """

    x: np.ndarray
    y: np.ndarray
    name: str
    colour: str


_MARKER_COLOUR = "#d62728"


def animated_figure(panels, rows, names, *, curves=(), x_label="", y_label="", field=None,
                    title="", total=None, prefix="increment ", height=700) -> go.Figure:
    """Scenes animated together over the same increments, beside curves whose markers
    follow the frame.

    :func:`view_path` is one scene and one curve; a bending test in both states is two
    scenes and two curves, a FOLD file's frames one scene and no curve. The title, the axis
    titles, the curves' and panels' names may name symbols in plain text (``K_B``,
    ``Psi_ext``): the figure sets them with subscripts (:mod:`kresling.view.symbols`).

    Parameters
    ----------
    panels : sequence of PathPanel
        One scene each (one or two), side by side. A panel with fewer rows than a frame
        asks for shows its last row.
    rows : sequence of int
        The rows that become frames, ascending.
    names : sequence of str
        The frames' names (the numbers ``#frame=K`` refers to), one per row.
    curves : sequence of PathCurve
        Drawn on one pair of axes, right of the scenes; none: the scenes alone.
    x_label, y_label : str
        The curves' axis titles.
    field : str, optional
        Colour the edges by a field (see :data:`kresling.view.FIELDS`); its colour range is
        shared by every scene and frame.
    title : str
    total : int, optional
        Shown on the slider as "increment K / total" (default: the largest name).
    prefix : str, default "increment "
        What a frame is, on the slider.
    height : int, default 700
        Figure height [px].

    Returns
    -------
    plotly.graph_objects.Figure
    """
    from plotly.subplots import make_subplots

    check_field(field)
    rows = [int(r) for r in rows]
    names = [str(name) for name in names]
    # Every text the figure shows, with its symbols subscripted (K_B as K<sub>B</sub>).
    title, x_label, y_label = subscripted(title), subscripted(x_label), subscripted(y_label)
    curves = [PathCurve(c.x, c.y, subscripted(c.name), c.colour) for c in curves]
    if not panels or len(panels) > 2:
        raise ValueError(f"panels has {len(panels)} entries: must have one or two")
    if len(rows) != len(names) or not rows:
        raise ValueError(f"rows ({len(rows)}) and names ({len(names)}) must have one entry per "
                         "frame, at least one")
    points, values = [], []
    for panel in panels:
        model = panel.inputs.model
        last = len(panel.displacement) - 1
        points.append([node_points(model, panel.displacement[min(r, last)]) for r in rows])
        if field is not None:
            edges = field_edges(model, field)
            values.append([edge_values(model, field, panel.displacement[min(r, last)],
                                       edges=edges) for r in rows])
    with_curve = bool(curves)
    scenes_end = (0.56 if len(panels) == 1 else 0.62) if with_curve else 1.0
    specs = [[{"type": "scene"}] * len(panels) + ([{"type": "xy"}] if with_curve else [])]
    widths = [scenes_end / len(panels)] * len(panels) + ([1.0 - scenes_end] if with_curve
                                                          else [])
    fig = make_subplots(rows=1, cols=len(specs[0]), specs=specs, column_widths=widths,
                        horizontal_spacing=0.0)
    shared = np.concatenate([np.concatenate(v) for v in values]) if values else None
    moving, scenes = [], []
    for k, panel in enumerate(panels):
        scene_name = "scene" if k == 0 else f"scene{k + 1}"
        scene = _Scene(panel.inputs, field, shared, scene=scene_name,
                       colorbar_x=scenes_end + 0.005, show_scale=k == len(panels) - 1,
                       show_legend=k == 0)
        scenes.append(scene)
        first = scene.traces(points[k][0], values[k][0] if values else None)
        for trace in first:
            fig.add_trace(trace, row=1, col=k + 1)
        moving.append(list(range(len(fig.data) - len(first), len(fig.data))))
        fig.add_trace(_box_trace(points[k], scene=scene_name), row=1, col=k + 1)

    marker_indices, decimals = [], []
    single = len(curves) == 1
    for curve in curves:
        x, y = np.asarray(curve.x, dtype=float), np.asarray(curve.y, dtype=float)
        decimals.append((significant_decimals(x), significant_decimals(y)))
    for curve, (dx, dy) in zip(curves, decimals):
        fig.add_trace(go.Scatter(
            x=rounded(curve.x, dx), y=rounded(curve.y, dy), mode="lines", name=curve.name,
            line=dict(color=curve.colour, width=2), showlegend=not single,
            hovertemplate=("" if single else f"{curve.name}<br>")
            + f"{x_label}: %{{x}}<br>{y_label}: %{{y}}<extra></extra>"),
            row=1, col=len(panels) + 1)

    def marker(curve, dx, dy, row, full=False):
        row = min(row, len(curve.x) - 1)
        args = dict(x=rounded(np.asarray(curve.x, dtype=float)[[row]], dx),
                    y=rounded(np.asarray(curve.y, dtype=float)[[row]], dy))
        if not full:
            return go.Scatter(**args)
        colour = _MARKER_COLOUR if single else curve.colour
        return go.Scatter(**args, mode="markers", name="increment shown", showlegend=False,
                          cliponaxis=False,
                          marker=dict(color=colour, size=12, line=dict(color="white",
                                                                       width=1.5)),
                          hovertemplate="shown: %{x}, %{y}<extra></extra>")

    for curve, (dx, dy) in zip(curves, decimals):
        fig.add_trace(marker(curve, dx, dy, rows[0], full=True), row=1, col=len(panels) + 1)
        marker_indices.append(len(fig.data) - 1)

    frames = []
    for i, (name, row) in enumerate(zip(names, rows)):
        data, traces = [], []
        for k, scene in enumerate(scenes):
            data += scene.traces(points[k][i], values[k][i] if values else None,
                                 coordinates_only=True)
            traces += moving[k]
        data += [marker(curve, dx, dy, row) for curve, (dx, dy) in zip(curves, decimals)]
        frames.append(go.Frame(name=name, data=data, traces=traces + marker_indices))
    fig.frames = frames
    total = max(int(name) for name in names) if total is None else int(total)
    # Room for two title lines above the legend; each further line (a run that stopped
    # early adds one) pushes the legend and the plots down, the title then set from the top.
    extra = max(0, title.count("<br>") - 1)
    top = 100 + 30 * extra
    title_layout = dict(text=title, x=0.5, xanchor="center")
    if extra:
        title_layout.update(y=1.0 - 15.0 / height, yref="container", yanchor="top")
    layout = {}
    for k in range(len(panels)):
        # A narrow scene (one of two) needs the camera further back to hold a squat model.
        layout["scene" if k == 0 else f"scene{k + 1}"] = scene_layout(
            points[k], 2.5 if len(panels) == 1 else 3.0)
    fig.update_layout(
        title=title_layout, template="plotly_white",
        height=height, margin=dict(l=10, r=20, t=top, b=130), uirevision="view",
        legend=dict(orientation="h", x=0.0, y=1.0, yanchor="bottom"),
        sliders=[slider(names, total, prefix=prefix)], updatemenus=[play_buttons()], **layout)
    step = scenes_end / len(panels)
    for k, panel in enumerate(panels):
        domain = [round(k * step, 4), round((k + 1) * step, 4)]
        fig.layout["scene" if k == 0 else f"scene{k + 1}"].domain.x = domain
        if panel.title and len(panels) > 1:   # below the legend, above the scene
            fig.layout["scene" if k == 0 else f"scene{k + 1}"].domain.y = [0.0, 0.93]
            fig.add_annotation(text=f"<b>{subscripted(panel.title)}</b>", x=sum(domain) / 2,
                               y=0.94, xref="paper", yref="paper", xanchor="center",
                               yanchor="bottom", showarrow=False, font=dict(size=14))
    if with_curve:
        fig.layout.xaxis.domain = [round(scenes_end + 0.14, 4), 1.0]
        fig.update_xaxes(title_text=x_label, row=1, col=len(panels) + 1)
        fig.update_yaxes(title_text=y_label, row=1, col=len(panels) + 1)
    return fig
