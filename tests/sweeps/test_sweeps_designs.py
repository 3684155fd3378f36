"""Design sets for sweeps: the thesis's grid, lists of designs, and bad input."""

import numpy as np
import pytest

from kresling import Design
from kresling.sweeps import as_design_set, design_grid


def test_thesis_grid_by_default():
    grid = design_grid()
    assert len(grid) == 4 * 100 * 100
    assert sorted(set(grid.n.tolist())) == [4, 6, 8, 10]
    # The corners are in the grid exactly (linspace ends), so the optimum is a grid point.
    assert grid.Lc.min() == 15.0 and grid.Lc.max() == 60.0
    assert grid.lam.min() == 0.7 and grid.lam.max() == 0.9
    assert np.all(grid.R == 30.0)


def test_grid_order_and_sizes():
    grid = design_grid((8, 10), (3, 2), Lc=(20, 40), lam=(0.75, 0.85), R=25)
    assert len(grid) == 2 * 3 * 2
    # n, then Lc, then lambda fastest.
    assert grid.n.tolist() == [8] * 6 + [10] * 6
    assert grid.Lc[:6].tolist() == [20, 20, 30, 30, 40, 40]
    assert grid.lam[:2].tolist() == [0.75, 0.85]
    assert grid.design(0) == Design(8, 0.75, 20, 25)
    assert grid.spec == {"kind": "grid", "n": [8, 10], "size": [3, 2], "Lc": [20.0, 40.0],
                         "lam": [0.75, 0.85], "R": 25.0}


def test_default_Lc_range_follows_R():
    grid = design_grid((6,), 2, R=20)
    assert sorted(set(grid.Lc.tolist())) == [10.0, 40.0]


def test_key_identifies_the_values():
    assert design_grid((8,), 4).key == design_grid((8,), 4).key
    assert design_grid((8,), 4).key != design_grid((8,), 5).key
    assert design_grid((8,), 4).key != design_grid((8,), 4, lam=(0.7, 0.9 + 1e-15)).key


def test_lists_and_mappings():
    designs = [Design(8, 0.8, 30), Design(4, 0.7, 30, R=25)]
    from_list = as_design_set(designs)
    assert list(from_list) == designs
    from_mapping = as_design_set({"n": [8, 4], "Lc": [30, 30], "lam": [0.8, 0.7], "R": [30, 25]})
    assert from_mapping.key == from_list.key
    assert as_design_set({"n": [8], "Lc": [30], "lam": [0.8]}).R.tolist() == [30.0]


@pytest.mark.parametrize("call, message", [
    (lambda: design_grid(()), "n is empty"),
    (lambda: design_grid((8,), 0), "size = 0 is invalid"),
    (lambda: design_grid((8,), (2, 2, 2)), "one or two integers"),
    (lambda: design_grid((8,), 3, lam=(0.9, 0.7)), "increasing range"),
    (lambda: design_grid((8,), 3, lam=(0.7, 1.2)), "lam"),
    (lambda: design_grid((2,), 3), "n = 2 is invalid"),
    (lambda: as_design_set([]), "empty"),
    (lambda: as_design_set(Design(8, 0.8, 30)), "wrap one Design in a list"),
    (lambda: as_design_set([(8, 30, 0.8)]), "must be Design objects"),
    (lambda: as_design_set({"n": [8], "lam": [0.8]}), "missing the column(s) Lc"),
])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        call()
