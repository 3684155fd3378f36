"""Marker extraction from photographs, on synthetic images with known marker positions."""

import numpy as np
import pytest

pytest.importorskip("cv2")

from kresling.manipulator import Manipulator, pseudo_linkage  # noqa: E402
from kresling.manipulator.vision import (blob_centroids, calibrate_plane, extract_markers,  # noqa: E402
                                         marker_mask)
from kresling.manipulator.vision_synthetic import camera_homography, render_plane  # noqa: E402

SCALE = 2.5  # px/mm, a quarter of the thesis's 10 px/mm: a harder case
SIZE = (int(230 * SCALE), int(400 * SCALE))
BOARD = ((8, 6), 20.0)  # inner corners, square [mm]


@pytest.fixture(scope="module")
def camera():
    homography = camera_homography(scale=SCALE)
    board = render_plane(homography, SIZE, checkerboard=BOARD, edge_width=0.8)
    return homography, calibrate_plane(board, *BOARD)


def test_calibration_recovers_the_homography(camera):
    homography, calibration = camera
    assert calibration.rms_px < 0.05
    points = np.array([[0.0, 0.0], [150.0, -300.0], [-20.0, -200.0]])
    truth = np.c_[points, np.ones(3)] @ homography.T
    np.testing.assert_allclose(calibration.to_pixels(points), truth[:, :2] / truth[:, 2:], atol=0.05)


@pytest.mark.parametrize("config", ["000", "011", "101", "111"])
def test_markers_recovered_to_a_tenth_of_a_millimetre(camera, config):
    homography, calibration = camera
    # The arm hanging from (150, 0) mm on the board's plane, at full displacement.
    truth = pseudo_linkage(Manipulator(), config, [10]).plot_markers[0] + [150.0, 0.0]
    image = render_plane(homography, SIZE, markers=truth, edge_width=0.8)
    found = extract_markers(image, calibration, expected=4)
    assert np.abs(found - truth).max() < 0.1  # mm, the required bound (measured: <= 0.053)


def test_mask_and_blobs():
    homography = camera_homography(scale=SCALE)
    image = render_plane(homography, (200, 200), markers=[[0.0, 0.0], [30.0, -30.0]])
    mask = marker_mask(image)
    assert mask.dtype == np.uint8 and set(np.unique(mask)) == {0, 255}
    assert blob_centroids(mask).shape == (2, 2)
    assert blob_centroids(mask, min_area=10_000).shape == (0, 2)


def test_undistortion_with_an_ideal_lens_changes_nothing(camera):
    homography, _ = camera
    board = render_plane(homography, SIZE, checkerboard=BOARD, edge_width=0.8)
    K = np.array([[800.0, 0, SIZE[0] / 2], [0, 800.0, SIZE[1] / 2], [0, 0, 1]])
    plain = calibrate_plane(board, *BOARD)
    ideal = calibrate_plane(board, *BOARD, camera_matrix=K, dist_coeffs=np.zeros(5))
    np.testing.assert_allclose(ideal.to_plane([[100.0, 300.0]]), plain.to_plane([[100.0, 300.0]]),
                               atol=1e-6)


def test_bad_images(camera):
    _, calibration = camera
    blank = np.full((300, 300, 3), 200, np.uint8)
    with pytest.raises(ValueError, match="no checkerboard with 8 x 6 inner corners"):
        calibrate_plane(blank, *BOARD)
    with pytest.raises(ValueError, match=r"must be an \(h, w, 3\) uint8 BGR image"):
        calibrate_plane(blank[:, :, 0], *BOARD)
    with pytest.raises(ValueError, match="found 0 markers: expected 4"):
        extract_markers(blank, calibration, expected=4)
