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


# Every test that asks for the quick report is marked slow: whichever runs first pays for
# making it (about 30 s of CPU), and `pytest -m "not slow"` would make it for any of them.
@pytest.fixture(scope="module")
def quick_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("quick_report")
    start = time.perf_counter()
    result = subprocess.run([sys.executable, "-m", "kresling", "reproduce", "--quick",
                             "--out", str(out)], capture_output=True, text=True, timeout=600)
    return out, result, time.perf_counter() - start


@pytest.mark.slow
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


@pytest.mark.slow
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


LAYOUT_CHECK = """<script>
window.addEventListener("load", function () {
  var nav = document.getElementById("toc"), height = document.documentElement.scrollHeight;
  var seen = [];
  [0.25, 0.5, 0.99].forEach(function (f) {
    window.scrollTo(0, Math.floor(f * (height - window.innerHeight)));
    var box = nav.getBoundingClientRect();
    seen.push({scrolled: window.scrollY, top: box.top, bottom: box.bottom});
  });
  var folded = Array.prototype.map.call(document.querySelectorAll("details"), function (d) {
    return {open: d.open, rows: d.querySelectorAll("tbody tr").length,
            height: d.getBoundingClientRect().height,
            summary: d.querySelector("summary").getBoundingClientRect().height};
  });
  var out = document.createElement("pre");
  out.id = "layout-check";
  out.textContent = JSON.stringify({height: height, view: window.innerHeight, nav: seen,
                                    links: nav.querySelectorAll("a").length, folded: folded});
  document.body.appendChild(out);
});
</script>"""


@pytest.mark.slow
@needs_browser
def test_the_contents_stay_in_view_and_the_sweep_table_is_folded(quick_report, tmp_path):
    out, _, _ = quick_report
    page = out / "report.html"
    probe = page.with_name("_layout_probe.html")
    probe.write_text(page.read_text().replace("</body>", LAYOUT_CHECK + "</body>"))
    result = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         f"--user-data-dir={tmp_path / 'chromium-profile'}", "--window-size=1400,1000",
         "--virtual-time-budget=30000", "--dump-dom", probe.as_uri()],
        capture_output=True, text=True, timeout=180)
    start = result.stdout.find('<pre id="layout-check">')
    assert start >= 0, f"no result in the DOM; chromium said: {result.stderr[-2000:]}"
    found = json.loads(html.unescape(result.stdout[start:].split(">", 1)[1].split("</pre>")[0]))
    assert found["height"] > 10 * found["view"]  # a long page, scrolled for real
    for position in found["nav"]:
        assert position["scrolled"] > 0 and position["top"] == 0, found["nav"]
    sections = json.loads((out / "report.json").read_text())["sections"]
    assert found["links"] >= 2 + len(sections)  # top, summary, every section (and parts)
    # The sweep's 1,600 designs: all in the page, folded away until asked for
    folded = [d for d in found["folded"] if d["rows"] == 1600]
    assert len(folded) == 1 and not folded[0]["open"], found["folded"]
    assert folded[0]["height"] <= folded[0]["summary"] + 10  # only its one-line summary shows


@pytest.mark.slow
def test_the_readme_shows_the_quick_reports_table(quick_report):
    """README's quick start shows this command's table: the same sections, thesis chapters,
    checks and outcomes (not the seconds, which depend on the machine)."""
    import re
    from pathlib import Path

    _, result, _ = quick_report
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    start = readme.index("```text\nsection ")
    shown = readme[start + len("```text\n"):readme.index("```", start + 8)].splitlines()
    printed = result.stdout.splitlines()
    table = printed[printed.index(next(line for line in printed
                                       if line.startswith("section "))):]

    def rows(lines):  # after the header and its rule, up to the blank line
        body = lines[2:]
        body = body[:body.index("")] if "" in body else body
        # columns are two or more spaces apart; the seconds (the fourth) are left out
        return [[cell for k, cell in enumerate(re.split(r"\s{2,}", line.strip())) if k != 3]
                for line in body]

    assert rows(shown) == rows(table)
    assert len(rows(shown)) == len(CHAPTERS)
    total = re.search(r"(\d+/\d+) checks passed", "\n".join(shown)).group(1)
    assert f"{total} checks passed" in result.stdout


@pytest.mark.slow
def test_the_report_says_the_sweeps_optima_are_on_the_grids_boundary(quick_report):
    import csv

    out, _, _ = quick_report
    sections = {s["key"]: s for s in json.loads((out / "report.json").read_text())["sections"]}
    summary = sections["sweeps"]["summary"]
    assert "on the boundary of the searched domain (n max, Lc min, lam max)" in summary
    with open(out / "sweeps" / "maxima_by_n.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    # every maximum of every n at the grid's corner (thesis figures 3.9-3.12, 3.17)
    assert len(rows) == 12 and {row["on_boundary"] for row in rows} == {"Lc min; lam max"}
