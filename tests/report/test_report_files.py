"""report.json and report.html written by build_report, on fake sections."""

import json
import math
import re

import pytest

from kresling.report.build import build_report
from kresling.report.chapters import Chapter
from kresling.report.html_report import format_number

CHAPTERS = (
    Chapter("good", "Part 1", "Good", "report_fakes", "passing"),
    Chapter("off", "Part 2", "Off", "report_fakes", "off_tolerance"),
    Chapter("later", "Part 3", "Written later", "kresling.not_written_yet"),
    Chapter("broken", "Part 4", "Broken", "report_fakes", "raising"),
)


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    return build_report(tmp_path_factory.mktemp("report"), quick=True, chapters=CHAPTERS,
                        command="kresling reproduce --quick")


def _no_nan(text):
    raise AssertionError(f"{text} in report.json")


@pytest.fixture(scope="module")
def document(report):
    return json.loads(report.json_path.read_text(), parse_constant=_no_nan)


@pytest.fixture(scope="module")
def page(report):
    return report.html_path.read_text()


def test_json_summarizes_the_run(document):
    assert document["mode"] == "quick" and document["command"] == "kresling reproduce --quick"
    assert (document["checks_passed"], document["checks_total"]) == (3, 5)
    assert document["errors"] == ["broken"] and document["not_available"] == ["later"]
    assert [s["key"] for s in document["sections"]] == ["good", "off", "later", "broken"]
    assert [s["status"] for s in document["sections"]] == ["ran", "ran", "not available",
                                                            "error"]


def test_json_has_every_check_with_its_tolerance(document):
    good, off = document["sections"][:2]
    relative = good["checks"][1]
    assert relative == {
        "name": "relative", "value": 101.0, "reference": 100.0, "source": "by hand",
        "unit": "", "rtol": 0.02, "atol": 0.0, "tolerance": 2.0, "difference": 1.0,
        "relative_difference": 0.01, "passed": True, "note": "2 %", "synthetic": False}
    assert [c["passed"] for c in off["checks"]] == [True, False, False]
    nan = off["checks"][2]
    assert nan["value"] is None and nan["difference"] is None and nan["reference"] == 2.0


def test_json_keeps_errors_and_file_paths_relative_to_the_report(report, document):
    broken = document["sections"][3]
    assert broken["error"] == "RuntimeError: boom <b>" and "Traceback" in broken["traceback"]
    good = document["sections"][0]
    assert good["figures"] == [{"path": "good/line.png", "caption": "A line <i>down</i>."}]
    assert good["tables"][0]["path"] == "good/values.csv"
    assert (report.out_dir / good["figures"][0]["path"]).is_file()
    assert good["seconds"] >= 0.05 and document["seconds"] >= good["seconds"]


def test_html_escapes_every_text_it_inserts(page):
    assert "<script>" not in page and "<b>" not in page and "<i>down" not in page
    assert "&lt;script&gt;alert(&#x27;x&#x27;)&lt;/script&gt; &amp; co" in page
    assert "RuntimeError: boom &lt;b&gt;" in page
    assert "A line &lt;i&gt;down&lt;/i&gt;." in page


def test_html_embeds_the_figures_and_renders_the_tables(page):
    images = re.findall(r'<img src="([^"]*)"', page)
    assert len(images) == 1 and images[0].startswith("data:image/png;base64,iVBORw0KGgo")
    assert '<a href="good/values.csv">good/values.csv</a>' in page
    # Long floats shortened, the full value on hover; text cells escaped.
    assert '<td class="num" title="0.123456789012">0.123457</td>' in page
    assert "<td>&lt;b&gt;</td>" in page


def test_html_shows_each_outcome(page):
    summary = page[page.index('<table class="summary">'):page.index("</table>")]
    assert summary.count("<tr>") == 1 + 4 + 1  # header, sections, total
    assert '<td class="num">1/3</td><td class="fail">2 outside tolerance</td>' in summary
    assert '<td class="num">-</td><td class="missing">not yet available</td>' in summary
    assert "not yet available" in summary and "error: RuntimeError" in summary
    assert page.count('class="fail-row"') == 2
    assert page.count("&#10003; pass") == 3 and page.count("&#10007; fail") == 2
    assert "1/3 checks passed, 2 outside tolerance (" in page
    assert "Not yet available: module kresling.not_written_yet does not exist yet" in page


def test_the_report_shows_its_summary_in_a_notebook(report):
    html = report._repr_html_()
    assert html.startswith('<table class="summary">') and "Written later" in html


def test_format_number_shows_the_digits_the_tolerance_resolves():
    assert format_number(55.819466779781926, 1e-9) == "55.81946677978"
    assert format_number(0.04693333, 0.0005) == "0.04693"
    assert format_number(1.4e-14, 1e-9) == "1.4e-14"
    assert format_number(2.0, 0.0) == "2"
    assert format_number(1 / 3, 0.0) == "0.333333333333333"
    assert format_number(None) == "-" and format_number(math.inf, 1) == "inf"


def test_unknown_sections_are_rejected_before_anything_runs(tmp_path):
    with pytest.raises(ValueError, match="unknown section 'nope'"):
        build_report(tmp_path / "r", only=["nope"], chapters=CHAPTERS)
    assert not (tmp_path / "r").exists()


def test_json_and_page_record_the_commit_and_the_versions(document, page):
    import platform
    import subprocess

    import numpy
    import scipy

    from kresling import __version__
    from kresling.report.provenance import SOURCE_ROOT

    found = document["provenance"]
    assert {k: found[k] for k in ("kresling", "numpy", "scipy", "python", "platform")} == {
        "kresling": __version__, "numpy": numpy.__version__, "scipy": scipy.__version__,
        "python": platform.python_version(), "platform": platform.platform()}
    head = subprocess.run(["git", "-C", str(SOURCE_ROOT), "rev-parse", "HEAD"],
                          capture_output=True, text=True)
    if (SOURCE_ROOT / ".git").exists() and head.returncode == 0:  # the tests run in a checkout
        assert found["git_commit"] == head.stdout.strip() and len(found["git_commit"]) == 40
        assert isinstance(found["git_dirty"], bool)
        assert f"git commit <code>{found['git_commit'][:12]}</code>" in page
    else:
        assert found["git_commit"] is None and "not a git checkout" in page
    assert f"numpy {numpy.__version__}, scipy {scipy.__version__}" in page


def test_the_commit_is_that_of_the_checkout_holding_the_package_or_none(tmp_path):
    import subprocess

    from kresling.report.provenance import git_commit, provenance

    assert git_commit(tmp_path) == (None, None)  # not a checkout
    git = ["git", "-C", str(tmp_path), "-c", "user.name=t", "-c", "user.email=t@t"]
    subprocess.run([*git, "init", "-q"], check=True)
    assert git_commit(tmp_path) == (None, None)  # a checkout without a commit
    (tmp_path / "a.txt").write_text("a\n")
    subprocess.run([*git, "add", "a.txt"], check=True)
    subprocess.run([*git, "commit", "-q", "-m", "a"], check=True)
    head = subprocess.run([*git, "rev-parse", "HEAD"], capture_output=True, text=True,
                          check=True).stdout.strip()
    assert git_commit(tmp_path) == (head, False)
    (tmp_path / "a.txt").write_text("b\n")
    assert git_commit(tmp_path) == (head, True)
    # a package installed somewhere inside another repository is not that repository's code
    (tmp_path / "site-packages").mkdir()
    assert git_commit(tmp_path / "site-packages") == (None, None)
    assert provenance(tmp_path / "site-packages")["git_commit"] is None


@pytest.fixture(scope="module")
def long_page(tmp_path_factory):
    chapters = (Chapter("long", "Part 1", "Symbols and a long table", "report_fakes",
                        "long_table"),) + CHAPTERS[:2]
    report = build_report(tmp_path_factory.mktemp("long"), chapters=chapters)
    return report, report.html_path.read_text()


def test_the_table_of_contents_links_every_section_and_its_parts(long_page):
    _, page = long_page
    toc = page[page.index('<nav id="toc"'):page.index("</nav>")]
    targets = re.findall(r'href="#([^"]+)"', toc)
    assert targets[:2] == ["top", "summary"]
    assert {"long", "long-checks", "long-figures", "long-tables", "good", "good-checks",
            "good-figures", "good-tables", "off", "off-checks"} <= set(targets)
    assert "off-figures" not in targets  # a section without figures lists none
    ids = set(re.findall(r'\sid="([^"]+)"', page))
    assert set(targets) <= ids, set(targets) - ids
    assert '<span class="count fail">1/3</span>' in toc  # checks passed, beside the section
    assert '<span class="count pass">2/2</span>' in toc
    assert "position: sticky" in page  # stays in view (the browser test scrolls it)


def test_a_long_table_is_summarised_and_folded_a_short_one_shown(long_page):
    import csv as csv_module

    import numpy as np

    from report_fakes import LONG_ROWS

    report, page = long_page
    start = page.index("Every K<sub>B</sub>.")
    block = page[start:page.index("Two numbers.")]
    summary, folded = block.split("<details>")
    assert f"<summary>Show all {LONG_ROWS} rows</summary>" in folded
    assert folded.count("<tr>") == 1 + LONG_ROWS  # header and every row
    with open(report.out_dir / "long" / "long.csv", newline="") as handle:
        rows = list(csv_module.DictReader(handle))
    k_b = np.array([float(r["K_B"]) for r in rows])
    expected = (f"<tr><td>K_B</td><td class=\"num\">{LONG_ROWS}</td><td class=\"num\">"
                f"{k_b.min():.6g}</td><td class=\"num\">{np.median(k_b):.6g}</td>"
                f"<td class=\"num\">{k_b.max():.6g}</td><td></td></tr>")
    assert expected in summary
    failed = sum(r["status"] == "failed" for r in rows)
    assert f"ok \u00d7 {LONG_ROWS - failed}, failed \u00d7 {failed}" in summary
    short = page[page.index("Two numbers."):]
    assert "<details>" not in short.split("</section>")[0] and "<td class=\"num\">2</td>" in short


def test_symbols_are_set_with_subscripts(long_page):
    _, page = long_page
    main = page[page.index("<main"):]
    assert "The K<sub>B</sub> ratio is K<sub>ext</sub> / K<sub>con</sub>; &Psi;<sub>ext</sub> " \
           "too." in main
    assert "K<sub>B</sub> of the cell" in main and "K<sub>B</sub> against nothing." in main
    assert "<h2>Part 1: K<sub>B</sub> ratios</h2>" in main  # the section's own title
    # Visible text keeps no plain K_B but in CSV cells and column names (data, not prose)
    text = re.sub(r"<details>.*?</details>", "", main, flags=re.S)
    text = re.sub(r"<table class=\"columns\">.*?</table>", "", text, flags=re.S)
    text = re.sub(r"<[^>]*>", "", text)
    assert "K_B" not in text
    assert 'alt="K_B against nothing."' in main  # an attribute holds plain text


def test_checks_on_synthetic_data_are_tagged_as_pipeline_recovery(long_page):
    report, page = long_page
    document = json.loads(report.json_path.read_text())
    checks = document["sections"][0]["checks"]
    assert [c["synthetic"] for c in checks] == [False, True]
    section = page[page.index('<section id="long">'):page.index("</section>")]
    rows = re.findall(r"<tr>.*?</tr>", section[section.index('<table class="checks">'):],
                      flags=re.S)
    assert "pipeline recovery, synthetic data" not in rows[1]  # the thesis's check
    assert "pipeline recovery, synthetic data" in rows[2]
    assert section.count("not that the model reproduces the thesis's experiment") == 1
    assert "pipeline recovery" not in page[page.index('<section id="good">'):]


def test_figures_are_shown_at_their_physical_size(long_page):
    _, page = long_page
    # report_fakes draws 2 inches wide at 50 dpi (100 pixels): 192 CSS pixels at 96 per inch
    assert re.findall(r'<img src="data:image/png;base64,[^"]*" width="(\d+)"', page) == \
        ["192"] * 2
