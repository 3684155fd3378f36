"""The offline view page in headless Chromium: it opens at ``#frame=K`` and follows later
changes of the hash.

As in test_report_browser.py, a small script is added to a copy of the page; once the page
has loaded and the figure has settled it writes, into the DOM, the slider's active step, the
frame the slider names ("increment K / S" as drawn) and the curve marker's data; ``--dump-dom``
prints the DOM after the load event and the virtual time budget, so the result is read back
as text. WebGL runs on Chromium's software renderer (SwiftShader).
"""

import html
import json
import shutil
import subprocess

import pytest

from kresling.view import view_path, write_html
from view_cases import miura_sheet

CHROMIUM = next(filter(None, map(shutil.which, ("chromium", "chromium-browser",
                                                  "google-chrome"))), None)
needs_browser = pytest.mark.skipif(CHROMIUM is None,
                                   reason="no chromium (make test installs Debian's package)")

PROBE = """<script>
window.addEventListener("load", function () {
  function report() {
    var gd = document.getElementById("kresling-view");
    var marker = gd.data[gd.data.length - 1];
    var label = gd.querySelector(".slider-group .slider-label");
    var out = document.createElement("pre");
    out.id = "view-check";
    out.textContent = JSON.stringify({
      active: gd._fullLayout.sliders[0].active,
      step: gd._fullLayout.sliders[0].steps[gd._fullLayout.sliders[0].active].label,
      label: label ? label.textContent : null,
      marker: [marker.x[0], marker.y[0]],
      mesh_x: gd.data[0].x});
    document.body.appendChild(out);
  }
  setTimeout(function () {
    if (window.__NEXT_HASH__) { window.location.hash = window.__NEXT_HASH__; }
    setTimeout(report, 2000);
  }, 2000);
});
</script>"""


def view_in_browser(page, hash_, tmp_path, next_hash=None):
    """Open ``page#hash_`` in headless Chromium (then change the hash to ``next_hash``);
    return what the probe saw."""
    probe = page.with_name(f"_probe_{page.name}")
    script = PROBE if next_hash is None else \
        PROBE.replace("<script>", f"<script>window.__NEXT_HASH__ = {json.dumps(next_hash)};")
    probe.write_text(page.read_text(encoding="utf-8").replace("</body>", script + "</body>"),
                     encoding="utf-8")
    result = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--no-first-run",
         f"--user-data-dir={tmp_path / 'chromium-profile'}", "--virtual-time-budget=20000",
         "--dump-dom", probe.as_uri() + hash_], capture_output=True, text=True, timeout=180)
    start = result.stdout.find('<pre id="view-check">')
    assert start >= 0, f"no result in the DOM; chromium said: {result.stderr[-2000:]}"
    text = result.stdout[start:].split(">", 1)[1].split("</pre>", 1)[0]
    return json.loads(html.unescape(text))


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    model, topo, family, path = miura_sheet()
    fig = view_path(model, path, triangles=topo.triangles, hinge_family=family,
                    field="bar_strain")
    out = write_html(fig, tmp_path_factory.mktemp("view") / "view.html")
    return out, model, path


@needs_browser
def test_the_page_opens_at_the_increment_in_its_address(page, tmp_path):
    out, model, path = page
    seen = view_in_browser(out, "#frame=3", tmp_path)
    assert seen["active"] == 2 and seen["step"] == "3"
    assert seen["label"] == "increment 3 / 10"
    assert seen["marker"][1] == pytest.approx(path.load_factor[2])
    expected = model.nodes[:, 0] + path.displacement[2].reshape(-1, 3)[:, 0]
    assert seen["mesh_x"] == pytest.approx(expected.tolist(), abs=0.5e-10 + 1e-12)


@needs_browser
def test_the_page_follows_a_change_of_the_hash(page, tmp_path):
    out, _, path = page
    seen = view_in_browser(out, "#frame=3", tmp_path, next_hash="#frame=8")
    assert seen["active"] == 7 and seen["label"] == "increment 8 / 10"
    assert seen["marker"][1] == pytest.approx(path.load_factor[7])


@needs_browser
def test_without_a_hash_the_page_opens_at_the_first_increment(page, tmp_path):
    out, _, path = page
    seen = view_in_browser(out, "", tmp_path)
    assert seen["active"] == 0 and seen["label"] == "increment 1 / 10"
    assert seen["marker"][1] == pytest.approx(path.load_factor[0])
