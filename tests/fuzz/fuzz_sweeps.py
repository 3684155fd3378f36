"""Fuzz: design grids, sweeps (cheap metrics, on threads), metric names, design sets."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, edgy_ints, fuzz, junk, mostly
from kresling import Design
from kresling.sweeps import as_design_set, design_grid, resolve_metrics, sweep

NAMES = ("n", "size", "Lc", "lam", "R", "grid", "designs", "metric", "metrics", "workers",
         "executor", "chunk_size", "design", "empty", "progress")
ranges = mostly(st.tuples(st.floats(0.5, 0.99), st.floats(0.5, 0.99)),
                st.tuples(edgy_floats, edgy_floats), st.lists(edgy_floats, max_size=3), junk)


@fuzz(150)
@given(mostly(st.lists(st.integers(3, 12), min_size=1, max_size=3), st.lists(edgy_ints,
                                                                              max_size=3), junk),
       mostly(st.integers(1, 4), st.tuples(st.integers(1, 3), st.integers(1, 3)),
              st.sampled_from([0, -1, 2.5, 10**6, (10**5, 10**5)]), junk),
       mostly(st.none(), st.tuples(st.floats(0, 60), st.floats(0, 60)), ranges), ranges,
       mostly(st.floats(1, 60), edgy_floats, junk))
def test_design_grid(n, size, Lc, lam, R):
    grid = attempt(lambda: design_grid(n, size, Lc=Lc, lam=lam, R=R), *NAMES)
    if grid is not None:
        assert len(grid) >= 1
        assert np.isfinite(grid.Lc).all() and np.isfinite(grid.lam).all()


@fuzz(40)
@given(mostly(st.lists(st.builds(Design, n=st.integers(3, 10), lam=st.floats(0.55, 0.95),
                                 Lc=st.floats(1, 60)), min_size=1, max_size=4),
              st.dictionaries(st.sampled_from(["n", "Lc", "lam", "R"]),
                              st.one_of(edgy_floats, st.lists(edgy_floats, max_size=3), junk)),
              junk),
       mostly(st.lists(st.sampled_from(["psi_ratio", "kb_ratio_linear"]), min_size=1,
                       max_size=2, unique=True),
              st.sampled_from([[], "nope", ["psi_ratio", "psi_ratio"]]), junk),
       mostly(st.integers(1, 2), st.sampled_from([0, -1, 2.5]), junk),
       mostly(st.none(), st.integers(1, 3), st.sampled_from([0, -2]), junk))
def test_sweep(designs, metrics, workers, chunk_size):
    table = attempt(lambda: sweep(designs, metrics, workers=workers, chunk_size=chunk_size,
                                  progress=False), *NAMES)
    if table is not None:
        assert len(table) == len(as_design_set(designs))
        for name in resolve_metrics(metrics):
            values = np.asarray(table[name.name], dtype=float)
            failed = table["status"] != "ok"
            assert np.isfinite(values[~failed]).all() or name.name == "kb_ratio_linear"
            assert all(r.strip() for r in table["reason"][failed])
