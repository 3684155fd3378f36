"""Face normals and fold angles of many frames at once (kresling.io.frame_angles) against
their one-frame, one-face definitions."""

import numpy as np
import pytest

from kresling.io import fold_angles
from kresling.io.frame_angles import fold_angle_frames, newell_normals


def _reference_normals(frames, faces):
    """Newell's normal as np.cross summed over each face's corners, face by face."""
    frames = np.asarray(frames, dtype=float)
    out = np.zeros((len(frames), len(faces), 3))
    for f, face in enumerate(faces):
        corners = frames[:, face]                                   # (K, k, 3)
        out[:, f] = np.cross(corners, np.roll(corners, -1, axis=1)).sum(axis=1)
    return out


@pytest.mark.parametrize("flat_axis", [None, 0, 1, 2])
def test_newell_normals_are_the_cross_products_bit_for_bit(flat_axis):
    # Bit for bit, not to a tolerance: the path's files (path.fold) must not change by a
    # single byte with how the normals are computed. A coordinate held at 0 (a flat sheet,
    # -0.0 too) makes signed zeros, which the sum must treat as np.sum does.
    rng = np.random.default_rng(7)
    frames = rng.normal(size=(5, 40, 3)) * 10.0
    if flat_axis is not None:
        frames[..., flat_axis] = 0.0
        frames[::2, ::3, flat_axis] = -0.0
    faces = [list(rng.choice(40, size=rng.integers(3, 7), replace=False)) for _ in range(60)]
    got = newell_normals(frames, faces)
    assert got.shape == (5, 60, 3)
    assert got.tobytes() == _reference_normals(frames, faces).tobytes()


def test_fold_angle_frames_are_each_frames_fold_angles():
    # A folded strip of quads and triangles, in several frames: every frame's angles as the
    # one-frame loop (kresling.io.fold_angles, radians) gives them, to rounding (1e-9 deg:
    # the two take different but equivalent operation orders).
    rng = np.random.default_rng(3)
    flat = np.array([[x, y, 0.0] for y in (0.0, 1.0) for x in range(6)], dtype=float)
    faces = [[0, 1, 7, 6], [1, 2, 8], [1, 8, 7], [2, 3, 9, 8], [3, 4, 10, 9], [4, 5, 11, 10]]
    edges = np.array(sorted({tuple(sorted((f[i], f[(i + 1) % len(f)])))
                             for f in faces for i in range(len(f))}))
    frames = flat[None] + rng.normal(scale=0.2, size=(4, 12, 3))
    got = fold_angle_frames(faces, edges, frames)
    for k, frame in enumerate(frames):
        assert np.allclose(got[k], np.degrees(fold_angles(faces, edges, frame)),
                           rtol=0, atol=1e-9)
    assert np.any(np.abs(got) > 1.0)   # folded: the comparison is not of zeros
