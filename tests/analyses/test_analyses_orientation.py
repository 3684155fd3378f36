"""Appendix A's orientation study with the linearised model: K_B is axisymmetric."""

import math

import numpy as np
import pytest

from kresling import Design
from kresling.analyses import LinearBendingTester
from kresling.analyses.orientation import orientation_study
from kresling.analyses.plots import plot_orientation_study


def test_symmetries_of_the_bending_axis_angle():
    # A turn by 2 pi / n maps the specimen onto itself; beta + pi is the same axis.
    d = Design(8, 0.8, 30)
    tester = LinearBendingTester(8)
    for state in (0, 1):
        for beta in (0.0, 0.3):
            k = tester.run(d, state, angle=beta)
            assert tester.run(d, state, angle=beta + 2 * math.pi / 8) == pytest.approx(k, rel=1e-9)
            assert tester.run(d, state, angle=beta + math.pi) == pytest.approx(k, rel=1e-9)


def test_appendix_a_designs_are_axisymmetric():
    # Appendix A: Lc = 15, lambda = 0.9, n = 4..10 (figure A-1). Measured spread of the K_B
    # ratio over one period: 0.36 % (n=4), 0.066 % (6), 0.020 % (8), 0.0077 % (10).
    spreads = []
    for n, bound in ((4, 5e-3), (6, 1e-3), (8, 3e-4), (10, 1.5e-4)):
        study = orientation_study(Design(n, 0.9, 15), points=9)
        assert study.angles[-1] == pytest.approx(2 * math.pi / n)
        for quantity in ("extended", "contracted", "ratio"):
            assert study.variation(quantity) < bound, (n, quantity)
        spreads.append(study.variation())
    assert np.all(np.diff(spreads) < 0)          # ever more axisymmetric as n grows


def test_pin_offset_study_is_not_axisymmetric_in_the_same_sense():
    # Turning only the pin line changes K_B by far more than turning the whole test.
    d = Design(4, 0.7, 30)
    turned = orientation_study(d, [0.0], pin_offset=math.pi / 4)
    straight = orientation_study(d, [0.0])
    assert turned.contracted[0] / straight.contracted[0] - 1 > 0.5


def test_plot(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    studies = [orientation_study(Design(n, 0.9, 15), points=5) for n in (4, 6)]
    left, right = plot_orientation_study(studies)
    assert len(left.lines) == 2 and len(right.lines) == 4
    left.figure.savefig(tmp_path / "a1.png")
    assert (tmp_path / "a1.png").stat().st_size > 1000


def test_bad_quantity():
    with pytest.raises(ValueError, match="quantity = 'slope' is invalid"):
        orientation_study(Design(4, 0.8, 30), [0.0]).variation("slope")
