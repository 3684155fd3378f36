"""The analyses' figures set the bending stiffness as K with a subscript B (mathtext), not
as the plain text "K_B"."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402

from kresling import Design  # noqa: E402
from kresling.analyses import bending_stiffness  # noqa: E402
from kresling.analyses.plots import plot_moment_angle, plot_stiffness_by_n  # noqa: E402


def texts(figure) -> list:
    """Every piece of text the figure draws (titles, labels, legends, ticks)."""
    FigureCanvasAgg(figure).draw()
    return [t.get_text() for t in figure.findobj(matplotlib.text.Text) if t.get_text()]


def test_k_b_is_set_with_a_subscript():
    optimum = Design(10, 0.9, 15.0)
    comparison = bending_stiffness(optimum)
    ax = plot_moment_angle(comparison, experiment={"extended": (3.2, 0.1)})
    left, right = plot_stiffness_by_n({8: bending_stiffness(Design(8, 0.9, 15.0)),
                                       10: comparison})
    for figure in (ax.figure, left.figure):
        drawn = texts(figure)
        plain = [t for t in drawn if "K_B" in t.replace("$K_B$", "")]
        assert not plain, plain
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    stiffness = comparison.extended.stiffness
    assert legend[0] == f"state (1), extended: model, $K_B$ = {stiffness:.3f} N·m/rad"
    assert right.get_ylabel() == "$K_B$ ratio"
    plt.close("all")
