"""The snap-through in time, the cell's frequencies in its states, the thesis's masses.

The snap's landing is compared with the static test's second stable state (an independent
path: displacement control and energy descent) to 1e-6 mm: with the default damping the
motion has decayed by far more than that after 2 s (the settled height agrees to 1e-10 mm,
the kinetic energy is below 1e-20 N*mm)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from kresling import Design
from kresling.analyses.cell_frequencies import cell_frequencies
from kresling.analyses.laminate import LAMINATE_AREAL_DENSITY, specimen_masses
from kresling.analyses.snap_dynamics import snap_in_time, snap_test_cell
from kresling.assembly import assemble

OPTIMUM = Design(10, 0.9, 15, 30)


@pytest.fixture(scope="module")
def snap():
    return snap_in_time(OPTIMUM)


def test_the_snap_lands_on_the_static_stable_state(snap):
    s = snap.static
    assert snap.completed and s.bistable
    assert snap.settled_height == pytest.approx(s.stable_height, abs=1e-6)
    assert snap.settled_tilt == pytest.approx(s.stable_tilt, abs=1e-6)
    assert snap.final_kinetic < 1e-12
    # It jumps within the held load, past its stable travel, and springs back up.
    assert 0 < snap.jump_time < snap.hold
    assert snap.overshoot > 0 and snap.loaded_travel > s.stable_displacement
    assert snap.rebound > 0 and snap.settling_time < snap.time[-1]
    assert snap.load == pytest.approx(1.05 * s.snap_force, rel=1e-12)


def test_the_snap_history_starts_at_rest(snap):
    assert snap.time[0] == 0 and snap.travel[0] == 0 and snap.kinetic[0] == 0
    assert np.all(np.diff(snap.time) > 0)
    assert snap.height[0] == pytest.approx(OPTIMUM.Le, abs=1e-12)


@pytest.mark.parametrize("kwargs, name", [
    ({"margin": 0.0}, "margin"), ({"damping": -1}, "damping"),
    ({"eccentricity": -0.1}, "eccentricity"), ({"duration": 0.3}, "duration"),
    ({"time_step": float("nan")}, "time_step"), ({"hold": "x"}, "hold")])
def test_bad_snap_options_are_named(kwargs, name):
    with pytest.raises(ValueError, match=name):
        snap_in_time(OPTIMUM, **kwargs)


def test_a_monostable_cell_is_refused():
    with pytest.raises(ValueError, match="no second stable state"):
        snap_in_time(Design(4, 0.7, 60, 30))


def test_cell_frequencies_match_a_dense_eigensolve():
    f = cell_frequencies(OPTIMUM, k=4)
    cell, masses = snap_test_cell(OPTIMUM)
    free = cell.model.free_dofs
    # The snapped state's tangent and mass, solved densely (scipy's LAPACK, no shift).
    from kresling.analyses.snap_through import SnapThroughTester

    state = np.asarray(SnapThroughTester(OPTIMUM.n)._core.run(OPTIMUM._core).stable_state)
    K = assemble(cell.model, state).stiffness.toarray()[np.ix_(free, free)]
    M = np.repeat(masses, 3)[free]
    values = scipy.linalg.eigh((K + K.T) / 2, np.diag(M), eigvals_only=True)[:4]
    np.testing.assert_allclose(f.snapped.frequencies_hz, np.sqrt(values) / (2 * np.pi),
                               rtol=1e-8)
    # The switch: the extended cell is the stiffer; the snapped state is softer still.
    assert f.ratio > 1.5 and f.snapped_ratio > f.ratio
    assert f.mass == pytest.approx(masses.sum(), rel=1e-14)


def test_the_laminate_weighs_its_surface():
    cell, masses = snap_test_cell(OPTIMUM)
    from kresling.model.masses import specimen_triangles

    x = cell.model.nodes
    t = specimen_triangles(cell)
    area = 0.5 * np.linalg.norm(np.cross(x[t[:, 1]] - x[t[:, 0]], x[t[:, 2]] - x[t[:, 0]]),
                                axis=1).sum()
    assert masses.sum() == pytest.approx(LAMINATE_AREAL_DENSITY * area, rel=1e-12)
    assert LAMINATE_AREAL_DENSITY == pytest.approx(0.30 * 1.38e-9 + 0.05 * 1.0e-9, rel=1e-15)
    np.testing.assert_array_equal(masses, specimen_masses(cell))
