"""Figures take a model as a curve or as a single K_B, and reject malformed curves."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from kresling.fits.bending import fit_bending  # noqa: E402
from kresling.fits.plots import plot_bending_test, plot_crease_runs  # noqa: E402
from kresling.fits.synthetic import synthetic_bending_trials  # noqa: E402
from kresling.fits.thesis_tables import table1  # noqa: E402


@pytest.fixture(scope="module")
def result():
    rng = np.random.default_rng(0)
    trials = (synthetic_bending_trials(3.5, "extended", 110.6, rng)[0]
              + synthetic_bending_trials(0.8, "contracted", 60.0, rng)[0])
    return fit_bending(trials)


def test_model_as_curve_and_as_a_number(result):
    angle = np.linspace(0.0, 0.05, 50)
    ax = plot_bending_test(result, {"extended": (angle, 2.79 * angle), 0: 0.48})
    labels = [line.get_label() for line in ax.get_lines()]
    assert sum("model" in label for label in labels) == 2
    # The number becomes the line M = K delta across the experiment's angles.
    line = [ln for ln in ax.get_lines() if ln.get_label().startswith("state (0)") and
            "model" in ln.get_label()][0]
    x, y = line.get_data()
    assert y[-1] == pytest.approx(0.48 * x[-1])


def test_malformed_model_curve(result):
    with pytest.raises(ValueError, match="two 1-D arrays of one length"):
        plot_bending_test(result, {"extended": (np.zeros(3), np.zeros(4))})


def test_crease_runs_plot_marks_every_run():
    ax = plot_crease_runs(table1())
    assert len(ax.collections[0].get_offsets()) == 15


def test_the_crease_runs_legend_covers_no_data():
    # The report's Table 1 figure: the legend sat on the runs and the bands.
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    ax = plot_crease_runs(table1(), ax=Figure(figsize=(5.5, 4.0)).add_subplot(), title="Table 1")
    figure = ax.figure
    figure.tight_layout()
    renderer = FigureCanvasAgg(figure).get_renderer()
    legend, axes = ax.get_legend().get_window_extent(renderer), ax.get_window_extent(renderer)
    assert not legend.overlaps(axes), (legend, axes)
    assert figure.bbox.contains(legend.x1 - 1, legend.y0 + 1)  # still inside the figure
    assert [t.get_text() for t in ax.get_legend().get_texts()][0] == "runs"
