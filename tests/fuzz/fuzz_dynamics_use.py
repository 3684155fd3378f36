"""Fuzz: what the dynamics answers for the thesis's users (the snap in time, the cell's and
the arm's frequencies, the arm's masses and its sag under its own weight), the entry points
behind ``kresling snap --dynamic/--modes`` and ``kresling arm --gravity/--modes``."""

from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, fuzz, junk, mostly
from kresling import Design
from kresling.analyses.cell_frequencies import cell_frequencies
from kresling.analyses.snap_dynamics import snap_in_time
from kresling.arm import build_arm
from kresling.arm.frequencies import arm_frequencies
from kresling.arm.gravity import gravity_sag
from kresling.arm.masses import arm_masses

NAMES = ("margin", "damping", "eccentricity", "hold", "duration", "time_step", "design",
         "steps", "k", "orientation", "g", "pretension", "masses", "start", "configuration",
         "measured_skeleton", "arm")
designs = mostly(st.sampled_from([Design(10, 0.9, 15), Design(8, 0.8, 30),
                                  Design(4, 0.7, 60)]), junk)
small = mostly(st.floats(0.01, 0.5), edgy_floats, junk)


@fuzz(8)
@given(designs, small, small, mostly(st.floats(0, 1), edgy_floats, junk),
       mostly(st.sampled_from([0.1, 0.2]), edgy_floats, junk),
       mostly(st.sampled_from([0.3, 0.45]), edgy_floats, junk),
       mostly(st.sampled_from([1e-3, 5e-4]), edgy_floats, junk))
def test_snap_in_time(design, margin, damping, eccentricity, hold, duration, time_step):
    result = attempt(lambda: snap_in_time(design, margin=margin, damping=damping,
                                          eccentricity=eccentricity, hold=hold,
                                          duration=duration, time_step=time_step), *NAMES)
    if result is not None:
        finite(result.time, result.travel, result.kinetic)
        assert result.completed or result.message


@fuzz(8)
@given(designs, mostly(st.integers(1, 8), junk))
def test_cell_frequencies(design, k):
    result = attempt(lambda: cell_frequencies(design, k=k), *NAMES)
    if result is not None:
        finite(result.extended.frequencies_hz, result.contracted.frequencies_hz)


ARM = build_arm("0")


@fuzz(15)
@given(mostly(st.sampled_from(["hanging", "standing", "horizontal"]), junk),
       mostly(st.floats(0, 2e4), edgy_floats, junk), mostly(st.floats(0, 3), edgy_floats, junk),
       mostly(st.integers(1, 6), junk), mostly(st.booleans(), junk))
def test_gravity_sag(orientation, g, pretension, steps, measured):
    masses = attempt(lambda: arm_masses(ARM, measured_skeleton=measured), *NAMES)
    if masses is None:
        return
    finite(masses.node)
    result = attempt(lambda: gravity_sag(ARM, orientation, g=g, pretension=pretension,
                                         steps=steps, masses=masses), *NAMES)
    if result is not None:
        finite(result.loaded_markers, result.tension)
        assert result.completed or result.message


@fuzz(8)
@given(mostly(st.sampled_from(["0", "1", "01"]), st.text(alphabet="012", max_size=3), junk),
       mostly(st.integers(1, 6), junk), mostly(st.floats(0, 3), edgy_floats, junk))
def test_arm_frequencies(configuration, k, pretension):
    result = attempt(lambda: arm_frequencies(configuration, k=k, pretension=pretension), *NAMES)
    if result is not None:
        finite(result.modes.frequencies_hz)
