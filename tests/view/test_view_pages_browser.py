"""Every kind of interactive page in headless Chromium: a bending view (both states), a
snap-through view, a general FOLD view and the design explorer.

Each page is opened as a copy with a small script at the top of its head that logs
``console.error`` calls and unhandled promise rejections as console messages (uncaught
exceptions Chromium logs itself, as "Uncaught ..."); ``--enable-logging=stderr --v=0``
prints every console message on stderr, where the test reads them: no JavaScript errors.
``--screenshot`` renders the page (WebGL on Chromium's software renderer, SwiftShader): the
picture is not blank (not all pixels the same), and two different addresses (``#frame=K``,
or the explorer's ``#n=..&lam=..&Lc=..``) render different pictures. The pages name no
external URL in a ``src`` or ``href`` attribute. A negative control shows that the console
check does see an error.
"""

import html
import json
import re
import shutil
import subprocess
from html.parser import HTMLParser

import numpy as np
import pytest

from kresling import Design
from kresling.io import pattern_from_arrays, write_fold
from kresling.view import view_bending, view_fold, view_snap_through, write_html
from kresling.view.explorer import explorer_data, write_explorer
from view_cases import MIURA_NODES, MIURA_PANELS

CHROMIUM = next(filter(None, map(shutil.which, ("chromium", "chromium-browser",
                                                  "google-chrome"))), None)
needs_browser = pytest.mark.skipif(CHROMIUM is None,
                                   reason="no chromium (make test installs Debian's package)")

#: Put first in the page's head: console.error and unhandled rejections become console
#: messages that say what they are.
ERROR_PROBE = """<script>
(function () {
  var original = console.error;
  console.error = function () {
    console.log('[console.error] ' + Array.prototype.join.call(arguments, ' '));
    return original.apply(console, arguments);
  };
  window.addEventListener('unhandledrejection', function (event) {
    var reason = event.reason;
    console.log('[unhandledrejection] ' + (reason && reason.message ? reason.message : reason));
  });
})();
</script>"""

_CONSOLE = re.compile(r':CONSOLE[:(]\d+\)?\] "(.*)", source: ')
_WINDOW = (1280, 900)


def chromium(args, tmp_path, url, profile="chromium-profile"):
    return subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
         "--enable-unsafe-swiftshader", "--no-first-run", "--hide-scrollbars",
         f"--user-data-dir={tmp_path / profile}", "--enable-logging=stderr",
         "--v=0", f"--window-size={_WINDOW[0]},{_WINDOW[1]}", "--virtual-time-budget=8000",
         *args, url], capture_output=True, text=True, timeout=180)


def render(page, hash_, tmp_path, name):
    """Open ``page#hash_``; return (JavaScript errors on the console, the screenshot as an
    (H, W, 3) array)."""
    from PIL import Image

    probe = page.with_name(f"_probe_{name}_{page.name}")
    probe.write_text(page.read_text(encoding="utf-8").replace("<head>", "<head>" + ERROR_PROBE,
                                                              1), encoding="utf-8")
    shot = tmp_path / f"{name}.png"
    result = chromium([f"--screenshot={shot}"], tmp_path, probe.as_uri() + hash_,
                      profile=f"profile-{name}")
    assert shot.is_file(), f"no screenshot; chromium said: {result.stderr[-2000:]}"
    messages = _CONSOLE.findall(result.stderr)
    errors = [m for m in messages if m.startswith(("Uncaught", "[console.error]",
                                                   "[unhandledrejection]"))]
    return errors, np.asarray(Image.open(shot).convert("RGB"), dtype=np.int16)


def external_urls(page):
    found = []

    class Links(HTMLParser):
        def handle_starttag(self, tag, attrs):
            found.extend(value for name, value in attrs if name in ("src", "href") and value
                         and re.match(r"\s*(https?:)?//", value))

    Links().feed(page.read_text(encoding="utf-8"))
    return found


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    """One page of each kind and two addresses of each that must look different."""
    from kresling.fabrication import crease_pattern

    out = tmp_path_factory.mktemp("pages")
    optimum = Design(10, 0.9, 15)
    bending = write_html(view_bending(optimum, "0.001rad"), out / "bending.html")
    snap = write_html(view_snap_through(Design(8, 0.8, 30), steps=30), out / "snap.html")
    pattern = pattern_from_arrays(MIURA_NODES, MIURA_PANELS)
    frames = []
    for k in range(1, 4):
        frame = pattern.vertices.copy()
        frame[3:6, 2] += 3.0 * k
        frames.append(frame)
    fold = write_fold(out / "sheet.fold", pattern, frames=frames)
    fold_page = write_html(view_fold(fold), out / "fold.html")

    def flat(design):
        p = crease_pattern(design)
        return p.points, p.edges, p.edge_kinds

    explorer = write_explorer(explorer_data((4, 8), (4, 3), workers=1, flat_pattern=flat),
                              out / "explorer.html")
    return {"bending": (bending, "#frame=0", "#frame=10"),
            "snap-through": (snap, "#frame=0", "#frame=20"),
            "fold": (fold_page, "#frame=0", "#frame=3"),
            "explorer": (explorer, "#n=4&lam=0.7&Lc=60", "#n=8&lam=0.9&Lc=15")}


@needs_browser
@pytest.mark.parametrize("kind", ["bending", "snap-through", "fold", "explorer"])
def test_the_page_renders_without_errors_and_follows_its_address(pages, kind, tmp_path):
    from concurrent.futures import ThreadPoolExecutor

    page, first, second = pages[kind]
    assert external_urls(page) == []
    with ThreadPoolExecutor(2) as pool:     # the two addresses at once
        (errors, one), (more_errors, other) = pool.map(
            lambda args: render(page, args[0], tmp_path, args[1]),
            [(first, "first"), (second, "second")])
    assert errors == [] and more_errors == [], errors + more_errors
    assert len(np.unique(one.reshape(-1, 3), axis=0)) > 50, "a blank page"
    changed = (one != other).any(axis=2)
    assert changed.sum() > 2000, f"{first} and {second} look the same ({changed.sum()} pixels)"


EXPLORER_PROBE = """<script>
window.addEventListener("load", function () {
  setTimeout(function () {
    var seen = {n: document.getElementById("n-value").textContent,
                lam: document.getElementById("lam-value").textContent,
                Lc: document.getElementById("Lc-value").textContent,
                values: document.getElementById("explorer-values").innerHTML};
    window.kreslingExplorerShow(4, 0.9, 60).then(function () {
      var gd = document.getElementById("kresling-explorer");
      var marker = gd.data.filter(function (t) { return t.name === "kb_ratio design"; })[0];
      seen.moved = {hash: window.location.hash, n: document.getElementById("n-value").textContent,
                    marker: [marker.x[0], marker.y[0]]};
      var out = document.createElement("pre");
      out.id = "explorer-check";
      out.textContent = JSON.stringify(seen);
      document.body.appendChild(out);
    });
  }, 1500);
});
</script>"""


@needs_browser
def test_the_explorer_opens_at_the_nearest_grid_point_and_writes_its_address(pages, tmp_path):
    page = pages["explorer"][0]
    probe = page.with_name("_dom_probe.html")
    probe.write_text(page.read_text(encoding="utf-8").replace("</body>", EXPLORER_PROBE +
                                                              "</body>"), encoding="utf-8")
    result = chromium(["--dump-dom"], tmp_path, probe.as_uri() + "#n=7&lam=0.83&Lc=34")
    start = result.stdout.find('<pre id="explorer-check">')
    assert start >= 0, f"no result in the DOM; chromium said: {result.stderr[-2000:]}"
    seen = json.loads(html.unescape(result.stdout[start:].split(">", 1)[1].split("</pre>")[0]))
    # The grid: n 4, 8; Lc 15, 30, 45, 60; lambda 0.7, 0.8, 0.9.
    assert (seen["n"], seen["lam"], seen["Lc"]) == ("8", "0.800", "30.00 mm")
    assert "K<sub>B</sub> ratio" in seen["values"] and "snap force" in seen["values"]
    assert seen["moved"] == {"hash": "#n=4&lam=0.9&Lc=60", "n": "4", "marker": [60, 0.9]}


@needs_browser
def test_the_console_check_sees_an_error(tmp_path):
    page = tmp_path / "broken.html"
    page.write_text("<!DOCTYPE html><html><head></head><body><p>text</p><script>"
                    "console.error('told'); Promise.reject(new Error('rejected'));"
                    "notAFunction();</script></body></html>")
    errors, picture = render(page, "", tmp_path, "broken")
    assert any(e.startswith("Uncaught ReferenceError: notAFunction") for e in errors)
    assert "[console.error] told" in errors and "[unhandledrejection] rejected" in errors


@needs_browser
@pytest.mark.parametrize("size", [(1200, 900), (1920, 1080)])
@pytest.mark.parametrize("kind", ["bending", "fold"])
def test_the_page_fills_common_windows(pages, kind, size, tmp_path, monkeypatch):
    # The plot's height follows the window (no fixed 650 or 700 px): its lowest ink (the
    # slider's ticks) lies in the window's bottom third at both sizes. (Headless Chromium's
    # viewport is some 140 px shorter than its window.)
    monkeypatch.setitem(globals(), "_WINDOW", size)
    page, first, _ = pages[kind]
    errors, picture = render(page, first, tmp_path, f"{kind}{size[0]}")
    assert errors == []
    ink = np.flatnonzero((picture < 200).any(axis=(1, 2)))
    assert ink.max() > 0.67 * size[1], (size, ink.max())
