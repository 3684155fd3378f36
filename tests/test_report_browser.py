"""The real quick report, made by the ``kresling reproduce`` command and opened in a browser.

The report is rendered by headless Chromium (Debian's ``chromium``, installed by ``make
test``). A small script is added to a copy of the page: on the window's ``load`` event -
which fires only once every image has loaded or failed - it writes, into the DOM, how many
images there are and which are broken (not ``complete`` or ``naturalWidth == 0``, which is
what an undecodable data URI or a missing file gives). ``--dump-dom`` prints the DOM after
the load event, so the result is read back as text; no screenshots and no timing guesses.
A negative control shows that the check does see a broken image.
"""

import html
import json
import shutil
import subprocess
import sys
import time

import pytest

from kresling.report.chapters import CHAPTERS

CHROMIUM = next(filter(None, map(shutil.which, ("chromium", "chromium-browser",
                                                  "google-chrome"))), None)
needs_browser = pytest.mark.skipif(CHROMIUM is None,
                                   reason="no chromium (make test installs Debian's package)")

IMAGE_CHECK = """<script>
window.addEventListener("load", function () {
  var images = Array.prototype.slice.call(document.images);
  var broken = images.filter(function (img) { return !(img.complete && img.naturalWidth > 0); });
  var out = document.createElement("pre");
  out.id = "image-check";
  out.textContent = JSON.stringify({total: images.length, broken: broken.map(
      function (img) { return img.alt || img.src.slice(0, 80); })});
  document.body.appendChild(out);
});
</script>"""


def images_in_browser(page, tmp_path):
    """Open ``page`` in headless Chromium; return ``{"total": int, "broken": [str]}``."""
    probe = page.with_name(f"_probe_{page.name}")  # beside the page: same relative links
    probe.write_text(page.read_text().replace("</body>", IMAGE_CHECK + "</body>"))
    result = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         f"--user-data-dir={tmp_path / 'chromium-profile'}", "--virtual-time-budget=30000",
         "--dump-dom", probe.as_uri()], capture_output=True, text=True, timeout=180)
    start = result.stdout.find('<pre id="image-check">')
    assert start >= 0, f"no result in the DOM; chromium said: {result.stderr[-2000:]}"
    text = result.stdout[start:].split(">", 1)[1].split("</pre>", 1)[0]
    return json.loads(html.unescape(text))


@pytest.fixture(scope="module")
def quick_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("quick_report")
    start = time.perf_counter()
    result = subprocess.run([sys.executable, "-m", "kresling", "reproduce", "--quick",
                             "--out", str(out)], capture_output=True, text=True, timeout=600)
    return out, result, time.perf_counter() - start


def test_the_quick_report_runs_every_available_section(quick_report):
    out, result, seconds = quick_report
    assert result.returncode == 0, result.stderr
    assert f"report: {out / 'report.html'}" in result.stdout
    document = json.loads((out / "report.json").read_text())
    assert [s["key"] for s in document["sections"]] == [c.key for c in CHAPTERS]
    assert document["errors"] == []
    ran = {s["key"] for s in document["sections"] if s["status"] == "ran"}
    assert {"geometry", "experiments", "analyses", "fabrication", "manipulator"} <= ran
    assert seconds < 180, f"the quick report took {seconds:.0f} s"


@needs_browser
def test_every_figure_of_the_quick_report_loads_in_a_browser(quick_report, tmp_path):
    out, _, _ = quick_report
    figures = sum(len(s["figures"]) for s in json.loads((out / "report.json").read_text())
                  ["sections"])
    seen = images_in_browser(out / "report.html", tmp_path)
    assert seen["broken"] == []
    assert seen["total"] == figures >= 15


@needs_browser
def test_the_browser_check_sees_a_broken_image(tmp_path):
    from matplotlib.figure import Figure

    good = tmp_path / "good.png"
    Figure(figsize=(1, 1)).savefig(good, dpi=20)
    page = tmp_path / "page.html"
    page.write_text('<!DOCTYPE html><html><body><img src="good.png" alt="good">'
                    '<img src="missing.png" alt="missing">'
                    '<img src="data:image/png;base64,AAAA" alt="garbled"></body></html>')
    assert images_in_browser(page, tmp_path) == {"total": 3, "broken": ["missing", "garbled"]}
