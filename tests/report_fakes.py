"""Small fake report sections for the tests of the report machinery (fast: no real work)."""

import math
import time

from kresling.report import Check, Section

#: A check name that must come out of the HTML escaped.
HOSTILE = "<script>alert('x')</script> & co"


def _png(path):
    from matplotlib.figure import Figure

    figure = Figure(figsize=(2, 1.5))
    figure.add_subplot().plot([0, 1], [1, 0])
    figure.savefig(path, dpi=50)
    return path


def passing(out_dir, quick=True):
    """Two passing checks, one figure, one table; records ``quick`` in its summary."""
    out_dir.mkdir(parents=True, exist_ok=True)
    time.sleep(0.05)
    section = Section("Passing part", f"quick={quick}")
    section.checks += [Check(HOSTILE, 1.0, 1.0, "by hand", atol=1e-9, unit="mm"),
                       Check("relative", 101.0, 100.0, "by hand", rtol=0.02, note="2 %")]
    section.add_figure(_png(out_dir / "line.png"), "A line <i>down</i>.")
    (out_dir / "values.csv").write_text("name,value\nalpha,0.123456789012\n<b>,2\n")
    section.add_table(out_dir / "values.csv", "Some values.")
    return section


def off_tolerance(out_dir, quick=True):
    """One check outside its tolerance and one NaN."""
    section = Section("Part with failing checks")
    section.checks += [Check("ok", 2.0, 2.0, "thesis", atol=0.1),
                       Check("too far", 3.0, 2.0, "thesis", atol=0.1, note="known difference"),
                       Check("not a number", math.nan, 2.0, "thesis", atol=0.1)]
    return section


def raising(out_dir, quick=True):
    raise RuntimeError("boom <b>")


def not_a_section(out_dir, quick=True):
    return 42


def figure_not_written(out_dir, quick=True):
    section = Section("Lists a figure it did not write")
    section.add_figure(out_dir / "nowhere.png", "missing")
    return section


def leaves_a_figure_open(out_dir, quick=True):
    import matplotlib.pyplot as plt

    plt.figure()
    return Section("Leaves a pyplot figure open")


def with_views(out_dir, quick=True):
    """Two interactive views (plotly figures as JSON, one with frames and a title holding
    ``</b>``) and no checks."""
    import sys

    sys.path.insert(0, str(__import__("pathlib").Path(__file__).parent))
    from kresling.view import view_model, view_path
    from view_cases import miura_sheet

    out_dir.mkdir(parents=True, exist_ok=True)
    model, topo, family, path = miura_sheet()
    section = Section("Views")
    first = out_dir / "first.json"
    view_path(model, path, triangles=topo.triangles, hinge_family=family, max_frames=4,
              title="a <b>bold</b> title").write_json(first)
    section.add_view(first, "A path <b>animated</b>.")
    second = out_dir / "second.json"
    view_model(model).write_json(second)
    section.add_view(second, "The sheet at rest.")
    return section


#: Rows of the long table of :func:`long_table` (more than the page shows unfolded).
LONG_ROWS = 45


def long_table(out_dir, quick=True):
    """Symbols to set (K_B, Psi_ext), a check on synthetic data, a short and a long table."""
    out_dir.mkdir(parents=True, exist_ok=True)
    section = Section("K_B ratios", "The K_B ratio is K_ext / K_con; Psi_ext too.")
    section.checks += [Check("K_B of the cell", 2.0, 2.0, "thesis", atol=0.1),
                       Check("K_B recovered from synthetic trials", 1.0, 1.0, "synthetic truth",
                             atol=0.1, synthetic=True)]
    lines = ["n,K_B,status"] + [f"{4 + k % 4},{0.5 * k},{'ok' if k % 9 else 'failed'}"
                                for k in range(LONG_ROWS)]
    (out_dir / "long.csv").write_text("\n".join(lines) + "\n")
    section.add_table(out_dir / "long.csv", "Every K_B.")
    (out_dir / "short.csv").write_text("a,b\n1,2\n")
    section.add_table(out_dir / "short.csv", "Two numbers.")
    section.add_figure(_png(out_dir / "line.png"), "K_B against nothing.")
    return section
