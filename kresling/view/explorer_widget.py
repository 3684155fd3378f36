"""The design explorer as a Jupyter widget that calls the C++ core live.

Unlike the offline page (:mod:`kresling.view.explorer`, a precomputed grid), every slider
move here recomputes the design: its geometry (:class:`kresling.Design`), the cell in both
stable states, and, on request, its K_B ratio (the thesis's 0.001 rad bending protocol, in
both states) and its snap-through force, so any point of the design space can be looked at,
not only grid points. Needs ``ipywidgets`` and ``anywidget`` (plotly's widget support).

>>> from kresling.view.explorer_widget import ExplorerWidget
>>> explorer = ExplorerWidget(n=8, lam=0.8, Lc=30.0, mechanics=False)  # doctest: +SKIP
>>> explorer.show()  # doctest: +SKIP
"""

from __future__ import annotations

import numpy as np
import plotly.graph_objects as go

from kresling.analyses import BendingTester, SnapThroughTester
from kresling.geometry import Design
from kresling.view.explorer import CELL_STATES, LINE_STYLES, cell_topology

__all__ = ["ExplorerWidget"]


class ExplorerWidget:
    """Sliders for n, lambda and Lc beside the cell in both states, recomputed live.

    Parameters
    ----------
    n : int, default 10
        Polygon sides (the dropdown offers the thesis's 4, 6, 8, 10).
    lam, Lc : float
        Angle ratio and contracted height [mm] to start at (the sliders span lambda in
        [0.7, 0.9] and Lc in [R/2, 2R], the thesis's design space).
    R : float, default 30
        Polygon radius [mm].
    mechanics : bool, default True
        Also compute the K_B ratio (0.001 rad protocol) and the snap force at every move
        (about 0.1 s a design); False shows geometry only.

    Attributes
    ----------
    figure : plotly.graph_objects.FigureWidget
        Two scenes: the extended and the contracted cell.
    controls : dict
        The ``n``, ``lam`` and ``Lc`` widgets.
    summary : ipywidgets.HTML
        The design's numbers (heights, facet angles, K_B ratio, snap force).
    """

    def __init__(self, n=10, lam=0.8, Lc=30.0, *, R=30.0, mechanics=True):
        import ipywidgets as widgets  # optional: only the widget needs it

        self.R = float(R)
        self.mechanics = bool(mechanics)
        self.controls = {
            "n": widgets.Dropdown(options=[4, 6, 8, 10], value=int(n), description="n"),
            "lam": widgets.FloatSlider(value=float(lam), min=0.7, max=0.9, step=0.005,
                                       description="λ", readout_format=".3f",
                                       continuous_update=False),
            "Lc": widgets.FloatSlider(value=float(Lc), min=self.R / 2, max=2 * self.R,
                                      step=0.5, description="Lc [mm]",
                                      continuous_update=False),
        }
        self.summary = widgets.HTML()
        self.figure = go.FigureWidget()
        self._build_traces(int(n))
        for control in self.controls.values():
            control.observe(self._on_change, names="value")
        self.update()

    # -- the figure ------------------------------------------------------------------------
    def _build_traces(self, n):
        """One mesh and one line trace per edge family in each scene, for an n-gon cell."""
        topology = cell_topology(n)
        self._topology = topology
        with self.figure.batch_update():
            self.figure.data = []
            for scene, (_, name) in zip(("scene", "scene2"), CELL_STATES):
                self.figure.add_trace(go.Mesh3d(
                    x=[], y=[], z=[], i=topology["i"], j=topology["j"], k=topology["k"],
                    color="#e9dcc0", flatshading=True, name=f"{name} cell", scene=scene,
                    hoverinfo="skip"))
                for family in topology["lines"]:
                    colour, width, dash = LINE_STYLES[family]
                    self.figure.add_trace(go.Scatter3d(
                        x=[], y=[], z=[], mode="lines", name=family, scene=scene,
                        line=dict(color=colour, width=width, dash=dash), showlegend=False))
            self.figure.update_layout(
                height=420, margin=dict(l=0, r=0, t=30, b=0),
                scene=dict(domain=dict(x=[0, 0.5]), aspectmode="data",
                           xaxis_title="x [mm]", yaxis_title="y [mm]", zaxis_title="z [mm]"),
                scene2=dict(domain=dict(x=[0.5, 1]), aspectmode="data",
                            xaxis_title="x [mm]", yaxis_title="y [mm]", zaxis_title="z [mm]"),
                annotations=[dict(text=name, x=x, y=1.0, xref="paper", yref="paper",
                                  showarrow=False) for (_, name), x in zip(CELL_STATES, (0.25, 0.75))])

    def design(self) -> Design:
        """The design the sliders show."""
        return Design(self.controls["n"].value, self.controls["lam"].value,
                      self.controls["Lc"].value, self.R)

    def cell_points(self, state: int) -> np.ndarray:
        """The cell's points (2n, 3) [mm] in ``state`` (1 extended, 0 contracted): bottom
        polygon, then top."""
        bottom, top = self.design().vertices(state)
        return np.vstack([bottom, top])

    def _on_change(self, change):
        if change["owner"] is self.controls["n"]:
            self._build_traces(int(change["new"]))
        self.update()

    def update(self):
        """Recompute the design (C++ core) and redraw the cells and the numbers."""
        design = self.design()
        traces = iter(self.figure.data)
        with self.figure.batch_update():
            for state, _ in CELL_STATES:
                points = self.cell_points(state)
                mesh = next(traces)
                mesh.x, mesh.y, mesh.z = points[:, 0], points[:, 1], points[:, 2]
                for family, order in self._topology["lines"].items():
                    line = next(traces)
                    xyz = np.full((len(order), 3), np.nan)
                    valid = np.asarray(order) >= 0
                    xyz[valid] = points[np.asarray(order)[valid]]
                    line.x, line.y, line.z = xyz[:, 0], xyz[:, 1], xyz[:, 2]
        self.summary.value = self._summary(design)

    def _summary(self, design: Design) -> str:
        rows = [("Le (extended height)", f"{design.Le:.3f} mm"),
                ("Lc (contracted height)", f"{design.Lc:.3f} mm"),
                ("Ψ<sub>ext</sub> / Ψ<sub>con</sub>", f"{np.degrees(design.psi_ext):.2f} / "
                                  f"{np.degrees(design.psi_con):.2f} deg")]
        if self.mechanics:
            ratio, snap = self.mechanics_of(design)
            rows += [("K<sub>B</sub> ratio (0.001 rad)", f"{ratio:.3f}"),
                     ("snap force", f"{snap:.3f} N")]
        cells = "".join(f"<tr><td>{k}</td><td style='text-align:right'>{v}</td></tr>"
                        for k, v in rows)
        return f"<table>{cells}</table>"

    def mechanics_of(self, design: Design):
        """K_B ratio (extended over contracted, 0.001 rad protocol) and snap force [N],
        computed now by the C++ core."""
        bending = BendingTester(design.n, protocol="0.001rad")
        extended, contracted = bending.run(design, 1), bending.run(design, 0)
        ratio = extended.stiffness / contracted.stiffness
        snap = SnapThroughTester(design.n).run(design).snap_force
        return float(ratio), float(snap)

    def show(self):
        """The widget: controls and numbers above the figure (display it in Jupyter)."""
        import ipywidgets as widgets

        return widgets.VBox([widgets.HBox(list(self.controls.values())), self.summary,
                             self.figure])

    def _ipython_display_(self):  # pragma: no cover - needs a notebook front end
        from IPython.display import display

        display(self.show())
