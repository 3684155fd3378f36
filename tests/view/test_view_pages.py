"""The pages built on kresling.view: the bending test in both states, the snap-through test,
any FOLD file, the design explorer; their paths against the C++ tests; the command line
(``kresling bend/snap --view``, ``kresling view``, ``kresling explore``); the report's
interactive views. No browser here (see test_view_pages_browser.py)."""

import json
import re
from html.parser import HTMLParser

import numpy as np
import pytest
from plotly.offline import get_plotlyjs

from cli_helpers import run_kresling
from kresling import Design
from kresling.analyses import bending_test, snap_through
from kresling.analyses.paths import bending_path, snap_through_path
from kresling.io import pattern_from_arrays, write_fold
from kresling.view import (check_writable, view_bending, view_fold, view_snap_through,
                           write_html)
from kresling.view.explorer import explorer_data, write_explorer
from kresling.view.surface import polyline_order
from view_cases import MIURA_NODES, MIURA_PANELS, page_figure

OPTIMUM = Design(10, 0.9, 15)


def by_trace(frame):
    """A frame's updates by the index of the trace they update."""
    return dict(zip(frame["traces"], frame["data"]))


def external_urls(page):
    """src and href attributes of the page's tags that point to the network."""
    found = []

    class Links(HTMLParser):
        def handle_starttag(self, tag, attrs):
            found.extend(value for name, value in attrs if name in ("src", "href") and value
                         and re.match(r"\s*(https?:)?//", value))

    Links().feed(page)
    return found


# -- the paths are the C++ tests' -----------------------------------------------------------

@pytest.mark.parametrize("protocol", ["5mm", "0.001rad"])
@pytest.mark.parametrize("state", [1, 0])
def test_the_bending_path_is_the_bending_test(protocol, state):
    bent = bending_path(OPTIMUM, state, protocol)
    reference = bending_test(OPTIMUM, state, protocol)
    assert bent.path.completed and bent.path.num_steps == len(reference.force)
    assert np.abs(bent.path.displacement[-1] - reference.final_displacement.ravel()).max() < 1e-9
    for name in ("deflection", "force", "angle", "moment"):
        assert np.allclose(getattr(bent, name), getattr(reference, name), rtol=1e-9,
                           atol=1e-12), name
    slope = bent.moment @ bent.angle / (bent.angle @ bent.angle)
    assert slope == pytest.approx(reference.stiffness, rel=1e-9)
    assert bent.module_length == pytest.approx(reference.module_length, rel=1e-12)


def test_the_snap_through_path_is_the_snap_through_test():
    design = Design(8, 0.8, 30)
    snap = snap_through_path(design, steps=60)
    reference = snap_through(design, steps=60)
    assert np.allclose(snap.travel, reference.displacement[1:], rtol=1e-9, atol=1e-12)
    assert np.allclose(snap.force, reference.force[1:], rtol=1e-9, atol=1e-9)
    assert np.allclose(snap.path.energy, reference.energy[1:], rtol=1e-9, atol=1e-9)


def test_bad_paths():
    with pytest.raises(ValueError, match="n = 7 is invalid: must be even"):
        bending_path(Design(7, 0.8, 30), 1)
    with pytest.raises(ValueError, match="protocol = '1cm' is invalid"):
        bending_path(OPTIMUM, 1, "1cm")
    with pytest.raises(ValueError, match="deflection = 40.0 is invalid"):
        bending_path(OPTIMUM, 1, deflection=40.0)


# -- the bending test in both states --------------------------------------------------------

@pytest.fixture(scope="module")
def bending():
    paths = [bending_path(OPTIMUM, state) for state in (1, 0)]
    return paths, view_bending(OPTIMUM, paths=paths, max_frames=36)


def test_the_bending_view_shows_both_states_on_one_slider(bending):
    (extended, contracted), fig = bending
    names = [frame.name for frame in fig.frames]
    assert len(names) == 36 and names[0] == "0" and names[-1] == "350"
    slider = fig.layout.sliders[0]
    assert slider.currentvalue.prefix == "increment " and slider.currentvalue.suffix == " / 350"
    assert {fig.layout.scene.domain.x[1], fig.layout.scene2.domain.x[0]} == {0.31}
    titles = [a.text for a in fig.layout.annotations]
    assert "<b>extended</b>" in titles and "<b>contracted</b>" in titles
    assert fig.layout.xaxis.title.text == "deflection angle δ [rad]"
    assert fig.layout.yaxis.title.text == "moment M [N·m]"
    # One legend entry per family: the second scene's traces share the first one's.
    shown = [t.name for t in fig.data if t.showlegend is not False and t.type != "scatter"]
    assert len(shown) == len(set(shown)) and "valley" in shown
    assert "16.80" in fig.layout.title.text         # the K_B ratio of the optimum


def test_every_frame_of_the_bending_view_is_both_paths(bending):
    (extended, contracted), fig = bending
    scenes = {}
    for index, trace in enumerate(fig.data):
        if trace.type == "mesh3d":
            scenes[trace.scene] = index
    markers = [i for i, t in enumerate(fig.data) if t.name == "increment shown"]
    assert len(markers) == 2
    for frame in fig.frames[::5] + fig.frames[-1:]:
        k = int(frame.name)
        updates = dict(zip(frame.traces, frame.data))
        for bent, scene in ((extended, "scene"), (contracted, "scene2")):
            expected = bent.specimen.model.nodes + (
                bent.path.displacement[k - 1].reshape(-1, 3) if k else 0.0)
            mesh = updates[scenes[scene]]
            assert np.abs(np.column_stack([mesh.x, mesh.y, mesh.z]) - expected).max() <= 1e-9
        for bent, marker in zip((extended, contracted), markers):   # 6 significant digits
            angle = bent.angle[k - 1] if k else 0.0
            moment = bent.moment[k - 1] if k else 0.0
            assert updates[marker].x[0] == pytest.approx(angle, abs=5e-6 * bent.angle.max())
            assert updates[marker].y[0] == pytest.approx(moment, abs=5e-6 * bent.moment.max())


def test_the_bending_view_of_the_page_holds_the_paths_to_1e_9_mm(bending, tmp_path):
    (extended, contracted), fig = bending
    page = write_html(fig, tmp_path / "bend.html", initial_frame=170)
    data, layout, frames = page_figure(page.read_text(encoding="utf-8"))
    frame = next(f for f in frames if f["name"] == [f["name"] for f in frames][17])
    k = int(frame["name"])
    meshes = [i for i, t in enumerate(data) if t["type"] == "mesh3d"]
    for bent, index in zip((extended, contracted), meshes):
        mesh = by_trace(frame)[index]
        expected = bent.specimen.model.nodes + bent.path.displacement[k - 1].reshape(-1, 3)
        assert np.abs(np.column_stack([mesh["x"], mesh["y"], mesh["z"]]) - expected).max() \
            <= 1e-9


# The symbols the views must set with subscripts, as plain text (any occurrence).
PLAIN_SYMBOLS = ("K_B", "K_ext", "K_con", "Psi_ext", "Psi_con")


def figure_texts(fig):
    """Every string of a figure (data, layout and frames): titles, names, hover templates,
    annotations, colour-bar titles."""
    found = []

    def walk(node):
        if isinstance(node, str):
            found.append(node)
        elif isinstance(node, dict):
            for value in node.values():
                walk(value)
        elif isinstance(node, (list, tuple)):
            for value in node:
                walk(value)

    walk(fig.to_dict())
    return found


def plain_symbols(texts):
    return [text for text in texts if any(symbol in text for symbol in PLAIN_SYMBOLS)]


def test_the_bending_view_sets_its_symbols_with_subscripts(bending):
    _, fig = bending
    texts = figure_texts(fig)
    assert plain_symbols(texts) == []
    assert "K<sub>B</sub> ratio 16.80" in fig.layout.title.text
    curves = [t for t in fig.data if t.type == "scatter" and t.mode == "lines"]
    assert [c.name.split(":")[0] for c in curves] == ["extended", "contracted"]
    assert all(": K<sub>B</sub> = " in c.name and c.name in c.hovertemplate for c in curves)


def test_the_snap_through_and_path_views_have_no_plain_symbols():
    design = Design(8, 0.8, 30)
    fig = view_snap_through(design, path=snap_through_path(design, steps=20), max_frames=5,
                            field="energy", title="K_B and Psi_ext / Psi_con")
    assert plain_symbols(figure_texts(fig)) == []
    assert fig.layout.title.text == "K<sub>B</sub> and Ψ<sub>ext</sub> / Ψ<sub>con</sub>"


# -- the snap-through test ------------------------------------------------------------------

def test_the_snap_through_view_follows_the_force_travel_curve():
    design = Design(8, 0.8, 30)
    snap = snap_through_path(design, steps=40)
    fig = view_snap_through(design, path=snap, max_frames=41)
    assert [f.name for f in fig.frames] == [str(k) for k in range(41)]
    curve = next(t for t in fig.data if t.name == "force")
    assert curve.x[0] == 0 and curve.y[0] == 0
    # 6 significant digits of the largest value.
    assert np.allclose(curve.x[1:], snap.travel, atol=5e-6 * snap.travel.max())
    assert fig.layout.xaxis.title.text == "travel d [mm]"
    assert np.allclose(curve.y[1:], snap.force, atol=5e-6 * np.abs(snap.force).max())
    assert "snap force 4.3" in fig.layout.title.text and "second stable state" in \
        fig.layout.title.text
    mesh_index = next(i for i, t in enumerate(fig.data) if t.type == "mesh3d")
    frame = fig.frames[23]
    mesh = dict(zip(frame.traces, frame.data))[mesh_index]
    expected = snap.specimen.model.nodes + snap.path.displacement[22].reshape(-1, 3)
    assert np.abs(np.column_stack([mesh.x, mesh.y, mesh.z]) - expected).max() <= 1e-9


# -- any FOLD file --------------------------------------------------------------------------

@pytest.fixture(scope="module")
def folding(tmp_path_factory):
    """A Miura-like sheet with three frames: its middle row rising."""
    pattern = pattern_from_arrays(MIURA_NODES, MIURA_PANELS)
    frames = []
    for k in range(1, 4):
        frame = pattern.vertices.copy()
        frame[3:6, 2] += 2.0 * k
        frames.append(frame)
    assignment = ["M" if (a + b) % 2 else "V" if a != b else "F" for a, b in pattern.edges]
    path = write_fold(tmp_path_factory.mktemp("fold") / "sheet.fold", pattern.vertices,
                      MIURA_PANELS, edges=pattern.edges, edges_assignment=pattern.edges_assignment,
                      frames=frames)
    return path, pattern, frames, assignment


def test_a_fold_file_with_frames_is_animated_from_its_key_frame(folding):
    path, pattern, frames, _ = folding
    fig = view_fold(path)
    assert [f.name for f in fig.frames] == ["0", "1", "2", "3"]
    assert fig.layout.sliders[0].currentvalue.prefix == "frame "
    assert fig.layout.sliders[0].currentvalue.suffix == " / 3"
    assert "sheet.fold" in fig.layout.title.text and "3 frames" in fig.layout.title.text
    for frame in fig.frames:
        k = int(frame.name)
        expected = pattern.vertices if k == 0 else frames[k - 1]
        mesh = frame.data[frame.traces.index(0)]
        assert np.abs(np.column_stack([mesh.x, mesh.y, mesh.z]) - expected).max() <= 1e-9
    # The boundary (B) and the inner (U) edges, each drawn once.
    lines = {t.name: t for t in fig.data if t.type == "scatter3d" and t.mode == "lines"}
    assert set(lines) == {"boundary", "unassigned"}
    segments = sum(sum(1 for a, b in zip(t.x[:-1], t.x[1:]) if a is not None and b is not None)
                   for t in lines.values())
    assert segments == len(pattern.edges)


def test_a_fold_file_without_frames_is_one_state(tmp_path):
    pattern = pattern_from_arrays(MIURA_NODES, MIURA_PANELS,
                                  edges=[[1, 4], [3, 4], [4, 5], [4, 7]],
                                  edges_assignment=["M", "V", "V", "C"])
    path = write_fold(tmp_path / "flat.fold", pattern)
    fig = view_fold(path)
    assert not fig.frames and not fig.layout.sliders
    names = {t.name for t in fig.data}
    assert {"mountain", "valley", "cut", "boundary", "panels"} <= names
    assert next(t for t in fig.data if t.name == "cut").line.color == "#000000"


def test_bad_fold_input(tmp_path):
    with pytest.raises(ValueError, match="pattern = int is invalid"):
        view_fold(3)
    (tmp_path / "bad.fold").write_text("{")
    with pytest.raises(ValueError, match="bad.fold:1:2: not valid JSON"):
        view_fold(tmp_path / "bad.fold")


# -- lines, paths ---------------------------------------------------------------------------

@pytest.mark.parametrize("seed", range(6))
def test_polylines_draw_every_edge_once_in_as_few_strokes_as_possible(seed):
    rng = np.random.default_rng(seed)
    pairs = {tuple(sorted(p)) for p in rng.integers(0, 12, size=(25, 2)).tolist() if p[0] != p[1]}
    edges = np.array(sorted(pairs))
    order = polyline_order(edges)
    drawn = [tuple(sorted(p)) for p in zip(order[:-1], order[1:]) if min(p) >= 0]
    assert sorted(drawn) == sorted(map(tuple, edges))        # every edge, exactly once
    # The fewest strokes: per connected group, half its odd-degree nodes (at least one).
    parent = list(range(12))

    def root(v):
        while parent[v] != v:
            v = parent[v]
        return v

    for a, b in edges:
        parent[root(a)] = root(b)
    degree = np.bincount(edges.ravel(), minlength=12)
    groups = {root(v) for v in edges.ravel()}
    fewest = sum(max(1, int(sum(degree[v] % 2 for v in range(12) if degree[v] and root(v) == g)
                            // 2)) for g in groups)
    assert (order == -1).sum() + 1 == fewest


def test_check_writable(tmp_path):
    (tmp_path / "file.txt").write_text("x")
    assert check_writable(tmp_path / "new" / "deeper" / "a.html") == \
        tmp_path / "new" / "deeper" / "a.html"
    assert not (tmp_path / "new").exists()               # nothing made
    assert check_writable(tmp_path / "a.html") and not (tmp_path / "a.html").exists()
    assert check_writable(tmp_path / "file.txt").read_text() == "x"      # left as it was
    with pytest.raises(ValueError, match=r"cannot write '.*file.txt/a.html': '.*file.txt' is "
                                         r"not a folder"):
        check_writable(tmp_path / "file.txt" / "a.html")
    with pytest.raises(ValueError, match=r"cannot write '.*': it is a folder"):
        check_writable(tmp_path)


# -- the command line -----------------------------------------------------------------------

def test_kresling_bend_view(tmp_path):
    result = run_kresling("bend", "--n", "10", "--lam", "0.9", "--Lc", "15", "--deflection-rad",
                          "0.001", "--json", "--view", "out/bend.html", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    ratio = json.loads(result.stdout)["ratio"]          # the 0.001 rad protocol: 21.69
    page = (tmp_path / "out" / "bend.html").read_text(encoding="utf-8")
    data, layout, frames = page_figure(page)
    assert [f["name"] for f in frames] == [str(k) for k in range(11)]
    assert sum(t["type"] == "mesh3d" for t in data) == 2
    assert page.count(get_plotlyjs()[:200]) == 1 and not external_urls(page)
    assert f"both stable states, K<sub>B</sub> ratio {ratio:.2f} (10 increments)" in \
        layout["title"]["text"]
    assert "PARTIAL" not in layout["title"]["text"]         # both runs completed


def test_kresling_snap_view(tmp_path):
    result = run_kresling("snap", "--n", "8", "--lam", "0.8", "--Lc", "30", "--steps", "30",
                          "--view", "snap.html", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    page = (tmp_path / "snap.html").read_text(encoding="utf-8")
    data, layout, frames = page_figure(page)
    assert len(frames) == 31 and layout["xaxis"]["title"]["text"] == "travel d [mm]"
    assert page.count(get_plotlyjs()[:200]) == 1 and not external_urls(page)
    assert layout["sliders"][0]["currentvalue"]["suffix"] == " / 30"
    assert "PARTIAL" not in layout["title"]["text"]


def test_kresling_view_of_a_fold_file(folding, tmp_path):
    path, *_ = folding
    result = run_kresling("view", str(path), "-o", "sheet.html", "--frame", "2", cwd=tmp_path)
    assert result.returncode == 0 and result.stderr == ""
    page = (tmp_path / "sheet.html").read_text(encoding="utf-8")
    # The page's title names the file's folder too (a simulation's path.fold is named by it).
    assert "var start = 2;" in page and f"<title>{path.parent.name}/sheet.fold: 9 vertices" in page
    assert page.count(get_plotlyjs()[:200]) == 1 and not external_urls(page)
    result = run_kresling("view", str(path), "-o", "far.html", "--frame", "12", cwd=tmp_path)
    assert result.returncode == 0
    assert "--frame 12 is out of range (sheet.fold has frames 0 to 3): opening frame 3" in \
        result.stderr
    assert "var start = 3;" in (tmp_path / "far.html").read_text(encoding="utf-8")


def test_kresling_view_of_a_file_without_frames(tmp_path):
    write_fold(tmp_path / "flat.fold", pattern_from_arrays(MIURA_NODES, MIURA_PANELS))
    result = run_kresling("view", "flat.fold", "--frame", "1", cwd=tmp_path)
    assert result.returncode == 0
    assert "--frame 1 is out of range (flat.fold has only frame 0 (no frames: one state)): " \
           "opening frame 0" in result.stderr
    data, layout, frames = page_figure((tmp_path / "flat.html").read_text(encoding="utf-8"))
    assert frames == [] and data[0]["type"] == "mesh3d"


@pytest.mark.parametrize("argv, guard", [
    (["bend", "--n", "10", "--lam", "0.9", "--Lc", "15", "--view"], "kresling.analyses.bending_stiffness"),
    (["snap", "--n", "8", "--lam", "0.8", "--Lc", "30", "--view"], "kresling.analyses.snap_through"),
    (["explore", "-o"], "kresling.view.explorer.explorer_data"),
    (["view", "missing.fold", "-o"], "kresling.io.read_pattern"),
])
def test_an_unwritable_page_fails_before_any_computation(argv, guard, tmp_path, monkeypatch,
                                                         capsys):
    from kresling.cli import main

    def computing(*args, **kwargs):
        raise AssertionError("computed before checking the output path")

    monkeypatch.setattr(guard, computing)
    (tmp_path / "file.txt").write_text("x")
    bad = tmp_path / "file.txt" / "page.html"
    assert main(argv + [str(bad)]) == 2
    error = capsys.readouterr().err
    assert error.startswith(f"kresling {argv[0]}: error: cannot write '{bad}'") and \
        "is not a folder" in error
    assert main(argv + [str(tmp_path)]) == 2
    assert "it is a folder" in capsys.readouterr().err


# -- the design explorer --------------------------------------------------------------------

@pytest.fixture(scope="module")
def explorer(tmp_path_factory):
    from kresling.fabrication import crease_pattern

    def flat(design):
        pattern = crease_pattern(design)
        return pattern.points, pattern.edges, pattern.edge_kinds

    data = explorer_data((4, 8), (4, 3), workers=1, flat_pattern=flat)
    page = write_explorer(data, tmp_path_factory.mktemp("explorer") / "explorer.html", n=8,
                          lam=0.8, Lc=30)
    return data, page.read_text(encoding="utf-8")


def test_the_explorer_maps_are_the_sweep(explorer):
    from kresling.sweeps import design_grid, sweep

    data, _ = explorer
    assert data["n"] == [4, 8] and data["Lc"] == [15.0, 30.0, 45.0, 60.0]
    assert data["lam"] == pytest.approx([0.7, 0.8, 0.9])
    table = sweep(design_grid((4, 8), (4, 3)), ["kb_ratio", "snap_force"], workers=1,
                  progress=False)
    for metric in ("kb_ratio", "snap_force"):
        for n in (4, 8):
            _, _, values = table.grid(metric, n)
            page_values = np.array(data["maps"][metric][str(n)], dtype=float)
            assert np.allclose(page_values, values, equal_nan=True, rtol=1e-12)
    assert data["sweep"]["designs"] == 24 and data["sweep"]["failed"] == 0


def test_the_explorer_cells_and_patterns_are_the_designs(explorer):
    from kresling.fabrication import crease_pattern

    data, _ = explorer
    for n in (4, 8):
        for c, Lc in enumerate(data["Lc"]):
            for a, lam in enumerate(data["lam"]):
                design, index = Design(n, lam, Lc), c * len(data["lam"]) + a
                for state in (0, 1):
                    shown = np.reshape(data["cells"][str(n)]["states"][str(state)][index], (2, n, 3))
                    assert np.abs(shown - design.vertices(state)).max() <= 0.5e-3 + 1e-12
                flat = np.reshape(data["patterns"][str(n)]["points"][index], (-1, 2))
                assert np.abs(flat - crease_pattern(design).points).max() <= 0.5e-3 + 1e-12
    # Valleys join B_i to T_(i+1), mountains B_i to T_i: the folded pattern's creases.
    lines = data["cells"]["8"]["lines"]
    valley = {tuple(sorted(p)) for p in zip(lines["valley"][:-1], lines["valley"][1:])
              if min(p) >= 0}
    assert valley == {tuple(sorted((i, 8 + (i + 1) % 8))) for i in range(8)}


def test_the_explorer_page_is_self_contained_and_opens_at_its_design(explorer):
    data, page = explorer
    assert page.count(get_plotlyjs()[:200]) == 1 and not external_urls(page)
    assert "<title>kresling: design explorer</title>" in page
    for slider in ("n-slider", "lam-slider", "Lc-slider"):
        assert f'id="{slider}"' in page
    assert 'id="n-slider" min="0" step="1" value="1"' in page          # n = 8
    assert 'id="lam-slider" min="0" step="1" value="1"' in page        # lambda = 0.8
    assert 'id="Lc-slider" min="0" step="1" value="1"' in page         # Lc = 30
    assert "a sweep of 24 designs (2 n × 4 Lc × 3 λ: Lc 15-60 mm every 15 mm" in page
    embedded = json.JSONDecoder().raw_decode(page, page.index("var D = ") + len("var D = "))[0]
    assert embedded == json.loads(json.dumps(data))
    assert "hashchange" in page and "lam=" in page


def test_the_explorer_sets_its_symbols_with_subscripts(explorer):
    from kresling.view.explorer import explorer_figure

    data, page = explorer
    fig = explorer_figure(data, 8, 0.8, 30)
    assert plain_symbols(figure_texts(fig)) == []
    heat = next(t for t in fig.data if t.name == "kb_ratio")
    label = "K<sub>B</sub> ratio K<sub>ext</sub> / K<sub>con</sub> (0.001 rad)"
    assert heat.colorbar.title.text == label and heat.hovertemplate.count(label) == 1
    assert f"<b>{label}</b>" in [a.text for a in fig.layout.annotations]
    # The page's own text: the note under the sliders and the line the script writes.
    note = page[page.index('<p class="note">'):]
    note = note[:note.index("</p>")]
    assert plain_symbols([note]) == [] and "K<sub>B</sub> ratio: the thesis" in note
    assert "' mm;  K<sub>B</sub> ratio ' + fmt(values[0], 2)" in page


# -- the report's interactive views ---------------------------------------------------------

def test_the_report_embeds_interactive_views_with_plotly_once(tmp_path):
    from kresling.report.build import build_report
    from kresling.report.chapters import Chapter

    chapters = (Chapter("views", "Part 1", "With views", "report_fakes", "with_views"),)
    report = build_report(tmp_path / "report", chapters=chapters)
    document = json.loads(report.json_path.read_text())
    views = document["sections"][0]["views"]
    assert [v["path"] for v in views] == ["views/first.json", "views/second.json"]
    page = report.html_path.read_text(encoding="utf-8")
    assert page.count(get_plotlyjs()[:200]) == 1 and not external_urls(page)
    assert page.index(get_plotlyjs()[:200]) < page.index("<body>")
    assert 'id="view-1"' in page and 'id="view-2"' in page and "Plotly.addFrames" in page
    assert "A path &lt;b&gt;animated&lt;/b&gt;." in page            # the caption escaped
    start = page.index("var fig = ", page.index('id="view-1"')) + len("var fig = ")
    figure = json.JSONDecoder().raw_decode(page, start)[0]     # "<\/" is JSON for "</"
    saved = json.loads((report.out_dir / views[0]["path"]).read_text())
    assert figure["data"] == saved["data"] and figure["frames"] == saved["frames"]
    assert "</b>" not in page[start:page.index("</script>", start)]   # cannot end the script
