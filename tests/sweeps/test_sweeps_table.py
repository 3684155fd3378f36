"""SweepTable: exact CSV round trip, selection, maps for plots; and the figures."""

import math

import matplotlib
import numpy as np
import pytest

from kresling.sweeps import SweepTable
from kresling.sweeps.plots import plot_map, plot_maps, plot_max_by_n, plot_ratio_maps

matplotlib.use("Agg")


def made_up(seed=7):
    rng = np.random.default_rng(seed)
    rows = [(n, Lc, lam) for n in (4, 6) for Lc in (15.0, 30.0, 60.0) for lam in (0.7, 0.9)]
    n, Lc, lam = map(np.array, zip(*rows))
    ratio = rng.uniform(1, 20, len(rows)) * (lam / Lc)
    status = np.array(["ok"] * len(rows), dtype=object)
    status[3] = "failed"
    ratio[3] = math.nan
    return SweepTable({"n": n, "Lc": Lc, "lam": lam, "R": np.full(len(rows), 30.0),
                       "kb_ratio": ratio, "status": status,
                       "reason": np.where(status == "ok", "", "a, \"quoted\" reason"),
                       "iterations": np.arange(len(rows)), "seconds": rng.uniform(0, 1, len(rows)),
                       "index": np.arange(len(rows))})


def test_csv_round_trip_is_exact(tmp_path):
    table = made_up()
    table.to_csv(tmp_path / "t.csv")
    back = SweepTable.read_csv(tmp_path / "t.csv")
    assert back.columns == table.columns
    for column in table.columns:
        a, b = table[column], back[column]
        assert a.dtype == b.dtype
        assert [str(x) for x in a.tolist()] == [str(x) for x in b.tolist()]  # NaN included


def test_a_header_naming_a_column_twice_is_refused_with_its_line(tmp_path):
    # A damaged file whose header repeats a name: its rows would fill that column twice.
    path = tmp_path / "t.csv"
    path.write_text("n,Lc,n\n4,15.0,4\n")
    with pytest.raises(ValueError, match=r"t\.csv, line 1: .*\['n'\] more than once"):
        SweepTable.read_csv(path)


def test_selection_best_and_grid():
    table = made_up()
    assert len(table.where(n=4)) == 6 and len(table.where(n=4, lam=0.9)) == 3
    best = table.best("kb_ratio", n=4)
    ok4 = table.where(n=4).take(table.where(n=4).ok)
    assert best["kb_ratio"] == ok4["kb_ratio"].max()
    Lc, lam, values = table.grid("kb_ratio", 4)
    assert Lc.tolist() == [15.0, 30.0, 60.0] and lam.tolist() == [0.7, 0.9]
    assert values.shape == (2, 3)
    assert np.isnan(values[1, 1])  # row 3 (n=4, Lc=30, lam=0.9) failed
    assert values[0, 2] == table.where(n=4, Lc=60.0, lam=0.7)["kb_ratio"][0]
    assert "1 failed" in repr(table)
    with pytest.raises(KeyError, match="no column 'nope'"):
        table["nope"]


def test_columns_of_different_lengths_are_refused():
    with pytest.raises(ValueError, match="different lengths"):
        SweepTable({"n": [4, 6], "Lc": [15.0]})


def test_figures_draw_and_mark_the_best():
    table = made_up()
    ax = plot_map(table, "kb_ratio", 4)
    star = [line for line in ax.lines if line.get_marker() == "*"][0]
    best = table.best("kb_ratio", n=4)
    assert (star.get_xdata()[0], star.get_ydata()[0]) == (best["Lc"], best["lam"])
    visible = [a for a in plot_maps(table, "kb_ratio").axes if a.get_visible()]
    assert len(visible) == 4  # two maps and their colour bars
    assert len(plot_ratio_maps(table, 6, ("kb_ratio", "iterations")).axes) == 4
    line = plot_max_by_n(table, "kb_ratio").lines[0]
    assert line.get_xdata().tolist() == [4, 6]
    with pytest.raises(ValueError, match="at least 2 x 2"):
        plot_map(table.where(lam=0.9), "kb_ratio", 4)
    matplotlib.pyplot.close("all")


def test_where_takes_values_comparisons_ranges_and_lists():
    table = made_up()
    n, Lc, lam = table["n"], table["Lc"], table["lam"]
    # each result against the same selection made with numpy directly
    cases = [({"Lc": ">=30"}, Lc >= 30), ({"Lc": "< 30"}, Lc < 30), ({"lam": ">0.8"}, lam > 0.8),
             ({"Lc": "<=15"}, Lc <= 15), ({"n": "!=4"}, n != 4), ({"n": "==6"}, n == 6),
             ({"Lc": (15, 30)}, (Lc >= 15) & (Lc <= 30)), ({"Lc": (20, None)}, Lc >= 20),
             ({"Lc": (None, 1e1)}, Lc <= 10), ({"n": [4]}, n == 4),
             ({"n": 6, "Lc": ">15", "lam": (0.8, 0.95)}, (n == 6) & (Lc > 15) & (lam >= 0.8))]
    for conditions, expected in cases:
        assert table.where(**conditions)["index"].tolist() == \
            table["index"][expected].tolist(), conditions
    # a NaN meets a range or a comparison only through "!="
    assert 3 not in table.where(kb_ratio=(None, None))["index"]
    assert 3 not in table.where(kb_ratio=">-1")["index"]
    assert 3 in table.where(kb_ratio="!=0")["index"]
    assert table.where(status="ok")["index"].tolist() == [i for i in range(12) if i != 3]


def test_where_on_a_text_column_takes_equality_and_inequality():
    # Before, a comparison string on a text column was compared as a plain value: "!=ok"
    # matched no row, silently. Each result against numpy's own selection.
    table = made_up()
    status, index = table["status"], table["index"]
    failed = index[status != "ok"].tolist()
    assert failed == [3]
    for condition in ("!=ok", "!= ok", " != ok ", "==failed"):
        assert table.where(status=condition)["index"].tolist() == failed, condition
    for condition in ("ok", "==ok", "== ok"):
        assert table.where(status=condition)["index"].tolist() == \
            index[status == "ok"].tolist(), condition
    # the other text column, and an empty text after the operator
    assert table.where(reason="!=")["index"].tolist() == failed
    assert table.where(reason="==")["index"].tolist() == index[status == "ok"].tolist()
    # a value starting with an operator is written after "=="
    odd = SweepTable({"n": [4, 6], "status": ["!=x", "ok"]})
    assert odd.where(status="==!=x")["n"].tolist() == [4]
    assert odd.where(status="!=x")["n"].tolist() == [4, 6]


@pytest.mark.parametrize("condition", ["<ok", ">=ok", " <= failed", ">a"])
def test_where_refuses_an_ordering_of_text(condition):
    with pytest.raises(ValueError, match=r"where: status = .* is not a condition on the text "
                                         r"column status: only equality applies to text"):
        made_up().where(status=condition)


@pytest.mark.parametrize("conditions, message", [
    ({"nope": 1}, "where: no column 'nope'; the columns are n, Lc"),
    ({"Lc": "about 30"}, "where: Lc = 'about 30' is not a condition: a comparison is one of"),
    ({"Lc": "=>30"}, "is not a condition"),
    ({"Lc": (1, 2, 3)}, r"where: Lc = \(1, 2, 3\) is not a range"),
    ({"Lc": ("15", 30)}, "is not a range"),
    ({"status": ("a", "b")}, "on a numeric column"),
])
def test_where_refuses_bad_conditions(conditions, message):
    with pytest.raises(ValueError, match=message):
        made_up().where(**conditions)


def test_best_takes_where_and_flags_the_boundary_of_the_searched_domain():
    table = made_up()
    for where in ({"n": 4}, {"Lc": ">=30", "lam": 0.7}, {"Lc": (20, 40)}):
        best = table.best("kb_ratio", where=where)
        part = table.where(**where)
        assert best["kb_ratio"] == np.nanmax(np.where(part.ok, part["kb_ratio"], np.nan))
    assert table.best("kb_ratio", where={"n": 4}) == table.best("kb_ratio", n=4)
    assert table.best("kb_ratio", where={"Lc": ">=30"}, n=4)["n"] == 4

    # made-up values rising towards one design: the boundary names exactly its edges
    rows = [(n, Lc, lam) for n in (4, 6, 8) for Lc in (15.0, 30.0, 45.0) for lam in (0.7, 0.8, 0.9)]
    n, Lc, lam = map(np.array, zip(*rows))

    def peaked(at):
        value = -((n - at[0]) ** 2 + (Lc - at[1]) ** 2 + 100 * (lam - at[2]) ** 2)
        return SweepTable({"n": n, "Lc": Lc, "lam": lam, "R": np.full(len(rows), 30.0),
                           "m": value, "status": ["ok"] * len(rows)})
    corner = peaked((8, 15.0, 0.9))
    assert corner.best("m")["boundary"] == ("n max", "Lc min", "lam max")
    assert corner.best("m", n=8)["boundary"] == ("Lc min", "lam max")  # n not searched
    assert corner.best("m", n=8, lam=(0.7, 0.8))["boundary"] == ("Lc min", "lam max")
    assert peaked((6, 30.0, 0.8)).best("m")["boundary"] == ()  # inside
    assert peaked((6, 30.0, 0.7)).best("m")["boundary"] == ("lam min",)
    # R is a design parameter too, once it varies
    varied = SweepTable({"n": [8, 8], "Lc": [15.0, 15.0], "lam": [0.9, 0.9], "R": [20.0, 30.0],
                         "m": [1.0, 2.0], "status": ["ok", "ok"]})
    assert varied.best("m")["boundary"] == ("R max",)


@pytest.mark.parametrize("call, message", [
    (lambda t: t.best("nope"), "metric = 'nope' is invalid: must be a numeric column, one of n, "),
    (lambda t: t.best("status"), "metric = 'status' is invalid"),
    (lambda t: t.best("kb_ratio", where="n=4"), "where = 'n=4' is invalid: must be a dict"),
    (lambda t: t.best("kb_ratio", where={"n": 5}), "no successful design with a finite "
                                                   "kb_ratio where {'n': 5}"),
])
def test_best_refuses_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call(made_up())
