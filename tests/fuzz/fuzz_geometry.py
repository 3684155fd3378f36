"""Fuzz: the closed-form cell (Design, its methods, design_quantities, state_index)."""

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, edgy_ints, finite, fuzz, junk
from kresling import Design
from kresling.geometry import design_quantities, state_index

DESIGN = ("n", "lam", "Lc", "R", "chirality")
arguments = st.fixed_dictionaries({
    "n": st.one_of(edgy_ints, junk, st.floats(2.5, 12.5)),
    "lam": st.one_of(st.floats(0.5, 1.0), edgy_floats, junk),
    "Lc": st.one_of(st.floats(0, 300), edgy_floats, junk),
    "R": st.one_of(st.floats(0.01, 1000), edgy_floats, junk),
    "chirality": st.one_of(st.sampled_from([1, -1, 0, 2, 1.0, -1.5, True]), junk)})


def check_design(d: Design) -> None:
    q = d.quantities()
    ratio = q.pop("Psi_ratio")
    finite(list(q.values()))
    # inf only where documented: Psi_con is 0 (Lc = 0) or the ratio overflows.
    assert math.isfinite(ratio) or d.psi_con == 0 or d.psi_ext / d.psi_con == math.inf
    assert 0 < d.alpha_e <= d.alpha0 < math.pi
    assert d.Le >= d.Lc


@fuzz(400)
@given(arguments)
def test_design(kwargs):
    d = attempt(lambda: Design(**kwargs), *DESIGN)
    if d is not None:
        check_design(d)
        assert Design(d.n, d.lam, d.Lc, d.R, d.chirality) == d


@fuzz(150)
@given(st.builds(Design, n=st.integers(3, 40), lam=st.floats(0.5, 1.0, exclude_min=True,
                                                             exclude_max=True),
                 Lc=st.floats(0, 200), R=st.floats(0.1, 500)),
       st.one_of(edgy_floats, st.lists(edgy_floats, max_size=4), junk),
       st.one_of(st.sampled_from([0, 1, "contracted", "extended"]), junk))
def test_design_methods(d, alpha, state):
    for method in (d.height_at, d.mountain_length_at, d.facet_angle_at):
        value = attempt(lambda: method(alpha), "alpha")
        if value is not None:
            finite(value)
    for method in (d.twist, d.height, d.vertices):
        value = attempt(lambda: method(state), "state")
        if value is not None:
            finite(value)


@fuzz(150)
@given(st.one_of(edgy_ints, st.lists(edgy_ints, min_size=1, max_size=4), junk),
       st.one_of(edgy_floats, st.lists(edgy_floats, min_size=1, max_size=4), junk),
       st.one_of(edgy_floats, st.lists(edgy_floats, min_size=1, max_size=4), junk),
       st.one_of(st.just(30.0), edgy_floats, junk))
def test_design_quantities(n, lam, Lc, R):
    q = attempt(lambda: design_quantities(n, lam, Lc, R), "n", "lam", "Lc", "R")
    if q is not None:
        finite(*(v for k, v in q.items() if k != "Psi_ratio"))
        assert not np.isnan(q["Psi_ratio"]).any()


@fuzz(100)
@given(junk)
def test_state_index(state):
    value = attempt(lambda: state_index(state), "state")
    assert value in (None, 0, 1)
