"""Identities of the generalized Kresling geometry over the whole valid design space
(hypothesis). Tolerances are relative to the cell's size: lengths are computed from
well-conditioned closed forms, so they agree to a few ulps of R; 1e-10 leaves headroom
for the sums of squares near the degenerate corners (lam -> 0.5, Lc -> 0)."""

import math

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

from kresling import Design, design_quantities

designs = st.builds(
    Design,
    n=st.integers(min_value=3, max_value=64),
    lam=st.floats(min_value=0.5, max_value=1.0, exclude_min=True, exclude_max=True),
    Lc=st.floats(min_value=0.0, max_value=200.0),
    R=st.floats(min_value=0.1, max_value=500.0),
    chirality=st.sampled_from([1, -1]),
)


def _tol(d: Design) -> float:  # for lengths computed away from a flat state
    return 1e-10 * max(d.R, d.Lc, 1.0)


@settings(max_examples=400, deadline=None)
@given(designs)
def test_path_passes_through_both_stable_states(d):
    # Compared as squares: near a flat state (L -> 0, reachable as lam -> 0.5 with Lc = 0)
    # the rounding of alpha itself (~1e-16) moves L^2 by ~1e-16 R^2 and so L by ~1e-8 R; that
    # is the conditioning of sqrt at 0, not an error of the formulas.
    tol2 = 1e-12 * max(d.R, d.Lc, 1.0) ** 2
    assert abs(d.height_at(d.alpha0) ** 2 - d.Lc**2) <= tol2
    assert abs(d.height_at(d.alpha_e) ** 2 - d.Le**2) <= tol2
    assert abs(d.mountain_length_at(d.alpha0) ** 2 - d.Mg**2) <= tol2
    assert abs(d.mountain_length_at(d.alpha_e) ** 2 - d.Mg**2) <= tol2


@settings(max_examples=400, deadline=None)
@given(designs)
@example(Design(28, 0.9999999999999998, 0.0, 1.0))  # alpha_e was exactly 0 there
def test_derived_quantities_are_consistent(d):
    tol = _tol(d)
    # Both states have the same valley and polygon lengths: the extended height is taller.
    assert d.Le >= d.Lc
    assert 0.0 < d.alpha_e <= d.alpha0 < math.pi  # equal in the limit lam -> 0.5
    assert abs(math.hypot(d.V, d.Lc) - d.Vg) <= tol
    # Valley bar = chord between bottom i and top i+1 at twist alpha0 (docs/thesis_equations.md, 'Geometry').
    assert abs(2 * d.R * math.sin((d.alpha0 + 2 * d.phi) / 2) - d.V) <= tol
    assert abs(2 * d.R * math.sin(d.alpha0 / 2) - d.M) <= tol
    # Flat facet: law of cosines with theta_g closes the triangle (P, Vg, Mg).
    mg = math.sqrt(max(d.P**2 + d.Vg**2 - 2 * d.P * d.Vg * math.cos(d.theta_g), 0.0))
    assert abs(mg - d.Mg) <= 1e-6 * max(d.R, d.Lc, 1.0)
    assert 0.0 <= d.psi_ext <= math.pi and 0.0 <= d.psi_con <= math.pi
    if d.Lc > 1e-6 * d.R:  # Lc = 0 folds the contracted cell flat: Psi_con = 0
        assert d.psi_con > 0.0 and math.isfinite(d.psi_ratio)


@settings(max_examples=200, deadline=None)
@given(n=st.integers(3, 64), R=st.floats(0.1, 500.0))
def test_traditional_limit(n, R):
    # lambda -> 1 with Lc = 0: Le = M = 2 R cos(pi/n). At lam = 1 - 1e-12 the first-order
    # change of Le is about 1e-12 * R * gamma, far below the tolerance.
    d = Design(n, 1.0 - 1e-12, 0.0, R)
    expected = 2 * R * math.cos(math.pi / n)
    assert abs(d.Le - expected) <= 1e-9 * R
    assert abs(d.M - expected) <= 1e-9 * R


@settings(max_examples=50, deadline=None)
@given(st.lists(designs, min_size=1, max_size=20))
def test_vectorised_equals_single(ds):
    q = design_quantities([d.n for d in ds], [d.lam for d in ds], [d.Lc for d in ds],
                          [d.R for d in ds])
    for i, d in enumerate(ds):
        for key, value in d.quantities().items():
            if key != "chirality":
                assert np.asarray(q[key])[i] == value, key
