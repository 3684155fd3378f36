"""The human-readable report, ``report.html``: one self-contained page.

It renders the document of :mod:`kresling.report.json_report` (so the page and
``report.json`` cannot disagree): a table of contents that stays in view while scrolling (a
column on the left; on top on narrow screens), a summary table, then each section with its
checks (our number beside the reference, the tolerance and a pass/fail mark; checks of the
pipelines on synthetic data are tagged as such), its figures (PNG embedded as base64 data
URIs, so the page works when moved alone) and its tables (CSV rendered as HTML, linked to
the CSV file beside the page; a table longer than :data:`INLINE_TABLE_ROWS` rows is shown as
a summary of its columns, the full table folded in a ``<details>`` element). Every text
inserted is HTML-escaped; symbols such as ``K_B`` are then set with subscripts (K<sub>B</sub>).
"""

from __future__ import annotations

import base64
import csv
import json
import math
import re
import statistics
from html import escape
from pathlib import Path
from urllib.parse import quote

__all__ = ["render_html", "write_html", "summary_table_html", "format_number", "rich_text"]

#: Tables of up to this many rows are shown as they are; longer ones as a summary of their
#: columns, with the full table folded away (and the CSV file linked).
INLINE_TABLE_ROWS = 30

#: Plain-text symbols of the report's texts and how the page sets them.
SYMBOLS = {"K_B": "K<sub>B</sub>", "K_ext": "K<sub>ext</sub>", "K_con": "K<sub>con</sub>",
           "Psi_ext": "&Psi;<sub>ext</sub>", "Psi_con": "&Psi;<sub>con</sub>",
           "L_c": "L<sub>c</sub>", "L_e": "L<sub>e</sub>"}
_SYMBOL = re.compile(r"(?<![\w/.])(" + "|".join(SYMBOLS) + r")(?![\w/])")

_STYLE = """
body { font: 15px/1.45 system-ui, sans-serif; margin: 0; color: #222;
       display: grid; grid-template-columns: 14em minmax(0, 1fr); }
main { max-width: 1200px; padding: 0 1.5em 2em; min-width: 0; }
nav#toc { position: sticky; top: 0; align-self: start; height: 100vh; overflow-y: auto;
          box-sizing: border-box; padding: 1em 0.8em; border-right: 1px solid #ddd;
          background: #fafafa; font-size: 13px; }
nav#toc ol { list-style: none; padding-left: 0; margin: 0.3em 0; }
nav#toc ol ol { padding-left: 1em; margin: 0 0 0.4em; font-size: 12px; }
nav#toc li { margin: 0.15em 0; } nav#toc a { color: #1f4e8c; text-decoration: none; }
nav#toc a:hover { text-decoration: underline; } nav#toc .count { font-size: 12px; }
@media (max-width: 900px) {
  body { display: block; }
  nav#toc { position: static; height: auto; border-right: 0; border-bottom: 1px solid #ddd; }
  nav#toc ol ol, nav#toc ol ol li { display: inline; margin: 0 0 0 0.6em; padding: 0; }
}
h3 { font-size: 16px; margin: 1.2em 0 0.3em; }
.tag { display: inline-block; font-size: 11px; font-weight: 600; padding: 0 5px;
       border-radius: 3px; margin-left: 4px; white-space: nowrap; }
.tag.synthetic { background: #fff3cd; color: #6b4f00; border: 1px solid #e0c36a; }
details > summary { cursor: pointer; color: #1f4e8c; margin: 0.3em 0; }
table { border-collapse: collapse; margin: 0.6em 0 1.2em; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 7px; vertical-align: top; text-align: left; }
th { background: #f2f2f2; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.pass { color: #1a7f37; font-weight: 600; } .fail { color: #c62828; font-weight: 600; }
.missing { color: #8a6d00; font-weight: 600; }
tr.fail-row { background: #fdecea; }
figure { display: inline-table; margin: 0.5em 1em 1em 0; max-width: 100%;
         vertical-align: top; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
/* The caption as wide as its figure, so that figures sit side by side where they fit. */
figure > figcaption { display: table-caption; caption-side: bottom; padding-top: 0.3em; }
figure.view { display: block; margin: 0.5em 0 1.2em; }
figure.view > figcaption { display: block; }
figure.view > div { width: 100%; border: 1px solid #ddd; }
figure.view figcaption { max-width: 900px; }
.wide { overflow-x: auto; } td.mark { white-space: nowrap; }
/* Wide enough that a check's name and note take a few lines, not a dozen. */
table.checks td.name { min-width: 13em; } table.checks td.note { min-width: 20em; }
figcaption, .note { font-size: 12.5px; color: #555; }
pre { background: #f7f7f7; padding: 0.6em; overflow-x: auto; font-size: 12px; }
section { border-top: 2px solid #ddd; margin-top: 2em; }
"""


def format_number(value, tolerance: float = 0.0) -> str:
    """``value`` with two significant digits more than ``tolerance`` resolves (15 when
    the tolerance is 0).

    >>> format_number(55.819466779781926, 1e-9)
    '55.81946677978'
    >>> format_number(0.04693333, 0.0005), format_number(None)
    ('0.04693', '-')
    """
    if value is None:
        return "-"
    value = float(value)
    if not math.isfinite(value):
        return str(value)
    if value == 0.0:
        return "0"
    if tolerance and math.isfinite(tolerance) and tolerance > 0:
        digits = math.ceil(math.log10(abs(value) / tolerance)) + 2
    else:
        digits = 15
    return f"{value:.{min(max(digits, 3), 15)}g}"


def render_html(document: dict, out_dir) -> str:
    """The page for a report document (``report.json``'s content) written in ``out_dir``."""
    mode = escape(document["mode"])
    views = any(record.get("views") for record in document["sections"])
    parts = [
        "<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
        '<meta name="viewport" content="width=device-width, initial-scale=1">',
        f"<title>kresling: reproduction of the thesis ({mode})</title>",
        f"<style>{_STYLE}</style>", _plotly_script() if views else "", "</head><body>",
        _toc_html(document), '<main id="top">',
        "<h1>Bistable generalized Kresling origami: the thesis, reproduced</h1>",
        _header(document), '<h2 id="summary">Summary</h2>', summary_table_html(document),
    ]
    counter = iter(range(1, 1_000_000))
    parts += [_section_html(record, Path(out_dir), counter) for record in document["sections"]]
    parts.append("</main></body></html>")
    return "\n".join(parts)


def rich_text(text: str) -> str:
    """``text`` HTML-escaped, with the symbols of :data:`SYMBOLS` set with subscripts (a
    symbol inside a word, a file name or a path is left alone).

    >>> rich_text("K_B ratio <= 2, K_ext / K_con, kb_ratio, table_K_B.csv")
    'K<sub>B</sub> ratio &lt;= 2, K<sub>ext</sub> / K<sub>con</sub>, kb_ratio, table_K_B.csv'
    """
    return _SYMBOL.sub(lambda match: SYMBOLS[match.group(1)], escape(text))


def _toc_html(document: dict) -> str:
    """The table of contents: the summary, then each section with its parts."""
    items = ['<li><a href="#summary">Summary</a></li>']
    for record in document["sections"]:
        key = escape(record["key"])
        count = (f' <span class="count {_outcome_class(record)}">'
                 f'{escape(record["checks_text"])}</span>'
                 if record["status"] == "ran" and record["checks"] else "")
        parts = [(f"{key}-{part}", label) for part, label, present in (
            ("checks", "checks", record["checks"]), ("figures", "figures", record["figures"]),
            ("views", "interactive views", record.get("views")),
            ("tables", "tables", record["tables"])) if present]
        inner = ("<ol>" + "".join(f'<li><a href="#{anchor}">{label}</a></li>'
                                  for anchor, label in parts) + "</ol>") if parts else ""
        items.append(f'<li><a href="#{key}">{rich_text(record["title"])}</a>{count}{inner}'
                     f"</li>")
    return ('<nav id="toc" aria-label="Contents"><strong><a href="#top">Contents</a></strong>'
            "<ol>" + "".join(items) + "</ol></nav>")


def write_html(document: dict, out_dir, path) -> Path:
    """Write :func:`render_html` to ``path``; return the path."""
    path = Path(path)
    path.write_text(render_html(document, out_dir), encoding="utf-8")
    return path


def summary_table_html(document: dict) -> str:
    """The table at the top: section, checks passed/total, outcome, time."""
    rows = []
    for record in document["sections"]:
        css = _outcome_class(record)
        rows.append(
            f'<tr><td>{escape(record["part"])}</td>'
            f'<td><a href="#{escape(record["key"])}">{rich_text(record["title"])}</a></td>'
            f'<td class="num">{escape(record["checks_text"])}</td>'
            f'<td class="{css}">{escape(record["outcome"])}</td>'
            f'<td class="num">{record["seconds"]:.1f}</td></tr>')
    total = (f'<tr><th colspan="2">all sections</th><th class="num">'
             f'{document["checks_passed"]}/{document["checks_total"]}</th><th></th>'
             f'<th class="num">{document["seconds"]:.1f}</th></tr>')
    return ('<table class="summary"><thead><tr><th>thesis</th><th>section</th>'
            '<th>checks passed</th><th>outcome</th><th>seconds</th></tr></thead><tbody>'
            + "".join(rows) + total + "</tbody></table>")


def _header(document: dict) -> str:
    mode = ("quick (coarser grids and fewer repetitions where the answer does not move)"
            if document["mode"] == "quick" else "full (the thesis's resolution)")
    command = (f" Made by <code>{escape(document['command'])}</code>."
               if document.get("command") else "")
    return (f'<p>kresling {escape(document["kresling_version"])}, {escape(mode)}, '
            f'{escape(document["created"])}, {document["seconds"]:.1f} s.{command} '
            f'{_provenance_text(document.get("provenance"))}'
            "Each number is shown beside the value it reproduces, with the tolerance it is "
            "held to; the notes say why that tolerance, or what differs. A check outside its "
            "tolerance is marked <span class=\"fail\">fail</span> and left in view.</p>")


def _provenance_text(found) -> str:
    """One sentence: the commit and the versions the report ran with."""
    if not found:
        return ""
    commit = found.get("git_commit")
    code = (f"Code: git commit <code>{escape(commit[:12])}</code>"
            f"{' with uncommitted changes' if found.get('git_dirty') else ''}"
            if commit else "Code: not a git checkout")
    versions = ", ".join(f"{name} {escape(str(found[name]))}"
                         for name in ("numpy", "scipy", "python") if found.get(name))
    where = f" on {escape(found['platform'])}" if found.get("platform") else ""
    return f"{code}; {versions}{where}. "


def _outcome_class(record: dict) -> str:
    if record["status"] == "not available":
        return "missing"
    if record["status"] == "error" or record["checks_passed"] < record["checks_total"]:
        return "fail"
    return "pass"


def _section_html(record: dict, out_dir: Path, counter=None) -> str:
    key = escape(record["key"])
    parts = [f'<section id="{key}"><h2>{escape(record["part"])}: {rich_text(record["title"])}</h2>',
             f'<p class="{_outcome_class(record)}">{_checks_sentence(record)}'
             f'{escape(record["outcome"])} ({record["seconds"]:.1f} s)</p>']
    if record["status"] == "not available":
        parts.append(f'<p class="note">Not yet available: {escape(record["error"])}. '
                     "This part of the thesis is not reproduced by this version.</p>")
    if record["traceback"]:
        parts.append(f"<pre>{escape(record['traceback'])}</pre>")
    if record["summary"]:
        parts.append(f"<p>{rich_text(record['summary'])}</p>")
    if record["checks"]:
        parts.append(f'<h3 id="{key}-checks">Checks</h3>')
        if any(check.get("synthetic") for check in record["checks"]):
            parts.append(f'<p class="note">{_SYNTHETIC_TAG} {_SYNTHETIC_NOTE}</p>')
        parts.append(_checks_table(record["checks"]))
    if record["figures"]:
        parts.append(f'<h3 id="{key}-figures">Figures</h3>')
    parts += [_figure_html(item, out_dir) for item in record["figures"]]
    counter = counter if counter is not None else iter(range(1, 1_000_000))
    if record.get("views"):
        parts.append(f'<h3 id="{key}-views">Interactive views</h3>')
    parts += [_view_html(item, out_dir, f"view-{next(counter)}")
              for item in record.get("views", [])]
    if record["tables"]:
        parts.append(f'<h3 id="{key}-tables">Tables</h3>')
    parts += [_table_html(item, out_dir) for item in record["tables"]]
    parts.append("</section>")
    return "\n".join(parts)


_SYNTHETIC_TAG = '<span class="tag synthetic">pipeline recovery, synthetic data</span>'
_SYNTHETIC_NOTE = ("Checks with this tag run the analysis pipeline on synthetic records that "
                   "the model itself generated, with a known truth: they test that the "
                   "pipeline recovers it, not that the model reproduces the thesis's "
                   "experiment.")


def _checks_sentence(record: dict) -> str:
    if record["status"] != "ran":
        return ""
    return f'{escape(record["checks_text"])} checks passed, '


def _checks_table(checks: list) -> str:
    rows = []
    for check in checks:
        tolerance = check["tolerance"] or 0.0
        mark = '<span class="pass">&#10003; pass</span>' if check["passed"] else \
            '<span class="fail">&#10007; fail</span>'
        tag = f" {_SYNTHETIC_TAG}" if check.get("synthetic") else ""
        cells = [mark, rich_text(check["name"]) + tag,
                 format_number(check["value"], tolerance),
                 format_number(check["reference"], tolerance),
                 _difference_text(check), escape(_tolerance_text(check)),
                 escape(check["unit"]), rich_text(check["source"]), rich_text(check["note"])]
        classes = ["mark", "name", "num", "num", "num", "num", "", "", "note"]
        row_class = "" if check["passed"] else ' class="fail-row"'
        rows.append(f"<tr{row_class}>" + "".join(
            f'<td class="{c}">{v}</td>' if c else f"<td>{v}</td>"
            for c, v in zip(classes, cells)) + "</tr>")
    return ('<div class="wide"><table class="checks"><thead><tr><th></th><th>check</th>'
            "<th>ours</th>"
            "<th>reference</th><th>difference</th><th>tolerance</th><th>unit</th>"
            "<th>reference from</th><th>note</th></tr></thead><tbody>" + "".join(rows)
            + "</tbody></table></div>")


def _difference_text(check: dict) -> str:
    difference, relative = check["difference"], check["relative_difference"]
    if difference is None:
        return "-"
    if difference == 0.0:
        return "0"
    text = f"{difference:+.3g}"
    if relative is not None and difference != 0.0:
        text += f" ({relative:+.2%})" if abs(relative) >= 1e-4 else f" ({relative:+.1e} rel.)"
    return text


def _tolerance_text(check: dict) -> str:
    tolerance, atol, rtol = check["tolerance"], check["atol"], check["rtol"]
    if not tolerance:
        return "exact"
    if not rtol:
        return f"±{tolerance:.3g}"
    if not atol:
        return f"±{tolerance:.3g} (rtol {rtol:g})"
    return f"±{tolerance:.3g} (atol {atol:g} + rtol {rtol:g})"


def _figure_html(item: dict, out_dir: Path) -> str:
    caption, path, href = escape(item["caption"]), escape(item["path"]), _href(item["path"])
    png = (out_dir / item["path"]).read_bytes()
    width = _png_width(png)
    size = f' width="{width}"' if width else ""
    data = base64.b64encode(png).decode("ascii")
    return (f'<figure><img src="data:image/png;base64,{data}"{size} alt="{caption}">'
            f'<figcaption>{rich_text(item["caption"])} <a href="{href}">{path}</a>'
            f'</figcaption></figure>')


def _plotly_script() -> str:
    """plotly's JavaScript, inline (the page stays self-contained and offline)."""
    from plotly.offline import get_plotlyjs

    return f'<script type="text/javascript">{get_plotlyjs()}</script>'


def _view_html(item: dict, out_dir: Path, element_id: str) -> str:
    """An interactive view: the figure's JSON (frames included) drawn by plotly; its slider
    and play button step through the frames."""
    path, href = escape(item["path"]), _href(item["path"])
    figure = json.loads((out_dir / item["path"]).read_text(encoding="utf-8"))
    height = int(figure.get("layout", {}).get("height") or 650)
    # "</" would end the script early; "<\/" is the same string to JavaScript.
    text = json.dumps(figure, separators=(",", ":")).replace("</", "<\\/")
    script = (f"(function () {{ var fig = {text}; var id = '{element_id}';"
              " Plotly.newPlot(id, fig.data, fig.layout, {responsive: true, displaylogo: false})"
              ".then(function () { if (fig.frames && fig.frames.length) {"
              " return Plotly.addFrames(id, fig.frames); } }); })();")
    return (f'<figure class="view"><div id="{element_id}" style="height:{height}px"></div>'
            f"<script>{script}</script>"
            f'<figcaption>{rich_text(item["caption"])} <a href="{href}">{path}</a>'
            f'</figcaption></figure>')


def _table_html(item: dict, out_dir: Path) -> str:
    """A CSV table: whole when short; else a summary of its columns and the whole table
    folded in a ``<details>`` element."""
    with open(out_dir / item["path"], newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    header, body = (rows[0], rows[1:]) if rows else ([], [])
    path, href = escape(item["path"]), _href(item["path"])
    caption = f'<p>{rich_text(item["caption"])} <a href="{href}">{path}</a></p>'
    full = _html_table(header, body)
    if len(body) <= INLINE_TABLE_ROWS:
        return caption + full
    return (caption + f'<p class="note">{len(body)} rows; each column summarised below, the '
            f'whole table folded under it and in <a href="{href}">{path}</a>.</p>'
            + _column_summary(header, body)
            + f"<details><summary>Show all {len(body)} rows</summary>{full}</details>")


def _html_table(header: list, body: list) -> str:
    head = "".join(f"<th>{escape(cell)}</th>" for cell in header)
    lines = "".join("<tr>" + "".join(_csv_cell(cell) for cell in row) + "</tr>" for row in body)
    return (f'<div class="wide"><table><thead><tr>{head}</tr></thead><tbody>{lines}</tbody>'
            f"</table></div>")


def _column_summary(header: list, body: list) -> str:
    """One row per column: for a numeric column how many finite numbers, their smallest,
    median and largest (NaN and empty cells counted apart); for a text column its most
    common values."""
    rows = []
    for k, name in enumerate(header):
        cells = [row[k] if k < len(row) else "" for row in body]
        numbers = [_number_or_none(cell) for cell in cells]
        if all(x is not None or cell == "" for x, cell in zip(numbers, cells)) and \
                any(x is not None for x in numbers):
            finite = sorted(x for x in numbers if x is not None and math.isfinite(x))
            missing = len(cells) - len(finite)
            shown = (f"{x:.6g}" for x in (finite[0], statistics.median(finite), finite[-1])) \
                if finite else ("-", "-", "-")
            values = f"{missing} NaN or empty" if missing else ""
            rows.append((name, str(len(finite)), *shown, values))
        else:
            counts = {}
            for cell in cells:
                counts[cell] = counts.get(cell, 0) + 1
            common = sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))
            shown = ", ".join(f"{text or '(empty)'} \u00d7 {n}" for text, n in common[:3])
            more = f", and {len(common) - 3} more values" if len(common) > 3 else ""
            rows.append((name, "", "", "", "", shown + more))
    head = "".join(f"<th>{label}</th>" for label in
                   ("column", "numbers", "smallest", "median", "largest", "other values"))
    lines = "".join("<tr>" + "".join(
        f'<td class="num">{escape(cell)}</td>' if 1 <= k <= 4 else f"<td>{escape(cell)}</td>"
        for k, cell in enumerate(row)) + "</tr>" for row in rows)
    return (f'<div class="wide"><table class="columns"><thead><tr>{head}</tr></thead>'
            f"<tbody>{lines}</tbody></table></div>")


def _number_or_none(text: str):
    try:
        return float(text)
    except ValueError:
        return None


def _href(relative_path: str) -> str:
    """A link to a file beside the page (URL-quoted, then HTML-escaped)."""
    return escape(quote(relative_path))


def _png_width(png: bytes):
    """The width to show a PNG at [CSS px]: its physical width at the CSS 96 px per inch,
    from its pixel width and the resolution it records (its ``pHYs`` chunk, which Matplotlib
    writes from ``savefig``'s dpi); its pixel width if it records none; ``None`` if it is not
    a PNG. A figure drawn 5.5 inches wide thus shows 528 px wide at any dpi, two side by side."""
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        return None
    width = int.from_bytes(png[16:20], "big")
    position = png.find(b"pHYs", 33)
    if position >= 4 and png[position + 12] == 1:  # unit 1: pixels per metre
        per_metre = int.from_bytes(png[position + 4:position + 8], "big")
        if per_metre > 0:
            return max(1, round(width * 96 / (per_metre * 0.0254)))
    return width


def _csv_cell(text: str) -> str:
    """A CSV cell; long floats are shortened to 6 significant digits (full value on hover)."""
    try:
        value = float(text)
    except ValueError:
        return f"<td>{escape(text)}</td>"
    short = f"{value:.6g}" if len(text) > 8 and "." in text else text
    title = f' title="{escape(text)}"' if short != text else ""
    return f'<td class="num"{title}>{escape(short)}</td>'
