"""The human-readable report, ``report.html``: one self-contained page.

It renders the document of :mod:`kresling.report.json_report` (so the page and
``report.json`` cannot disagree): a summary table, then each section with its checks (our
number beside the reference, the tolerance and a pass/fail mark), its figures (PNG embedded
as base64 data URIs, so the page works when moved alone) and its tables (CSV rendered as
HTML, linked to the CSV file beside the page). Every text inserted is HTML-escaped.
"""

from __future__ import annotations

import base64
import csv
import json
import math
from html import escape
from pathlib import Path
from urllib.parse import quote

__all__ = ["render_html", "write_html", "summary_table_html", "format_number"]

#: Rows of a CSV table shown in the page; the CSV file has them all.
MAX_TABLE_ROWS = 60

_STYLE = """
body { font: 15px/1.45 system-ui, sans-serif; max-width: 1200px; margin: 2em auto;
       padding: 0 1em; color: #222; }
table { border-collapse: collapse; margin: 0.6em 0 1.2em; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 7px; vertical-align: top; text-align: left; }
th { background: #f2f2f2; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.pass { color: #1a7f37; font-weight: 600; } .fail { color: #c62828; font-weight: 600; }
.missing { color: #8a6d00; font-weight: 600; }
tr.fail-row { background: #fdecea; }
figure { display: inline-block; margin: 0.5em 1em 1em 0; max-width: 100%;
         vertical-align: top; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { max-width: 640px; }
figure.view { display: block; margin: 0.5em 0 1.2em; }
figure.view > div { width: 100%; border: 1px solid #ddd; }
figure.view figcaption { max-width: 900px; }
.wide { overflow-x: auto; } td.mark { white-space: nowrap; }
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
        "<h1>Bistable generalized Kresling origami: the thesis, reproduced</h1>",
        _header(document), summary_table_html(document),
    ]
    counter = iter(range(1, 1_000_000))
    parts += [_section_html(record, Path(out_dir), counter) for record in document["sections"]]
    parts.append("</body></html>")
    return "\n".join(parts)


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
            f'<td><a href="#{escape(record["key"])}">{escape(record["title"])}</a></td>'
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
    parts = [f'<section id="{key}"><h2>{escape(record["part"])}: {escape(record["title"])}</h2>',
             f'<p class="{_outcome_class(record)}">{_checks_sentence(record)}'
             f'{escape(record["outcome"])} ({record["seconds"]:.1f} s)</p>']
    if record["status"] == "not available":
        parts.append(f'<p class="note">Not yet available: {escape(record["error"])}. '
                     "This part of the thesis is not reproduced by this version.</p>")
    if record["traceback"]:
        parts.append(f"<pre>{escape(record['traceback'])}</pre>")
    if record["summary"]:
        parts.append(f"<p>{escape(record['summary'])}</p>")
    if record["checks"]:
        parts.append(_checks_table(record["checks"]))
    parts += [_figure_html(item, out_dir) for item in record["figures"]]
    counter = counter if counter is not None else iter(range(1, 1_000_000))
    parts += [_view_html(item, out_dir, f"view-{next(counter)}")
              for item in record.get("views", [])]
    parts += [_table_html(item, out_dir) for item in record["tables"]]
    parts.append("</section>")
    return "\n".join(parts)


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
        cells = [mark, escape(check["name"]),
                 format_number(check["value"], tolerance),
                 format_number(check["reference"], tolerance),
                 _difference_text(check), escape(_tolerance_text(check)),
                 escape(check["unit"]), escape(check["source"]), escape(check["note"])]
        classes = ["mark", "", "num", "num", "num", "num", "", "", "note"]
        row_class = "" if check["passed"] else ' class="fail-row"'
        rows.append(f"<tr{row_class}>" + "".join(
            f'<td class="{c}">{v}</td>' if c else f"<td>{v}</td>"
            for c, v in zip(classes, cells)) + "</tr>")
    return ('<div class="wide"><table><thead><tr><th></th><th>check</th><th>ours</th>'
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
            f'<figcaption>{caption} <a href="{href}">{path}</a></figcaption></figure>')


def _plotly_script() -> str:
    """plotly's JavaScript, inline (the page stays self-contained and offline)."""
    from plotly.offline import get_plotlyjs

    return f'<script type="text/javascript">{get_plotlyjs()}</script>'


def _view_html(item: dict, out_dir: Path, element_id: str) -> str:
    """An interactive view: the figure's JSON (frames included) drawn by plotly; its slider
    and play button step through the frames."""
    caption, path, href = escape(item["caption"]), escape(item["path"]), _href(item["path"])
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
            f'<figcaption>{caption} <a href="{href}">{path}</a></figcaption></figure>')


def _table_html(item: dict, out_dir: Path) -> str:
    with open(out_dir / item["path"], newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    header, body = (rows[0], rows[1:]) if rows else ([], [])
    shown = body[:MAX_TABLE_ROWS]
    more = (f'<p class="note">{len(body) - len(shown)} more rows in the CSV file.</p>'
            if len(body) > len(shown) else "")
    head = "".join(f"<th>{escape(cell)}</th>" for cell in header)
    lines = "".join("<tr>" + "".join(_csv_cell(cell) for cell in row) + "</tr>" for row in shown)
    path, href = escape(item["path"]), _href(item["path"])
    return (f'<p>{escape(item["caption"])} <a href="{href}">{path}</a></p>'
            f'<div class="wide"><table><thead><tr>{head}</tr></thead><tbody>{lines}</tbody>'
            f"</table></div>{more}")


def _href(relative_path: str) -> str:
    """A link to a file beside the page (URL-quoted, then HTML-escaped)."""
    return escape(quote(relative_path))


def _png_width(png: bytes):
    """Pixel width from a PNG's header (``None`` if it is not a PNG): the page shows each
    figure at its own size, up to the page's width."""
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        return None
    return int.from_bytes(png[16:20], "big")


def _csv_cell(text: str) -> str:
    """A CSV cell; long floats are shortened to 6 significant digits (full value on hover)."""
    try:
        value = float(text)
    except ValueError:
        return f"<td>{escape(text)}</td>"
    short = f"{value:.6g}" if len(text) > 8 and "." in text else text
    title = f' title="{escape(text)}"' if short != text else ""
    return f'<td class="num"{title}>{escape(short)}</td>'
