"""Constant-curvature map and forward kinematics through the Python API: round trips, the
thesis's protocol and Appendix E, frame conventions, and bad input."""

import math

import numpy as np
import pytest

from kresling import Design
from kresling.manipulator import (Manipulator, arc_from_tendons, forward_kinematics,
                                  protocol_tendon_lengths, pseudo_linkage, tendons_from_arc)
from kresling.manipulator.protocol import protocol_deviations
from kresling.report.sections.manipulator import appendix_e_markers

L = 2 * 55.8194667799374  # eqn 30's L: a module is two cells of height Le


@pytest.mark.parametrize("N", [1, 2, 6])
@pytest.mark.parametrize("phi", [0.35, 2.1, -2.8, -1.0])  # one per quadrant
def test_arc_round_trip_in_every_quadrant(N, phi):
    # 1e-9 (the required bound): the map is well conditioned for these bends.
    arcs = np.array([[31.0, kappa, phi] for kappa in (1e-6, 3e-3, 1.8e-2)])
    back = arc_from_tendons(tendons_from_arc(arcs, 32.0, N), 32.0, N)
    np.testing.assert_allclose(back[:, :2], arcs[:, :2], rtol=0, atol=1e-9)
    np.testing.assert_allclose(np.angle(np.exp(1j * (back[:, 2] - phi))), 0.0, atol=1e-9)


def test_straight_case_has_no_nan():
    s, kappa, phi = arc_from_tendons([30.0, 30.0, 30.0])
    assert (s, kappa, phi) == (30.0, 0.0, 0.0)
    markers = forward_kinematics(Manipulator(), "000", [30.0, 30.0, 30.0]).markers
    np.testing.assert_array_equal(markers[:, 2], [0, 30, 60, 90])


def test_bend_points_towards_the_shortest_tendon_also_when_l2_below_l3():
    # Tendon 3 shortest: it sits at 240 degrees, so the tip moves towards (cos 240, sin 240).
    tip = forward_kinematics(Manipulator(), "011", [35.0, 35.0, 20.0]).markers[1]
    direction = tip[:2] / np.linalg.norm(tip[:2])
    np.testing.assert_allclose(direction, [math.cos(4 * math.pi / 3), math.sin(4 * math.pi / 3)],
                               atol=1e-12)


def test_protocol_chord_and_bend_in_every_configuration():
    chord_error, bend_error = protocol_deviations(Manipulator())
    assert chord_error < 1e-9  # mm; rounding of ~100 mm coordinates is ~1e-13
    assert bend_error < 1e-9   # rad


def test_appendix_e_configuration_101_and_all_extended_tip():
    arm = Manipulator()
    markers = pseudo_linkage(arm, "101", [10]).markers[0]
    np.testing.assert_allclose(markers, appendix_e_markers(arm), atol=1e-9)
    # Appendix E plots (-x, -z) of markers 2..4 ("Coord2".."Coord4").
    np.testing.assert_allclose(pseudo_linkage(arm, "101", [10]).plot_markers[0, 2],
                               [-9.375, -140.1364663], atol=1e-7)
    tip = forward_kinematics(arm, "111").tip
    assert tip[2] == pytest.approx(3 * L, abs=1e-9)
    assert tip[2] == pytest.approx(3 * 111.6389, abs=1.5e-4)  # the thesis's rounded L


def test_extended_length_follows_the_design():
    arm = Manipulator(design=Design(8, 0.8, 30.0))
    assert arm.extended_length == pytest.approx(2 * 55.317649, abs=1e-5)
    assert arm.rest_tendon_length == 60.0


def test_frame_conventions_give_the_same_shape_when_used_consistently():
    rng = np.random.default_rng(5)
    for configuration in ("000", "010", "001"):
        f = configuration.count("0")
        lengths = rng.uniform(12, 40, (f, 3))  # different modules: a real test of phi handling
        jones = forward_kinematics(Manipulator(frame="jones"), configuration, lengths)
        free = forward_kinematics(Manipulator(frame="twist_free"), configuration, lengths)
        np.testing.assert_allclose(jones.markers, free.markers, atol=1e-10)
        np.testing.assert_allclose(jones.backbone(), free.backbone(), atol=1e-10)
        np.testing.assert_allclose(jones.frames[:, :3, 2], free.frames[:, :3, 2], atol=1e-12)
    # The Jones chain carries phi: under the protocol later modules get phi = 0 (Appendix E).
    arcs = forward_kinematics(Manipulator(frame="jones"), "000", protocol_tendon_lengths(4)).arcs
    np.testing.assert_allclose(arcs[:, 2], [math.pi / 2, 0.0, 0.0], atol=1e-15)


def test_protocol_tendon_lengths():
    np.testing.assert_array_equal(protocol_tendon_lengths(10), [10, 40, 40])
    np.testing.assert_array_equal(protocol_tendon_lengths([1, 2]), [[28, 31, 31], [26, 32, 32]])


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: arc_from_tendons([-1.0, 30, 30]), "l1 = -1 is invalid"),
        (lambda: arc_from_tendons([30, float("nan"), 30]), "l2 = nan is invalid"),
        (lambda: arc_from_tendons([[30, 30, 30], [0, 300, 300]]), r"\[1\] = \(0, 300, 300\)"),
        (lambda: arc_from_tendons([0, 300, 300]), "no constant-curvature arc with d = 32 mm"),
        (lambda: arc_from_tendons([30, 30]), r"shape \(2,\)"),
        (lambda: forward_kinematics(Manipulator(), "121", [30, 30, 30]), "configuration = '121'"),
        (lambda: forward_kinematics(Manipulator(), (1, 0, 2), [30, 30, 30]), "configuration ="),
        (lambda: forward_kinematics(Manipulator(), "10", [30, 30, 30]), "must have 3 entries"),
        (lambda: forward_kinematics(Manipulator(), "101"), "tendon_lengths are required"),
        (lambda: forward_kinematics(Manipulator(), "001", np.ones((3, 3)) * 30), r"must be \(3,\) or \(2, 3\)"),
        (lambda: Manipulator(modules=0), "modules = 0 is invalid: must be an integer >= 1"),
        # 2^31 - 1 modules ended in MemoryError / std::bad_alloc
        (lambda: Manipulator(modules=2**31 - 1), r"modules = 2147483647 is invalid: must be an "
                                                  r"integer >= 1 and <= 10000"),
        (lambda: forward_kinematics(Manipulator(), "111").backbone(10**9),
         r"per_module = 1000000000 is invalid: must be an integer >= 1 and <= 3333333"),
        (lambda: Manipulator(frame="dh"), "frame = 'dh' is invalid"),
        (lambda: Manipulator(tendon_radius=-2), "tendon_radius = -2"),
        (lambda: Manipulator(tendon_bounds=(0, 500)), "no constant-curvature arc"),
        (lambda: pseudo_linkage(Manipulator(), "000", [16]), r"l1\[module 1\] = -2 is invalid"),
    ],
)
def test_bad_input_is_a_value_error(call, message):
    with pytest.raises(ValueError, match=message):
        call()
