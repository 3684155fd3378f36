"""Marker positions from photographs (thesis section 4.3, figures 4.9-4.10).

The thesis calibrated its camera with a checkerboard photographed in the plane of motion,
segmented the green markers with an HSV threshold, took the centre of each blob and mapped
pixels to mm with the calibration. This module does the same with OpenCV (the optional
``vision`` extra: ``pip install "kresling[vision]"``):

1. :func:`calibrate_plane`: checkerboard corners (sub-pixel) -> the homography from pixels
   to mm on the plane of motion (optionally after removing lens distortion with a camera
   matrix and distortion coefficients from ``cv2.calibrateCamera``);
2. :func:`marker_mask`: HSV threshold -> binary mask;
3. :func:`blob_centroids`: connected components -> centroids in pixels;
4. :func:`extract_markers`: all three, returning marker positions in mm on the plane.

Plane coordinates: origin at the checkerboard's inner corner nearest the image's top-left,
x along its first row of corners (to the right), y up (opposite to the image rows), in mm.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

__all__ = ["PlaneCalibration", "HsvRange", "GREEN", "calibrate_plane", "marker_mask",
           "blob_centroids", "extract_markers", "order_along_chain"]

logger = logging.getLogger(__name__)


def _cv2():
    try:
        import cv2  # here, not at the top: an optional extra, needed only to read photos
    except ImportError as error:  # pragma: no cover - exercised only without the extra
        raise ImportError("marker extraction needs OpenCV: pip install 'kresling[vision]' "
                          "(opencv-python-headless)") from error
    return cv2


def _color_image(image, name: str = "image") -> np.ndarray:
    image = np.asarray(image)
    if image.ndim != 3 or image.shape[2] != 3 or image.dtype != np.uint8:
        raise ValueError(f"{name} has shape {image.shape} and dtype {image.dtype}: must be an "
                         "(h, w, 3) uint8 BGR image (as cv2.imread returns)")
    return image


@dataclass(frozen=True)
class PlaneCalibration:
    """Pixel <-> mm mapping of the plane of motion.

    Attributes
    ----------
    homography : ndarray, shape (3, 3)
        Maps homogeneous (undistorted) pixels to homogeneous plane coordinates [mm].
    rms_px : float
        Root-mean-square reprojection error of the checkerboard corners [px].
    camera_matrix, dist_coeffs : ndarray or None
        Lens model used to undistort pixels first (None: no undistortion).
    """

    homography: np.ndarray
    rms_px: float
    camera_matrix: np.ndarray | None = None
    dist_coeffs: np.ndarray | None = None

    def _undistort(self, pixels: np.ndarray) -> np.ndarray:
        if self.camera_matrix is None:
            return pixels
        cv2 = _cv2()
        points = pixels.reshape(-1, 1, 2).astype(np.float64)
        return cv2.undistortPoints(points, self.camera_matrix, self.dist_coeffs,
                                   P=self.camera_matrix).reshape(-1, 2)

    def to_plane(self, pixels) -> np.ndarray:
        """Pixels (u, v), shape (n, 2) -> plane coordinates [mm], shape (n, 2)."""
        pixels = self._undistort(np.asarray(pixels, dtype=float).reshape(-1, 2))
        homogeneous = np.c_[pixels, np.ones(len(pixels))] @ self.homography.T
        return homogeneous[:, :2] / homogeneous[:, 2:]

    def to_pixels(self, points) -> np.ndarray:
        """Plane coordinates [mm], shape (n, 2) -> (undistorted) pixels, shape (n, 2)."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        homogeneous = np.c_[points, np.ones(len(points))] @ np.linalg.inv(self.homography).T
        return homogeneous[:, :2] / homogeneous[:, 2:]


@dataclass(frozen=True)
class HsvRange:
    """Inclusive HSV bounds in OpenCV's scale (hue 0-179, saturation and value 0-255)."""

    lower: tuple = (40, 90, 60)
    upper: tuple = (85, 255, 255)


#: Green markers, as in the thesis.
GREEN = HsvRange()


def calibrate_plane(image, pattern_size=(8, 6), square_size: float = 23.0, *,
                    camera_matrix=None, dist_coeffs=None) -> PlaneCalibration:
    """Calibrate pixels to mm from a checkerboard lying in the plane of motion.

    Parameters
    ----------
    image : ndarray, shape (h, w, 3), uint8
        BGR photograph of the checkerboard.
    pattern_size : (int, int)
        Inner corners per row and per column.
    square_size : float
        Side of a square [mm] (23 mm in the thesis).
    camera_matrix, dist_coeffs : ndarray, optional
        Lens model (from ``cv2.calibrateCamera``); corners are undistorted first.

    Returns
    -------
    PlaneCalibration

    Raises
    ------
    ValueError
        If the image is not a colour image or no checkerboard of that size is found.
    """
    cv2 = _cv2()
    gray = cv2.cvtColor(_color_image(image), cv2.COLOR_BGR2GRAY)
    columns, rows = (int(v) for v in pattern_size)
    found, corners = cv2.findChessboardCorners(gray, (columns, rows))
    if not found:
        raise ValueError(f"no checkerboard with {columns} x {rows} inner corners found in the image")
    criteria = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 100, 1e-4)
    corners = cv2.cornerSubPix(gray, corners, (7, 7), (-1, -1), criteria).reshape(-1, 2)
    # OpenCV may start at either end of a symmetric board: start at the top-left one.
    if corners[0].sum() > corners[-1].sum():
        corners = corners[::-1].copy()
    grid = np.array([(i * square_size, -j * square_size) for j in range(rows) for i in range(columns)])
    calibration = PlaneCalibration(np.eye(3), 0.0,
                                   None if camera_matrix is None else np.asarray(camera_matrix, float),
                                   None if dist_coeffs is None else np.asarray(dist_coeffs, float))
    pixels = calibration._undistort(corners.astype(np.float64))
    homography, _ = cv2.findHomography(pixels, grid, 0)
    calibration = PlaneCalibration(homography, 0.0, calibration.camera_matrix, calibration.dist_coeffs)
    rms = float(np.sqrt(np.mean(np.sum((calibration.to_pixels(grid) - pixels) ** 2, axis=1))))
    logger.info("checkerboard %dx%d: reprojection RMS %.3f px", columns, rows, rms)
    return PlaneCalibration(homography, rms, calibration.camera_matrix, calibration.dist_coeffs)


def marker_mask(image, hsv_range: HsvRange = GREEN) -> np.ndarray:
    """Binary mask (uint8, 0/255), shape (h, w), of the pixels inside ``hsv_range``."""
    cv2 = _cv2()
    hsv = cv2.cvtColor(_color_image(image), cv2.COLOR_BGR2HSV)
    return cv2.inRange(hsv, np.array(hsv_range.lower, np.uint8), np.array(hsv_range.upper, np.uint8))


def blob_centroids(mask, min_area: int = 20) -> np.ndarray:
    """Centroids (u, v) [px] of the connected components of ``mask`` with at least
    ``min_area`` pixels, shape (n, 2), top of the image first."""
    cv2 = _cv2()
    count, _, stats, centroids = cv2.connectedComponentsWithStats(np.asarray(mask, np.uint8), connectivity=8)
    keep = [i for i in range(1, count) if stats[i, cv2.CC_STAT_AREA] >= min_area]
    points = centroids[keep].reshape(-1, 2)
    return points[np.argsort(points[:, 1], kind="stable")]


def order_along_chain(points, start: int = 0) -> np.ndarray:
    """Order points (n, 2) as a chain from ``points[start]``, each next the nearest unused."""
    points = np.asarray(points, dtype=float)
    order, left = [start], set(range(len(points))) - {start}
    while left:
        last = points[order[-1]]
        order.append(min(left, key=lambda i: float(np.sum((points[i] - last) ** 2))))
        left.remove(order[-1])
    return points[order]


def extract_markers(image, calibration: PlaneCalibration, hsv_range: HsvRange = GREEN,
                    min_area: int = 20, expected: int | None = None) -> np.ndarray:
    """Marker positions on the plane of motion [mm], shape (n, 2).

    Ordered as a chain from the uppermost marker (the base plate's, in the thesis's set-up),
    so row 0 is the base marker and the others follow along the arm.

    Raises
    ------
    ValueError
        If ``expected`` is given and a different number of markers is found.
    """
    pixels = blob_centroids(marker_mask(image, hsv_range), min_area)
    if expected is not None and len(pixels) != expected:
        raise ValueError(f"found {len(pixels)} markers: expected {expected} (check the HSV range "
                         "and min_area)")
    plane = calibration.to_plane(pixels)
    return order_along_chain(plane, int(np.argmax(plane[:, 1]))) if len(plane) else plane
