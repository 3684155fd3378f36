"""Forward kinematics of the chain (thesis eqns 25-30): frames and markers at the base and
every module end, and points along the backbone for drawing.

Coordinates: the base frame of eqn 26, z along the undeformed axis (away from the base
plate), tendon 1 on +x; the thesis's plots show ``(-x, -z)`` (:func:`to_plot_plane`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, as_integer
from kresling.manipulator.model import Manipulator, configuration_name

__all__ = ["ChainState", "forward_kinematics", "flexible_tendon_rows", "to_plot_plane",
           "from_plot_plane", "marker_distances"]


def to_plot_plane(points) -> np.ndarray:
    """Model points ``(..., 3)`` -> the thesis's plot coordinates ``(..., 2)`` = ``(-x, -z)``.

    The thesis photographs the arm hanging from its base plate, in the plane of tendon 1,
    and reports marker positions relative to the base marker as ``(-x, -z)`` (Appendix E).
    """
    points = np.asarray(points, dtype=float)
    return np.stack([-points[..., 0], -points[..., 2]], axis=-1)


def from_plot_plane(xy) -> np.ndarray:
    """Inverse of :func:`to_plot_plane` for points in the plane y = 0: ``(..., 2) -> (..., 3)``."""
    xy = np.asarray(xy, dtype=float)
    return np.stack([-xy[..., 0], np.zeros(xy.shape[:-1]), -xy[..., 1]], axis=-1)


def marker_distances(markers) -> np.ndarray:
    """Distance between consecutive markers, ``(..., m + 1, k) -> (..., m)``: the module
    ("joint") lengths of Table 5."""
    return np.linalg.norm(np.diff(np.asarray(markers, dtype=float), axis=-2), axis=-1)


def flexible_tendon_rows(configuration, tendon_lengths) -> np.ndarray:
    """Tendon lengths per flexible module, ``(f, 3)``, from ``(3,)`` (the same for every
    flexible module, the thesis's assumption) or ``(f, 3)`` (base first)."""
    f = sum(1 for s in configuration if s == 0)
    if tendon_lengths is None:
        if f:
            raise ValueError(f"tendon_lengths are required: configuration "
                             f"{configuration_name(configuration)} has {f} flexible module(s)")
        return np.zeros((0, 3))
    lengths = as_float_array("tendon_lengths", tendon_lengths)
    if lengths.shape == (3,):
        return np.tile(lengths, (f, 1))
    if lengths.shape == (f, 3):
        return lengths
    raise ValueError(f"tendon_lengths has shape {lengths.shape}: must be (3,) or ({f}, 3) for "
                     f"configuration {configuration_name(configuration)}")


class MarkerViews:
    """Views of a ``markers`` array of shape (..., m + 1, 3), shared by the results that
    carry one (:class:`ChainState`, :class:`~kresling.manipulator.ProtocolRun`)."""

    markers: np.ndarray

    @property
    def plot_markers(self) -> np.ndarray:
        """Markers in the thesis's plot coordinates ``(-x, -z)`` [mm], shape (..., m + 1, 2)."""
        return to_plot_plane(self.markers)

    @property
    def module_lengths(self) -> np.ndarray:
        """Marker-to-marker distance of each module [mm], shape (..., m)."""
        return marker_distances(self.markers)


@dataclass(frozen=True)
class ChainState(MarkerViews):
    """The manipulator evaluated at one configuration and tendon input (pinocchio's ``Data``).

    Attributes
    ----------
    model : Manipulator
    configuration : tuple of int
        0/1 per module, base first.
    tendon_lengths : ndarray, shape (f, 3)
        (l1, l2, l3) of each flexible module [mm], base first.
    arcs : ndarray, shape (m, 3)
        ``(s, kappa, phi)`` per module in the model's frame convention; rigid modules
        ``(L, 0, 0)``.
    frames : ndarray, shape (m + 1, 4, 4)
        Homogeneous frames at the base (identity) and every module end.
    """

    model: Manipulator
    configuration: tuple
    tendon_lengths: np.ndarray
    arcs: np.ndarray
    frames: np.ndarray

    @property
    def markers(self) -> np.ndarray:
        """Marker positions at the base and every module end [mm], shape (m + 1, 3)."""
        return self.frames[:, :3, 3].copy()

    @property
    def tip(self) -> np.ndarray:
        """Position of the last module's end [mm], shape (3,)."""
        return self.frames[-1, :3, 3].copy()

    def backbone(self, per_module: int = 24) -> np.ndarray:
        """Points along the backbone [mm], shape (m * per_module + 1, 3).

        Raises
        ------
        ValueError
            For ``per_module`` < 1, or more than ``MAX_BACKBONE_POINTS`` (10 million) points.
        """
        most = (_core.kinematics.MAX_BACKBONE_POINTS - 1) // self.model.modules
        per_module = as_integer("per_module", per_module, minimum=1, maximum=most)
        return _core.kinematics.backbone_points(self.model._chain, self.configuration, self.arcs,
                                                per_module)


def forward_kinematics(model: Manipulator, configuration, tendon_lengths=None) -> ChainState:
    """Evaluate the chain (eqn 25) for one configuration and tendon input.

    Parameters
    ----------
    model : Manipulator
    configuration : str or sequence of int
        E.g. ``"101"``: 0 = contracted (flexible), 1 = extended (rigid), base first.
    tendon_lengths : array_like, shape (3,) or (f, 3), optional
        Tendon lengths of the flexible modules [mm]: one triple for all (the thesis's
        assumption of identical modules) or one per flexible module. Not needed when every
        module is extended.

    Returns
    -------
    ChainState

    Raises
    ------
    ValueError
        For a bad configuration, negative or NaN lengths, or lengths no arc realises.

    Examples
    --------
    >>> arm = Manipulator()
    >>> round(float(forward_kinematics(arm, "111").tip[2]), 4)
    334.9168
    """
    configuration = model.configuration(configuration)
    rows = flexible_tendon_rows(configuration, tendon_lengths)
    arcs = _core.kinematics.module_arcs(model._chain, configuration, rows)
    frames = _core.kinematics.module_end_frames(model._chain, configuration, arcs)
    return ChainState(model, configuration, rows, arcs, frames)
