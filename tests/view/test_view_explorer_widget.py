"""The design explorer widget: every slider move recomputes the design with the C++ core."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("ipywidgets", reason="the explorer widget needs ipywidgets")
pytest.importorskip("anywidget", reason="plotly's FigureWidget needs anywidget")

from kresling import Design  # noqa: E402
from kresling.analyses import BendingTester, SnapThroughTester  # noqa: E402
from kresling.view import ExplorerWidget  # noqa: E402


def mesh_points(widget, scene_index):
    meshes = [t for t in widget.figure.data if t.type == "mesh3d"]
    m = meshes[scene_index]
    return np.column_stack([m.x, m.y, m.z])


def test_cells_follow_the_sliders():
    w = ExplorerWidget(n=8, lam=0.8, Lc=30.0, mechanics=False)
    for lam, Lc in ((0.75, 20.0), (0.9, 45.5)):
        w.controls["lam"].value = lam
        w.controls["Lc"].value = Lc
        design = Design(8, lam, Lc)
        for scene, state in enumerate((1, 0)):
            bottom, top = design.vertices(state)
            np.testing.assert_allclose(mesh_points(w, scene), np.vstack([bottom, top]),
                                       atol=1e-12)
    assert "Le (extended height)" in w.summary.value
    assert f"{Design(8, 0.9, 45.5).Le:.3f} mm" in w.summary.value


def test_changing_n_rebuilds_the_cell():
    w = ExplorerWidget(n=8, lam=0.8, Lc=30.0, mechanics=False)
    w.controls["n"].value = 6
    assert mesh_points(w, 0).shape == (12, 3)
    assert len([t for t in w.figure.data if t.type == "mesh3d"][0].i) == 12  # 2n facets


def test_mechanics_are_computed_live():
    w = ExplorerWidget(n=4, lam=0.7, Lc=30.0, mechanics=True)
    design = Design(4, 0.7, 30.0)
    bending = BendingTester(4, protocol="0.001rad")
    ratio = bending.run(design, 1).stiffness / bending.run(design, 0).stiffness
    snap = SnapThroughTester(4).run(design).snap_force
    assert w.mechanics_of(design) == pytest.approx((ratio, snap), rel=1e-12)
    assert f"{ratio:.3f}" in w.summary.value and f"{snap:.3f} N" in w.summary.value
    # The symbols with subscripts (an ipywidgets.HTML), none in plain text.
    assert "<td>K<sub>B</sub> ratio (0.001 rad)</td>" in w.summary.value
    assert "<td>Ψ<sub>ext</sub> / Ψ<sub>con</sub></td>" in w.summary.value
    assert not any(s in w.summary.value for s in ("K_B", "Psi_", "Psi ext"))
