"""Summaries, outlier scores and ratio propagation against hand-computed values."""

import math

import numpy as np
import pytest

from kresling.fits.statistics import (Summary, fit_line, flag_outliers, modified_z_scores,
                                      ratio_of_means, summarize)


def test_summary_of_a_small_sample_by_hand():
    s = summarize([1.0, 2.0, 3.0, 6.0])
    assert (s.n, s.mean) == (4, 3.0)
    assert s.sd == pytest.approx(math.sqrt(14.0 / 3.0), rel=1e-12)  # n - 1 in the SD
    assert s.se == pytest.approx(s.sd / 2.0, rel=1e-12)
    # t(0.975, 3) = 3.182446305284263 (tables)
    assert s.ci[1] - s.mean == pytest.approx(3.182446305284263 * s.se, rel=1e-12)


def test_one_value_has_no_spread_and_json_says_so():
    s = summarize([0.05])
    assert math.isnan(s.sd) and s.as_dict()["sd"] is None and s.as_dict()["ci"] == [None, None]


@pytest.mark.parametrize("values, confidence", [([], 0.95), ([1.0, np.nan], 0.95),
                                                ([1.0, 2.0], 1.0)])
def test_bad_summaries(values, confidence):
    with pytest.raises(ValueError):
        summarize(values, confidence)


def test_modified_z_by_hand():
    # median 3, MAD = median(|-2, -1, 0, 1, 7|) = 1
    z = modified_z_scores([1.0, 2.0, 3.0, 4.0, 10.0])
    assert z == pytest.approx(0.6745 * np.array([-2, -1, 0, 1, 7]), rel=1e-12)
    assert flag_outliers([1.0, 2.0, 3.0, 4.0, 10.0]).tolist() == [False] * 4 + [True]


def test_modified_z_when_most_values_are_equal():
    # MAD = 0: the mean absolute deviation stands in, and the odd value is still flagged.
    assert flag_outliers([5.0] * 9 + [50.0]).tolist() == [False] * 9 + [True]
    assert not flag_outliers([5.0] * 4).any()


def test_ratio_propagation_by_hand():
    a = Summary(3, 3.5, 0.29, 0.29 / math.sqrt(3), (0, 0), 0.95)
    b = Summary(3, 0.8, 0.07, 0.07 / math.sqrt(3), (0, 0), 0.95)
    r = ratio_of_means(a, b)
    assert r.value == 4.375
    assert r.sd == pytest.approx(4.375 * math.sqrt((0.29 / 3.5) ** 2 + (0.07 / 0.8) ** 2))
    assert r.sd == pytest.approx(0.5272, abs=1e-4)


def test_fit_line_exact_and_degenerate():
    assert fit_line([0.0, 1.0, 2.0], [1.0, 3.0, 5.0]) == pytest.approx((2.0, 1.0))
    with pytest.raises(ValueError, match="never changes"):
        fit_line([1.0, 1.0], [0.0, 1.0])
