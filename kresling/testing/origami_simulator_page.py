"""Origami Simulator's own importer, run in headless Chromium: what that simulator reads
and builds from a file, for tests and studies to compare with.

The page loads the copy of Origami Simulator's pattern and importer code (and the libraries
they use) in tests/data/public/origami_simulator/js/ (MIT; see tests/data/public/README.md),
with a stand-in for the parts of its ``globals`` those files touch: ``vertTol`` (3, its
default in js/globals.js), ``foldUseAngles`` (true, its default), ``warn`` (collected:
every message the application would show the user) and ``model.buildModel`` (captured:
what the simulator would build its model from). Nothing of the simulator's code is changed.

- :func:`import_svg` calls ``initPattern(globals).loadSVG(url)`` (js/pattern.js, line 367),
  the path of a crease pattern drawn in SVG.
- :func:`open_fold` gives the file to ``initImporter(globals)`` through its file input
  ``#fileSelector`` (js/importer.js, lines 70-126 and 281-288), as a user opening a FOLD
  file does: its checks of the keys, then ``setFoldData``.
"""

from __future__ import annotations

import html
import json
import shutil
import subprocess
from pathlib import Path

import numpy as np

from kresling.io.fold_format import fold_document

#: Origami Simulator's code (MIT), vendored with the repository's test data: the page runs
#: from a checkout of the repository.
JS = (Path(__file__).resolve().parents[2] / "tests" / "data" / "public" / "origami_simulator"
      / "js")
SCRIPTS = ("jquery-3.2.1.min.js", "underscore-min.js", "three.min.js", "SVGLoader.js",
           "path-data-polyfill.js", "earcut.js", "fold.js", "pattern.js", "importer.js")
CHROMIUM = next(filter(None, map(shutil.which, ("chromium", "chromium-browser",
                                                  "google-chrome"))), None)

_PAGE = """<!DOCTYPE html>
<html><head><meta charset="utf-8">
{scripts}
</head><body><input id="fileSelector" type="file"><pre id="result"></pre>
<script>
window.gtag = function () {{}};
var warnings = [], built = null;
window.onerror = function (message) {{ warnings.push('error: ' + message); }};
// The opener logs the exception behind "Unable to parse FOLD json." with console.log.
var log = console.log;
console.log = function (x) {{
  if (x instanceof Error) warnings.push('exception: ' + x.message + ' | ' + x.stack);
  return log.apply(console, arguments);
}};
var globals = {{vertTol: 3, foldUseAngles: true, includeCurves: false, url: null,
  warn: function (message) {{ warnings.push(String(message)); }},
  noCreasePatternAvailable: function () {{ return false; }},
  setCreasePercent: function () {{}},
  model: {{buildModel: function (fold, creases) {{
    built = {{fold: fold, creases: creases}};
  }}}}}};
globals.pattern = initPattern(globals);
globals.importer = initImporter(globals);
function report() {{
  var raw = globals.pattern.getFoldData(true);
  document.getElementById('result').textContent = '<<' + 'RESULT>>' + JSON.stringify({{
    warnings: warnings, raw: raw,
    vertices: built ? built.fold.vertices_coords : null,
    triangles: built ? built.fold.faces_vertices : null,
    triangle_edges: built ? built.fold.edges_assignment : null,
    creases: built ? built.creases : null}}) + '<<' + 'END>>';
}}
{action}
setTimeout(report, 3000);
</script></body></html>
"""


def _run(action: str, folder: Path) -> dict:
    """Open the page with ``action`` in Chromium; what the simulator built and said."""
    if CHROMIUM is None or not JS.is_dir():
        raise RuntimeError("Origami Simulator's page needs Chromium (Debian's chromium) and "
                           f"the repository's copy of its code ({JS})")
    scripts = "\n".join(f'<script src="{(JS / name).as_uri()}"></script>' for name in SCRIPTS)
    page = folder / "origami_simulator.html"
    page.write_text(_PAGE.format(scripts=scripts, action=action), encoding="utf-8")
    result = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--allow-file-access-from-files", f"--user-data-dir={folder / 'chromium-profile'}",
         "--virtual-time-budget=10000", "--dump-dom", page.as_uri()],
        capture_output=True, text=True, timeout=180)
    # The page's text is escaped in the DOM; the markers are split in the script's source.
    dom = html.unescape(result.stdout)
    start, end = dom.find("<<RESULT>>"), dom.find("<<END>>")
    assert 0 <= start < end, f"no result in the DOM; chromium said: {result.stderr[-2000:]}"
    text = dom[start + len("<<RESULT>>"):end]
    return json.loads(text)


def import_svg(path, folder: Path) -> dict:
    """Origami Simulator's import of an SVG crease pattern.

    Returns
    -------
    dict
        ``raw``: the FOLD data it made (before triangulation: its faces are the regions the
        strokes enclose); what it builds its model from: ``vertices`` (after separating
        cuts), ``triangles`` and ``creases`` (one per crease it drives: [face, vertex, face,
        vertex, edge, angle]); and ``warnings``.
    """
    return _run(f"globals.pattern.loadSVG({json.dumps(Path(path).resolve().as_uri())});",
                folder)


def open_fold(path, folder: Path) -> dict:
    """Origami Simulator opening a FOLD file through its file input (same dict as
    :func:`import_svg`)."""
    text = json.dumps(Path(path).read_text(encoding="utf-8"))
    name = json.dumps(Path(path).name)
    action = (f"var file = new File([{text}], {name});"
              "var event = jQuery.Event('change'); event.target = {files: [file]};"
              "$('#fileSelector').trigger(event);")
    return _run(action, folder)


def simulators_triangles(pattern, folder: Path, path=None):
    """The triangles Origami Simulator folds ``pattern`` on, in the pattern's vertex numbers.

    Its importer triangulates the faces (earcut); from the SVG at ``path``, or, without one,
    from the pattern written as a FOLD file and opened. Its vertices are matched to the
    pattern's by position (it lays the sheet in its x-z plane, scaled).
    """
    folder.mkdir(parents=True, exist_ok=True)
    if path is None:
        path = folder / "pattern.fold"
        path.write_text(json.dumps(fold_document(
            pattern.vertices[:, :2], pattern.edges, pattern.edges_assignment, pattern.faces,
            edges_fold_angle=np.nan_to_num(pattern.edges_fold_angle))))
        built = open_fold(path, folder)
    else:
        built = import_svg(path, folder)
    theirs = np.array(built["vertices"])[:, [0, 2]]
    ours = np.asarray(pattern.vertices)[:, :2]
    best = None
    for flip in ((1, 1), (1, -1), (-1, 1), (-1, -1)):
        q = theirs * flip
        q = (q - q.min(axis=0)) / np.ptp(q, axis=0).max()
        p = (ours - ours.min(axis=0)) / np.ptp(ours, axis=0).max()
        d = np.linalg.norm(q[:, None] - p[None], axis=2)
        if best is None or d.min(axis=1).max() < best[0]:
            best = (d.min(axis=1).max(), d.argmin(axis=1))
    assert best[0] < 1e-6 and len(set(best[1])) == len(ours), "vertices do not match"
    return best[1][np.array(built["triangles"])]
