"""``kresling simulate``'s page (kresling.view.path_page) in headless Chromium: it unpacks
plotly and its frames, opens at ``#frame=K``, follows a change of the hash, plays when its
play button is clicked, logs no JavaScript error, and renders at 1200 x 900 and 1920 x 1080
(the 3D scene not blank, and taller on the taller window: the plot fills the window).

As in test_view_browser.py, a probe script added to a copy of the page writes what it sees
into the DOM, which ``--dump-dom`` prints after the virtual time budget.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

import numpy as np
import pytest

from test_view_pages_browser import chromium, needs_browser, render

ROOT = Path(__file__).resolve().parents[2]

PROBE = """<script>
window.addEventListener("load", function () {
  var seen = {};
  function look() {
    var gd = document.getElementById("kresling-view");
    var label = gd.querySelector(".slider-group .slider-label");
    return {active: gd._fullLayout.sliders[0].active,
            label: label ? label.textContent : null,
            marker: [gd.data[gd.data.length - 1].x[0], gd.data[gd.data.length - 1].y[0]],
            mesh_x: gd.data[0].x, title: document.title};
  }
  function write() {
    var out = document.createElement("pre");
    out.id = "view-check";
    out.textContent = JSON.stringify(seen);
    document.body.appendChild(out);
  }
  window.kreslingReady.then(function () {
    setTimeout(function () {
      seen.first = look();
      window.location.hash = "#frame=30";
      setTimeout(function () {
        seen.moved = look();
        var play = document.querySelector(".updatemenu-button");
        play.dispatchEvent(new MouseEvent("click", {bubbles: true}));
        setTimeout(function () { seen.played = look(); write(); }, 1500);
      }, 1500);
    }, 500);
  });
});
</script>"""


def probe(page, hash_, tmp_path):
    copy = page.with_name("_probe_" + page.name)
    copy.write_text(page.read_text(encoding="utf-8").replace("</body>", PROBE + "</body>"),
                    encoding="utf-8")
    result = chromium(["--dump-dom"], tmp_path, copy.as_uri() + hash_, profile="probe")
    start = result.stdout.find('<pre id="view-check">')
    assert start >= 0, f"no result in the DOM; chromium said: {result.stderr[-2000:]}"
    return json.loads(html.unescape(result.stdout[start:].split(">", 1)[1].split("</pre>")[0]))


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    from kresling.simulate import simulate

    out = tmp_path_factory.mktemp("miura")
    sim = simulate(ROOT / "examples" / "miura_bending" / "problem.toml", progress=False)
    return sim, sim.write(out)["view"]


@needs_browser
def test_the_page_opens_at_its_address_follows_the_hash_and_plays(run, tmp_path):
    sim, page = run
    seen = probe(page, "#frame=12", tmp_path)
    first, moved, played = seen["first"], seen["moved"], seen["played"]
    assert first["active"] == 11 and first["label"] == "increment 12 / 50"
    reaction = sim.path.constraint_force[:, 0]
    assert first["marker"][1] == pytest.approx(reaction[11], rel=1e-9)
    exact = sim.model.nodes[:, 0] + sim.path.displacement[11].reshape(-1, 3)[:, 0]
    # Positions on a 16-bit grid of the scene's box: within half a step of it.
    side = np.ptp(sim.model.nodes[:, 0]) * 1.2
    assert np.abs(np.array(first["mesh_x"]) - exact).max() <= side / 65535
    assert moved["active"] == 29 and moved["label"] == "increment 30 / 50"
    assert moved["marker"][1] == pytest.approx(reaction[29], rel=1e-9)
    # Playing (60 ms a frame) for 1.5 s of virtual time moves on by several increments.
    assert played["active"] > 32
    assert "miura_bending/problem.toml" in first["title"]


@needs_browser
@pytest.mark.parametrize("size", [(1200, 900), (1920, 1080)])
def test_the_page_renders_without_errors_at_common_sizes(run, tmp_path, size, monkeypatch):
    import test_view_pages_browser as pages

    monkeypatch.setattr(pages, "_WINDOW", size)
    errors, picture = render(run[1], "#frame=50", tmp_path, f"miura{size[0]}")
    assert errors == []
    assert picture.shape[:2] == (size[1], size[0])
    # The plot fills the window: its lowest non-white row (the slider's ticks) is in the
    # bottom quarter.
    ink = np.flatnonzero((picture < 200).any(axis=(1, 2)))
    assert ink.max() > 0.75 * size[1], ink.max()
    assert len(np.unique(picture.reshape(-1, 3), axis=0)) > 50, "a blank page"
