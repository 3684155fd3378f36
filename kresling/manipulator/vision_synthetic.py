"""Synthetic photographs of the plane of motion, to test marker extraction against known
positions: a checkerboard and green disc markers drawn through a known homography
(a pinhole camera looking at a plane), antialiased by supersampling.

Plane coordinates as in :mod:`kresling.manipulator.vision`: the checkerboard's inner corner
(i, j) (i along a row, j down the columns) sits at ``(i * square, -j * square)`` mm.
"""

from __future__ import annotations

import numpy as np

__all__ = ["camera_homography", "render_plane"]


def camera_homography(scale: float = 3.0, top_left=(-40.0, 40.0), perspective=(1.5e-5, -1e-5),
                      shear: float = 0.01) -> np.ndarray:
    """A homography plane [mm] -> pixels of a camera slightly off square to the plane.

    Parameters
    ----------
    scale : float
        Pixels per mm near the top-left of the image.
    top_left : (float, float)
        Plane point [mm] imaged at pixel (0, 0).
    perspective : (float, float)
        Projective terms [1/px]: how much the scale changes across the image.
    shear : float
        In-plane shear of the pixel grid.

    Returns
    -------
    ndarray, shape (3, 3)
    """
    x0, y0 = top_left
    to_pixels = np.array([[scale, 0.0, -scale * x0], [0.0, -scale, scale * y0], [0.0, 0.0, 1.0]])
    camera = np.array([[1.0, shear, 0.0], [0.5 * shear, 1.0, 0.0], [perspective[0], perspective[1], 1.0]])
    return camera @ to_pixels


def _plane_points(inverse, rows: np.ndarray, width: int, supersample: int):
    offsets = (np.arange(supersample) + 0.5) / supersample - 0.5
    u = (np.arange(width)[:, None] + offsets[None, :]).ravel()
    v = (rows[:, None] + offsets[None, :]).ravel()
    uu, vv = np.meshgrid(u, v)
    w = inverse[2, 0] * uu + inverse[2, 1] * vv + inverse[2, 2]
    x = (inverse[0, 0] * uu + inverse[0, 1] * vv + inverse[0, 2]) / w
    y = (inverse[1, 0] * uu + inverse[1, 1] * vv + inverse[1, 2]) / w
    return x, y


def _ramp(values):
    return np.clip(values, -1.0, 1.0)


def render_plane(homography, image_size, *, checkerboard=None, markers=None,
                 marker_radius: float = 4.0, marker_bgr=(40, 170, 40), background_bgr=(170, 160, 150),
                 edge_width: float = 0.5, supersample: int = 1, chunk_rows: int = 128) -> np.ndarray:
    """Render the plane of motion as a BGR image.

    Edges are linear ramps ``edge_width`` mm wide, symmetric about the true edge, so that a
    checkerboard corner is an exact saddle point and a disc's intensity centroid is its
    centre: what is measured is the pipeline, not the renderer's aliasing.

    Parameters
    ----------
    homography : ndarray, shape (3, 3)
        Plane [mm] -> pixels.
    image_size : (int, int)
        (width, height) [px].
    checkerboard : ((int, int), float), optional
        ``((columns, rows) of inner corners, square size [mm])``; drawn with a one-square
        white margin.
    markers : array_like, shape (n, 2), optional
        Marker centres on the plane [mm], drawn as discs of ``marker_radius`` mm.
    edge_width : float
        Width of the antialiasing ramp [mm]; about a pixel or two.
    supersample : int
        Samples per pixel along each axis (1: sample pixel centres).

    Returns
    -------
    ndarray, shape (height, width, 3), uint8
    """
    width, height = (int(v) for v in image_size)
    inverse = np.linalg.inv(np.asarray(homography, dtype=float))
    markers = np.zeros((0, 2)) if markers is None else np.asarray(markers, dtype=float).reshape(-1, 2)
    background = np.asarray(background_bgr, dtype=float)
    image = np.empty((height, width, 3), dtype=np.uint8)
    ss = int(supersample)
    for start in range(0, height, chunk_rows):
        rows = np.arange(start, min(start + chunk_rows, height))
        x, y = _plane_points(inverse, rows, width, ss)
        color = np.empty(x.shape + (3,))
        color[:] = background
        if checkerboard is not None:
            (columns, board_rows), square = checkerboard
            i, j = np.floor(x / square), np.floor(-y / square)
            margin = (i >= -2) & (i <= columns) & (j >= -2) & (j <= board_rows)
            board = (i >= -1) & (i <= columns - 1) & (j >= -1) & (j <= board_rows - 1)
            color[margin] = 255.0
            # sin(pi x / square) changes sign on every edge with slope pi / square: scaled and
            # clipped it is a ramp of width edge_width centred on the edge; the product of the
            # two ramps is the checkerboard, with a saddle exactly on each corner.
            gain = square / (np.pi * 0.5 * edge_width)
            sign = _ramp(gain * np.sin(np.pi * x / square)) * _ramp(gain * np.sin(np.pi * y / square))
            gray = 137.5 + 117.5 * sign  # 20 (black) to 255 (white)
            color[board] = gray[board][:, None]
        for cx, cy in markers:
            distance = np.hypot(x - cx, y - cy)
            near = distance < marker_radius + edge_width
            cover = np.clip((marker_radius - distance[near]) / edge_width + 0.5, 0.0, 1.0)[:, None]
            color[near] = cover * np.asarray(marker_bgr, float) + (1 - cover) * color[near]
        averaged = color.reshape(len(rows), ss, width, ss, 3).mean(axis=(1, 3))
        image[rows] = np.clip(np.rint(averaged), 0, 255).astype(np.uint8)
    return image
