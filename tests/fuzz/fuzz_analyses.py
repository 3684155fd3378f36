"""Fuzz: the thesis's analyses (bending test, linearised bending, orientation study, facet
angle, snap-through) on random designs and options."""

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, finite_or_nan_with_reason, fuzz, junk, mostly
from kresling import Design
from kresling.analyses import (bending_test, facet_angle, facet_angles,
                               linear_bending_stiffness, orientation_study, snap_through)

designs = st.builds(Design, n=st.integers(3, 12),
                    lam=mostly(st.floats(0.55, 0.95),
                               st.floats(0.5, 1.0, exclude_min=True, exclude_max=True),
                               st.sampled_from([0.5 + 2**-52, 1 - 2**-53])),
                    Lc=mostly(st.floats(1, 100), st.floats(0, 200),
                              st.sampled_from([0.0, 5e-324, 1e-300, 1e3])),
                    R=mostly(st.floats(5, 100), st.floats(0.1, 300), st.sampled_from([1e-3, 1e4])),
                    chirality=st.sampled_from([1, -1]))
even_designs = st.builds(lambda d, half: Design(2 * half, d.lam, d.Lc, d.R, d.chirality), designs,
                         st.integers(2, 6))
states = mostly(st.sampled_from([0, 1, "contracted", "extended"]), junk)
NAMES = ("design", "state", "n", "Lc", "deflection", "steps", "cells", "protocol", "angle",
         "pin_offset", "points", "angles", "tolerance", "max_iterations", "extrapolation",
         "shift", "max_bisections", "reject_iterations", "parameters")


@fuzz(25)
@given(mostly(even_designs, designs, junk), states,
       mostly(st.sampled_from(["5mm", "0.001rad"]), junk),
       st.fixed_dictionaries({"steps": mostly(st.integers(1, 6), st.sampled_from([0, 2.5]))},
                             optional={"cells": mostly(st.sampled_from([2, 4]), st.just(3), junk),
                                       "deflection": mostly(st.floats(-10, 10), edgy_floats),
                                       "deflection_angle": mostly(st.floats(-0.1, 0.1),
                                                                  edgy_floats),
                                       "extrapolation": mostly(st.integers(0, 2), junk)}))
def test_bending_test(design, state, protocol, options):
    r = attempt(lambda: bending_test(design, state, protocol, **options), *NAMES)
    if r is not None:
        finite(r.deflection, r.force, r.angle, r.moment)
        assert r.completed or r.message.strip()
        finite_or_nan_with_reason(r.stiffness, r.message or "no increment")


@fuzz(60)
@given(mostly(even_designs, designs, junk), states, mostly(st.floats(-10, 10), edgy_floats,
                                                            junk),
       mostly(st.floats(-3, 3), edgy_floats, junk),
       mostly(st.sampled_from([2, 4, 6]), st.just(3), junk))
def test_linear_bending(design, state, angle, pin_offset, cells):
    K = attempt(lambda: linear_bending_stiffness(design, state, angle=angle,
                                                 pin_offset=pin_offset, cells=cells), *NAMES)
    if K is not None:
        # NaN only where the free DOFs form a mechanism (logged); never inf or negative.
        assert not math.isinf(K) and not K <= 0


@fuzz(20)
@given(mostly(even_designs, junk), mostly(st.none(), st.lists(edgy_floats, max_size=3), junk),
       mostly(st.integers(1, 4), st.integers(-1, 0), junk))
def test_orientation_study(design, angles, points):
    study = attempt(lambda: orientation_study(design, angles, points=points), *NAMES)
    if study is not None:
        assert study.angles.shape == study.extended.shape == study.contracted.shape


@fuzz(100)
@given(mostly(designs, junk), states)
def test_facet_angle(design, state):
    angles = attempt(lambda: facet_angles(design, state), *NAMES)
    if angles is not None:
        finite(angles)
        psi = facet_angle(design, state)
        assert 0 <= psi <= math.pi


@fuzz(40)
@given(mostly(designs, junk),
       mostly(st.integers(1, 40), st.sampled_from([0, -1, 2.5, 10**20]), junk),
       st.fixed_dictionaries({}, optional={
           "extrapolation": mostly(st.integers(0, 2), junk),
           "max_iterations": mostly(st.integers(1, 50), junk),
           "tolerance": mostly(st.sampled_from([1e-6, 1e-9, 1e-3]), edgy_floats)}))
def test_snap_through(design, steps, options):
    r = attempt(lambda: snap_through(design, steps=steps, **options), *NAMES)
    if r is not None:
        finite(r.displacement, r.force, r.energy)
        assert r.completed or r.message.strip()
        assert r.bistability.strip()
        for value in (r.snap_force, r.energy_barrier, r.stable_height):
            finite_or_nan_with_reason(value, r.bistability)
        assert math.isnan(r.snap_force) or abs(r.snap_force) < 1e6 * max(1.0, r.design.R)
        assert np.isfinite(r.iterations).all()
