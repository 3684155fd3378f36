"""Interactive views (kresling.view): frames, coordinates, the curve's marker, fields and the
offline HTML page. No browser here (see test_view_browser.py)."""

import doctest
import json
import re

import numpy as np
import plotly.graph_objects as go
import pytest
from plotly.offline import get_plotlyjs

from kresling.view import FAMILY_STYLES, element_energy, view_model, view_path, write_html
from kresling.view.animation import select_rows
from kresling.view.fields import hinge_angle_change
from kresling.view.surface import orient_triangles, triangles_from_hinges
from view_cases import kresling_bending, miura_sheet, page_figure

ROUNDING = 0.5e-10 + 1e-12  # coordinates are rounded to 1e-10 mm


@pytest.fixture(scope="module")
def miura():
    return miura_sheet()


@pytest.fixture(scope="module")
def kresling():
    return kresling_bending()


def trace(fig_or_frame, name, figure=None):
    """The trace called ``name`` (in a frame: the update of the figure's trace so named)."""
    if isinstance(fig_or_frame, go.Frame):
        names = [figure.data[i].name for i in fig_or_frame.traces]
        return fig_or_frame.data[names.index(name)]
    return next(t for t in fig_or_frame.data if t.name == name)


def segments(line):
    """(E, 2, 3) end points of the segments of a line trace: consecutive points of its
    polylines (separated by gaps)."""
    xyz = np.column_stack([np.array(line.x, dtype=float), np.array(line.y, dtype=float),
                           np.array(line.z, dtype=float)])
    both = ~np.isnan(xyz[:-1]).any(axis=1) & ~np.isnan(xyz[1:]).any(axis=1)
    return np.stack([xyz[:-1][both], xyz[1:][both]], axis=1)


def edge_nodes(ends, points):
    """Node pairs (sorted) of segments ``ends`` (E, 2, 3), found by position."""
    d = np.linalg.norm(ends[:, :, None, :] - points[None, None, :, :], axis=3)
    nodes = d.argmin(axis=2)
    assert d.min(axis=2).max() <= 1e-3
    return np.sort(nodes, axis=1)


# -- frames, coordinates, marker ---------------------------------------------------------

def test_one_frame_per_increment_and_the_slider(miura):
    model, topo, family, path = miura
    fig = view_path(model, path, triangles=topo.triangles, hinge_family=family)
    assert [f.name for f in fig.frames] == [str(k) for k in range(1, path.num_steps + 1)]
    slider = fig.layout.sliders[0]
    assert [s.label for s in slider.steps] == [f.name for f in fig.frames]
    assert [list(s.args[0]) for s in slider.steps] == [[f.name] for f in fig.frames]
    assert slider.currentvalue.prefix == "increment " and slider.currentvalue.suffix == " / 10"
    labels = [b.label for b in fig.layout.updatemenus[0].buttons]
    assert any("play" in b for b in labels) and any("pause" in b for b in labels)
    assert fig.layout.title.text


@pytest.mark.parametrize("stride, max_frames, rows", [
    (None, 4, [0, 3, 6, 9]), (3, 200, [0, 3, 6, 9]), (4, 200, [0, 4, 8, 9]),
    (None, 200, list(range(10))), (1, 3, [0, 4, 9])])
def test_frames_are_subsampled(miura, stride, max_frames, rows):
    model, _, _, path = miura
    assert select_rows(10, stride, max_frames).tolist() == rows
    fig = view_path(model, path, frame_stride=stride, max_frames=max_frames)
    assert [f.name for f in fig.frames] == [str(r + 1) for r in rows]


def test_mesh_and_creases_follow_the_path(miura):
    model, topo, family, path = miura
    fig = view_path(model, path, triangles=topo.triangles, hinge_family=family)
    mesh = fig.data[0]
    assert mesh.type == "mesh3d" and mesh.flatshading
    assert sorted(map(tuple, np.sort(np.column_stack([mesh.i, mesh.j, mesh.k]), axis=1))) == \
        sorted(map(tuple, topo.triangles))
    for frame in fig.frames:
        row = int(frame.name) - 1
        points = model.nodes + path.displacement[row].reshape(-1, 3)
        update = frame.data[frame.traces.index(0)]
        xyz = np.column_stack([update.x, update.y, update.z])
        assert np.abs(xyz - points).max() <= ROUNDING
        # Every crease family's lines end at the displaced nodes too.
        for name in ("mountain", "valley", "bend", "boundary"):
            ends = segments(trace(frame, name, fig))
            edges = edge_nodes(ends, points)
            assert len({tuple(e) for e in edges.tolist()}) == len(edges)   # each edge once
            assert np.abs(np.round(ends, 10) - ends).max() < 1e-12  # rounded to 1e-10 mm


def test_the_marker_follows_the_frame(miura):
    model, _, _, path = miura
    x, y = np.linspace(0, 1, path.num_steps) ** 2, np.cumsum(np.ones(path.num_steps))
    fig = view_path(model, path, curve=(x, y, "my x [mm]", "my y [N]"), max_frames=4)
    curve = trace(fig, "path")   # to 6 significant digits of the largest value
    assert np.abs(np.array(curve.x) - x).max() <= 5e-6 * np.abs(x).max()
    assert np.abs(np.array(curve.y) - y).max() <= 5e-6 * np.abs(y).max()
    assert fig.layout.xaxis.title.text == "my x [mm]" and fig.layout.yaxis.title.text == "my y [N]"
    for frame in fig.frames:
        row = int(frame.name) - 1
        marker = trace(frame, "increment shown", fig)
        assert (marker.x[0], marker.y[0]) == (curve.x[row], curve.y[row])
        assert marker.x[0] == pytest.approx(x[row], abs=5e-6)
        assert marker.y[0] == pytest.approx(y[row], abs=5e-5)


def test_default_curve_is_the_load_factor_against_the_dof_that_moves_most(miura):
    model, _, _, path = miura
    fig = view_path(model, path)
    dof = int(np.argmax(np.abs(path.displacement).max(axis=0)))
    assert dof == 3 * 8 + 2  # the pulled corner rises most
    assert fig.layout.xaxis.title.text == "uz of node 8 [mm]"
    curve = trace(fig, "path")
    x = path.displacement[:, dof]   # to 6 significant digits of the largest
    assert np.abs(np.array(curve.x) - x).max() <= 5e-6 * np.abs(x).max()
    assert np.allclose(curve.y, path.load_factor)
    last = fig.frames[-1]
    assert trace(last, "increment shown", fig).y[0] == pytest.approx(1.0)


def test_scene_has_equal_scales_and_labelled_axes(miura):
    model, _, _, path = miura
    fig = view_path(model, path)
    scene = fig.layout.scene
    assert scene.aspectmode == "data"
    assert [scene.xaxis.title.text, scene.yaxis.title.text, scene.zaxis.title.text] == \
        ["x [mm]", "y [mm]", "z [mm]"]
    # The axes hold every frame, so the view does not rescale while playing.
    everything = model.nodes[None] + path.displacement.reshape(path.num_steps, -1, 3)
    for k, axis in enumerate((scene.xaxis, scene.yaxis, scene.zaxis)):
        assert axis.range[0] <= everything[..., k].min()
        assert axis.range[1] >= everything[..., k].max()


# -- families ----------------------------------------------------------------------------

def test_creases_are_coloured_by_family(miura):
    model, topo, family, _ = miura
    fig = view_model(model, triangles=topo.triangles, hinge_family=family)
    for name in ("mountain", "valley", "bend", "boundary"):
        line = trace(fig, name).line
        assert (line.color, line.width, line.dash) == FAMILY_STYLES[name]
    assert FAMILY_STYLES["mountain"][0] == "#d62728" and FAMILY_STYLES["valley"][0] == "#1f77b4"
    # The boundary is the edges of one triangle: 8 on the 2 x 2 sheet, one closed polyline.
    assert len(segments(trace(fig, "boundary"))) == 8 and len(trace(fig, "boundary").x) == 9
    counts = {name: len(segments(trace(fig, name))) for name in ("mountain", "valley", "bend")}
    assert counts == {"mountain": int((family == "mountain").sum()),
                      "valley": int((family == "valley").sum()),
                      "bend": int((family == "bend").sum())}


def test_unnamed_families_get_colours_and_default_is_unassigned(miura):
    model, _, _, _ = miura
    fig = view_model(model, hinge_family=["crease A"] * 4 + ["crease B"] * 4)
    a, b = trace(fig, "crease A"), trace(fig, "crease B")
    assert a.line.color != b.line.color
    assert trace(view_model(model), "unassigned").line.color == FAMILY_STYLES["unassigned"][0]


def test_triangles_recovered_from_hinges_and_oriented(miura):
    model, topo, _, _ = miura
    recovered = triangles_from_hinges(model.hinges)
    assert sorted(map(tuple, recovered)) == sorted(map(tuple, np.sort(topo.triangles, axis=1)))
    oriented = orient_triangles(recovered, model.nodes)
    directed = [(t[k], t[(k + 1) % 3]) for t in oriented.tolist() for k in range(3)]
    assert len(set(directed)) == len(directed)        # no shared edge run the same way twice
    x = model.nodes
    normal = np.cross(x[oriented[:, 1]] - x[oriented[:, 0]], x[oriented[:, 2]] - x[oriented[:, 0]])
    assert normal[:, 2].sum() > 0                      # the sheet faces up
    mesh = view_model(model).data[0]
    assert np.column_stack([mesh.i, mesh.j, mesh.k]).tolist() == oriented.tolist()


# -- fields ------------------------------------------------------------------------------

def test_bar_strain_colours_are_the_element_states(miura):
    model, topo, _, path = miura
    fig = view_path(model, path, triangles=topo.triangles, field="bar_strain")
    line = trace(fig, "bar strain [-]").line
    assert line.colorbar.title.text == "bar strain [-]" and line.cmin == -line.cmax
    strains = [model.element_state(u)["bar_strain"] for u in path.displacement]
    largest = np.abs(strains).max()
    assert line.cmax == pytest.approx(largest, rel=1e-5) and line.cmax >= largest
    by_edge = {tuple(sorted(b)): k for k, b in enumerate(model.bars.tolist())}
    for frame in fig.frames:
        row = int(frame.name) - 1
        update = trace(frame, "bar strain [-]", fig)
        points = model.nodes + path.displacement[row].reshape(-1, 3)
        edges = edge_nodes(segments(update), points)
        assert len(edges) == len(model.bars)
        colours = np.array(update.line.color, dtype=float)[0::3]
        expected = strains[row][[by_edge[tuple(e)] for e in edges.tolist()]]
        assert np.abs(colours - expected).max() <= 5e-6 * largest   # 6 significant digits


def test_hinge_angle_change_colours_are_the_element_states(miura):
    model, _, _, path = miura
    fig = view_path(model, path, field="hinge_angle_change")
    assert trace(fig, "hinge angle change [deg]").line.colorbar.title.text == \
        "hinge angle change [deg]"
    by_axis = {tuple(sorted(h[:2])): k for k, h in enumerate(model.hinges.tolist())}
    for frame in fig.frames[::3]:
        row = int(frame.name) - 1
        update = trace(frame, "hinge angle change [deg]", fig)
        points = model.nodes + path.displacement[row].reshape(-1, 3)
        edges = edge_nodes(segments(update), points)
        theta = model.element_state(path.displacement[row])["hinge_angle"]
        change = np.degrees(theta - model.hinge_rest_angle)
        expected = change[[by_axis[tuple(e)] for e in edges.tolist()]]
        assert np.allclose(update.line.color[0::3], expected, atol=1e-4)
    # Wrapped to (-180, 180].
    assert hinge_angle_change(model, model.hinge_rest_angle + 2 * np.pi - 0.1) == \
        pytest.approx(np.full(len(model.hinges), np.degrees(-0.1)))


def test_energy_colours_add_up_to_the_stored_energy(miura):
    model, _, _, path = miura
    fig = view_path(model, path, field="energy")
    line = trace(fig, "stored energy [N·mm]").line
    assert line.cmin == 0 and "[N·mm]" in line.colorbar.title.text
    for frame in fig.frames:
        row = int(frame.name) - 1
        colours = np.array(trace(frame, "stored energy [N·mm]", fig).line.color, float)[0::3]
        # Each edge's value to 6 significant digits of the largest.
        assert colours.sum() == pytest.approx(path.energy[row],
                                              abs=5e-6 * line.cmax * len(colours))
        energy = element_energy(model, path.displacement[row])
        assert energy["bars"].sum() == pytest.approx(path.energy_bars[row], rel=1e-12)
        assert energy["hinges"].sum() == pytest.approx(path.energy_hinges[row], rel=1e-12)


def test_view_model_of_one_state(miura):
    model, topo, family, path = miura
    u = path.displacement[-1]
    fig = view_model(model, u.reshape(-1, 3), triangles=topo.triangles, hinge_family=family,
                     field="bar_strain", title="the last increment")
    assert not fig.frames and fig.layout.title.text == "the last increment"
    mesh = fig.data[0]
    points = model.nodes + u.reshape(-1, 3)
    assert np.abs(np.column_stack([mesh.x, mesh.y, mesh.z]) - points).max() <= ROUNDING
    assert fig.layout.scene.aspectmode == "data"
    assert "reference state" in view_model(model).layout.title.text


# -- HTML --------------------------------------------------------------------------------

def test_html_is_self_contained_and_offline(miura, tmp_path):
    model, topo, family, path = miura
    fig = view_path(model, path, triangles=topo.triangles, hinge_family=family)
    out = write_html(fig, tmp_path / "sub" / "view.html")
    assert out == tmp_path / "sub" / "view.html"
    page = out.read_text(encoding="utf-8")
    assert page.count(get_plotlyjs()[:200]) == 1           # plotly.js inlined, once
    assert not re.search(r"<script[^>]+src=[\"']?(https?:)?//", page)
    assert "<script src=\"http" not in page and not re.search(r"<link[^>]+href=\"?http", page)
    assert "location.hash" in page and "frame=" in page and "hashchange" in page
    assert "Plotly.animate" in page and "sliders[0].active" in page
    assert "<title>Equilibrium path" in page


def test_html_opens_at_the_initial_frame(miura, tmp_path):
    model, _, _, path = miura
    fig = view_path(model, path, max_frames=4)                    # frames 1, 4, 7, 10
    write_html(fig, tmp_path / "view.html", initial_frame=6)      # the nearest: 7
    page = (tmp_path / "view.html").read_text()
    assert re.search(r"var start = 7;", page)
    assert fig.layout.sliders[0].active == 0                      # the figure is unchanged
    # The page's figure starts at increment 7: its mesh and slider.
    data = re.search(r"Plotly\.newPlot\(\s*\"kresling-view\",\s*(\[.*?\]),\s*\{", page, re.S)
    traces = json.loads(data.group(1))
    points = model.nodes + path.displacement[6].reshape(-1, 3)
    mesh = np.column_stack([traces[0]["x"], traces[0]["y"], traces[0]["z"]])
    assert np.abs(mesh - points).max() <= ROUNDING
    assert '"active":2' in page.replace(" ", "")


def test_coordinates_are_rounded_in_the_page(miura, tmp_path):
    model, _, _, path = miura
    page = write_html(view_path(model, path), tmp_path / "v.html").read_text()
    figure_json = page[page.index("Plotly.newPlot"):]
    z_lists = re.findall(r'"z":\[([^\]]*)\]', figure_json)   # every 3D trace and its frames
    assert len(z_lists) >= len(path.load_factor) * 3
    decimals = [len(d) for z in z_lists for d in re.findall(r"\.(\d+)", z)]
    assert decimals and max(decimals) <= 10
    assert '"bdata"' not in figure_json    # plain numbers, not base64 float64 arrays


@pytest.fixture(scope="module")
def kresling_page(tmp_path_factory):
    """A 350-increment bending test as a page of 200 frames, and its figure's JSON."""
    specimen, path = kresling_bending(steps=350)
    page = write_html(view_path(specimen, path, max_frames=200),
                      tmp_path_factory.mktemp("page") / "view.html")
    return specimen, path, page_figure(page.read_text(encoding="utf-8"))


@pytest.mark.parametrize("increment", [1, 173, 350])
def test_the_page_holds_the_path_to_1e_9_mm(kresling_page, increment):
    """The frames in the page's JSON are the path: every node of the mesh, and every point of
    the crease lines, at ``model.nodes + path.displacement[K - 1]`` to 1e-9 mm."""
    specimen, path, (data, layout, frames) = kresling_page
    names = [frame["name"] for frame in frames]
    assert str(increment) in names and len(names) == 200
    frame = frames[names.index(str(increment))]
    expected = specimen.model.nodes + path.displacement[increment - 1].reshape(-1, 3)
    by_trace = dict(zip(frame["traces"], frame["data"]))
    mesh = by_trace[0]
    xyz = np.column_stack([mesh["x"], mesh["y"], mesh["z"]])
    assert xyz.shape == expected.shape
    assert np.abs(xyz - expected).max() <= 1e-9
    lines = [i for i, trace in enumerate(data) if trace["type"] == "scatter3d"
             and trace.get("mode") == "lines"]
    assert {data[i]["name"] for i in lines} >= {"valley", "mountain", "polygon_edge"}
    for i in lines:
        points = np.array([p for p in zip(by_trace[i]["x"], by_trace[i]["y"], by_trace[i]["z"])
                           if None not in p], dtype=float)
        distance = np.linalg.norm(points[:, None, :] - expected[None, :, :], axis=2).min(axis=1)
        assert distance.max() <= 1e-9, data[i]["name"]
    # The figure's initial data is increment 1, as exactly.
    first = np.column_stack([data[0]["x"], data[0]["y"], data[0]["z"]])
    assert np.abs(first - specimen.model.nodes - path.displacement[0].reshape(-1, 3)).max() <= 1e-9


# -- a Kresling specimen -----------------------------------------------------------------

def test_kresling_bending_test_view(kresling, tmp_path):
    from kresling.analyses import bending_test
    from kresling.analyses.specimen_views import specimen_faces

    specimen, path = kresling
    # The path is the thesis's bending test (same supports and drive).
    reference = bending_test(specimen.design, "extended", deflection=5.0, steps=40)
    assert np.abs(path.displacement[-1] - reference.final_displacement.ravel()).max() < 1e-6
    force = path.constraint_force.sum(axis=1)
    assert np.allclose(force, reference.force, rtol=1e-6, atol=1e-9)
    n = specimen.design.n
    centre_y = 3 * specimen.centre(2) + 1
    fig = view_path(specimen, path, field=None, max_frames=10,
                    curve=(-path.displacement[:, centre_y], force, "deflection [mm]", "force [N]"))
    assert len(fig.frames) == 10 and fig.frames[-1].name == "40"
    names = [t.name for t in fig.data]
    assert {"valley", "mountain", "polygon_edge", "polygon_spoke"} <= set(names)
    mesh = fig.data[0]
    assert len(mesh.i) == len(specimen_faces(specimen)) == 2 * n * 4 + n * 5
    frame = fig.frames[-1]
    points = specimen.model.nodes + path.displacement[-1].reshape(-1, 3)
    update = frame.data[frame.traces.index(0)]
    assert np.abs(np.column_stack([update.x, update.y, update.z]) - points).max() <= ROUNDING
    marker = trace(frame, "increment shown", fig)
    assert (marker.x[0], marker.y[0]) == pytest.approx((5.0, force[-1]), rel=1e-5)
    # With a field, and the model alone (triangles recovered from its hinges).
    energy = view_path(specimen.model, path, field="energy", max_frames=5)
    colours = np.array(trace(energy.frames[-1], "stored energy [N·mm]", energy).line.color)[0::3]
    assert colours.sum() == pytest.approx(path.energy[-1], rel=1e-5)
    assert len(energy.data[0].i) == len(specimen_faces(specimen))


def test_a_200_frame_kresling_page_stays_small(tmp_path):
    specimen, path = kresling_bending(steps=350)
    fig = view_path(specimen, path, field="bar_strain")
    assert len(fig.frames) == 200
    size = write_html(fig, tmp_path / "view.html").stat().st_size
    assert size < len(get_plotlyjs()) + 4_000_000, f"{size / 1e6:.1f} MB"


# -- bad input ---------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, message", [
    (dict(field="strain"), r"field = 'strain' is invalid: must be None or one of"),
    (dict(hinge_family=["mountain"]), r"hinge_family has 1 entries: must have one per hinge \(8\)"),
    (dict(triangles=[[0, 1, 99]]), r"triangles\[0\] = \[0, 1, 99\]: node index out of range"),
    (dict(triangles=[[0, 1]]), r"triangles has shape \(1, 2\)"),
    (dict(curve=([1, 2], [1, 2], "x", "y")), r"curve has x of length 2 and y of length 2"),
    (dict(curve=[1, 2]), r"curve is invalid"),
    (dict(frame_stride=0), r"frame_stride = 0 is invalid"),
    (dict(max_frames=0), r"max_frames = 0 is invalid"),
])
def test_bad_input(miura, kwargs, message):
    model, _, _, path = miura
    with pytest.raises(ValueError, match=message):
        view_path(model, path, **kwargs)


def test_bad_states(miura, kresling):
    model, _, _, path = miura
    with pytest.raises(ValueError, match=r"u has 3 entries: must have one per DOF \(27\)"):
        view_model(model, [1.0, 2.0, 3.0])
    with pytest.raises(ValueError,
                       match=r"path.displacement has shape \(40, 135\): must be \(S, 27\)"):
        view_path(model, kresling[1])
    with pytest.raises(ValueError, match=r"model = str is invalid"):
        view_model("model")


def test_docstring_examples():
    import kresling.view

    assert doctest.testmod(kresling.view).failed == 0


def test_an_object_carrying_a_model_and_its_families(miura):
    from types import SimpleNamespace

    model, topo, family, path = miura
    carrier = SimpleNamespace(model=model, hinge_family=tuple(family),
                              elements=SimpleNamespace(triangles=topo.triangles))
    fig = view_path(carrier, path, max_frames=2)
    assert {"mountain", "valley", "bend", "boundary"} <= {t.name for t in fig.data}
    mesh = fig.data[0]
    assert sorted(map(tuple, np.sort(np.column_stack([mesh.i, mesh.j, mesh.k]), axis=1))) == \
        sorted(map(tuple, topo.triangles))
    # A hinge field leaves the family lines out but keeps the boundary.
    names = [t.name for t in view_model(carrier, field="hinge_angle_change").data]
    assert names == ["panels", "boundary", "hinge angle change [deg]", "extent"]
