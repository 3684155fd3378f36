"""What a page looks like, checked without a browser: the scene's box of a flat pattern, the
ticks per axis, the pages' height, the join creases' style, and tables without rounding
noise."""

from __future__ import annotations

import re

import numpy as np
import pytest

from kresling.cli._output import print_table
from kresling.view import FAMILY_STYLES, view_path, write_html
from kresling.view.scene_box import MIN_SIDE, box, scene_layout
from view_cases import miura_sheet


def test_a_flat_patterns_box_is_not_a_slab():
    flat = np.array([[0.0, 0.0, 0.0], [100.0, 0.0, 0.0], [100.0, 60.0, 0.0], [0.0, 60.0, 0.0]])
    low, high = box([flat])
    side = high - low
    assert side[2] == pytest.approx(MIN_SIDE * side.max())
    assert low[2] == pytest.approx(-high[2])            # centred on the sheet
    # The other sides: the nodes' extent padded by 3 % of the longest side each way.
    assert side[0] == pytest.approx(106.0) and side[1] == pytest.approx(66.0)
    layout = scene_layout([flat])
    # Ticks in proportion to each side: no pile of z ticks on a short axis.
    assert [layout[f"{a}axis"]["nticks"] for a in "xyz"] == [8, 5, 3]


def test_a_tall_models_box_keeps_its_sides():
    tall = np.array([[0.0, 0.0, 0.0], [10.0, 10.0, 200.0], [0.0, 10.0, 100.0]])
    low, high = box([tall])
    assert (high - low)[2] == pytest.approx(212.0)       # 200 + 2 x 3 % of 200
    assert (high - low)[0] == pytest.approx(MIN_SIDE * 212.0)


def test_a_page_fills_the_window_and_the_figure_keeps_its_height(tmp_path):
    model, topo, family, path = miura_sheet()
    fig = view_path(model, path, triangles=topo.triangles, hinge_family=family)
    page = write_html(fig, tmp_path / "v.html").read_text(encoding="utf-8")
    assert re.search(r'id="kresling-view"[^>]*style="height:max\(100vh, 560px\)', page) or \
        "height:max(100vh, 560px)" in page
    assert '"height":700' not in page.replace(" ", "")
    assert fig.layout.height == 700                       # the notebook's figure unchanged


def test_join_creases_are_drawn_thinner_and_lighter_than_mountains_and_valleys():
    def lightness(colour):
        return sum(int(colour[k:k + 2], 16) for k in (1, 3, 5))

    join = FAMILY_STYLES["join"]
    for family in ("mountain", "valley"):
        assert join[1] < FAMILY_STYLES[family][1]
        assert lightness(join[0]) > lightness(FAMILY_STYLES[family][0])


def test_tables_print_rounding_noise_as_zero(capsys):
    print_table([(3, 9.375, -5.740531871e-16, 140.1364663),
                 (4, 75.65487853, -4.632525242e-15, 229.9709207),
                 (5, 1e-13, 2e-13, 3e-13)],
                ("marker", "x", "y", "z"))
    lines = capsys.readouterr().out.splitlines()
    assert lines[2].split() == ["3", "9.375", "0", "140.1364663"]
    assert lines[3].split() == ["4", "75.65487853", "0", "229.9709207"]
    # Row 5: 1e-13 and 3e-13 are below 1e-12 of their columns' largest (75.7 and 230 mm):
    # noise there, printed 0; 2e-13 is its column's largest and its row's are no larger:
    # a value in its own right, kept.
    assert lines[4].split() == ["5", "0", "2e-13", "0"]


def test_the_manipulators_table_has_no_noise():
    from cli_helpers import run_kresling

    result = run_kresling("manipulator", "--config", "101", "--k", "10", cwd=".")
    assert result.returncode == 0, result.stderr
    assert "e-16" not in result.stdout and "e-15" not in result.stdout
    assert re.search(r"^3\s+9.375\s+0\s+140.1364663$", result.stdout, re.M)


def test_a_long_failure_message_is_shown_whole_in_lines_that_fit_the_page():
    import re

    from kresling.view.animation import TITLE_LINE, partial_line

    reason = ("Newton did not converge at load factor 0.4375 after 50 iterations "
              "(correction 3.1e-04 mm > tolerance 1.0e-06 mm); the increment was halved "
              "12 times down to 1.2e-05 of the first <and> the path was left there " * 3
              + "x" * 250)
    lines = partial_line(17, reason).split("<br>")[1:]
    texts = [re.sub(r"<[^>]+>", "", line) for line in lines]
    import html
    texts = [html.unescape(t) for t in texts]
    assert len(texts) > 1 and all(len(t) <= TITLE_LINE for t in texts)
    # Every character of the message is there, in order (lines broken at spaces).
    whole = "".join(texts).replace(" ", "")
    assert whole == (f"PARTIAL: the solver stopped after 17 increments ({reason})").replace(
        " ", "")
    assert "<b>PARTIAL: the solver stopped after 17 increments</b>" in lines[0]
    assert "&lt;and&gt;" in partial_line(17, reason)
