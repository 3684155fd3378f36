"""Bars and hinges given one by one (:class:`Members`), beside a crease pattern's or instead
of them: the braced links of a linkage, a hinge whose wings are not a panel's corners, a
bar across a panel's diagonal.

A member bar is an axial bar like a pattern's, with its own modulus, area and law. A member
hinge is a rotational spring on the dihedral angle of four nodes ``(a, b, c, d)`` (axis
``a -> b``, wings ``c`` and ``d``, the angle ``pi`` when the two triangles are coplanar and
open) whose ``stiffness`` is its whole moment per radian [N mm/rad]: unlike a crease's, it
is not multiplied by the length of its axis. Two nodes may sit at one point when they
belong to different members (the joints of a linkage): only a member bar between them, or
a hinge whose axis ends there, is refused.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import show
from kresling.laws import BAR_LAWS, FOLD_LIMITS, HINGE_ANGLES, SPRING_LAWS
from kresling.model.model import Model

__all__ = ["Members"]


@dataclass(frozen=True)
class Members:
    """Member bars and hinges to add to a model.

    Attributes
    ----------
    bars : ndarray of int, shape (B, 2)
        End nodes of each bar (0-based, the model's numbering).
    bar_modulus, bar_area : ndarray, shape (B,), or one number for every bar
        Modulus [N/mm^2] and cross-section [mm^2]; the axial stiffness is their product.
    bar_law : tuple of str, length B
        One of :data:`kresling.laws.BAR_LAWS` per bar.
    hinges : ndarray of int, shape (H, 4)
        ``(a, b, c, d)``: axis ``a -> b``, wings ``c`` and ``d``.
    hinge_stiffness : ndarray, shape (H,), or one number
        Moment per radian [N mm/rad], >= 0.
    hinge_rest_angle : ndarray, shape (H,), or one number
        Rest dihedral angle [rad] in [0, 2 pi); NaN: the angle as built (stress-free).
    hinge_law : tuple of str, length H
        One of :data:`kresling.laws.SPRING_LAWS` per hinge.
    """

    bars: np.ndarray
    bar_modulus: np.ndarray
    bar_area: np.ndarray
    bar_law: tuple
    hinges: np.ndarray
    hinge_stiffness: np.ndarray
    hinge_rest_angle: np.ndarray
    hinge_law: tuple

    def __post_init__(self):
        bars = np.asarray(self.bars, dtype=np.int64).reshape(-1, 2)
        hinges = np.asarray(self.hinges, dtype=np.int64).reshape(-1, 4)
        object.__setattr__(self, "bars", bars)
        object.__setattr__(self, "hinges", hinges)
        for name, count in (("bar_modulus", len(bars)), ("bar_area", len(bars)),
                            ("hinge_stiffness", len(hinges)),
                            ("hinge_rest_angle", len(hinges))):
            value = np.asarray(getattr(self, name), dtype=float).reshape(-1)
            if value.size == 1:     # one value for every member
                value = np.full(count, value[0])
            if value.shape != (count,):
                raise ValueError(f"{name} has {value.size} entries: must have {count}")
            object.__setattr__(self, name, value)
        for name, table, count in (("bar_law", BAR_LAWS, len(bars)),
                                   ("hinge_law", SPRING_LAWS, len(hinges))):
            laws = tuple(getattr(self, name))
            if len(laws) != count or any(law not in table for law in laws):
                raise ValueError(f"{name} = {show(laws)} is invalid: must be {count} of "
                                 f"{sorted(table)}")
            object.__setattr__(self, name, laws)

    @property
    def nodes(self) -> np.ndarray:
        """The nodes the member bars hold (sorted, unique)."""
        return np.unique(self.bars)

    def __len__(self) -> int:
        return len(self.bars) + len(self.hinges)

    def added_to(self, model: Model) -> Model:
        """``model`` with these bars after its own and these hinges after its own (its
        elements keep their indices and their numbers)."""
        nodes = model.nodes
        self._check_geometry(nodes)
        forms = np.concatenate([model.hinge_angle,
                                np.full(len(self.hinges), HINGE_ANGLES["exact"])])
        rest = _as_built_angles(nodes, self.hinges, self.hinge_rest_angle)
        return model.replace(
            bars=np.vstack([model.bars, self.bars]),
            bar_modulus=np.concatenate([model.bar_modulus, self.bar_modulus]),
            bar_area=np.concatenate([model.bar_area, self.bar_area]),
            bar_rest_length=np.concatenate([
                model.bar_rest_length,
                np.linalg.norm(nodes[self.bars[:, 1]] - nodes[self.bars[:, 0]], axis=1)]),
            bar_law=_names(BAR_LAWS, model.bar_law) + list(self.bar_law),
            hinges=np.vstack([model.hinges, self.hinges]),
            hinge_stiffness=np.concatenate([model.hinge_stiffness, self.hinge_stiffness]),
            hinge_rest_angle=np.concatenate([model.hinge_rest_angle, rest]),
            # A member hinge's stiffness is its whole moment per radian: length 1.
            hinge_length=np.concatenate([model.hinge_length, np.ones(len(self.hinges))]),
            hinge_law=_names(SPRING_LAWS, model.hinge_law) + list(self.hinge_law),
            hinge_limits=np.vstack([model.hinge_limits,
                                    np.broadcast_to(FOLD_LIMITS, (len(self.hinges), 2))]),
            hinge_angle=_names(HINGE_ANGLES, forms))


    def _check_geometry(self, nodes) -> None:
        """Every node in range, no bar or hinge axis between two nodes at one point, no
        hinge wing on its axis line (ValueError naming the member)."""
        scale = float(np.ptp(nodes, axis=0).max()) or 1.0
        for name, rows in (("bars", self.bars), ("hinges", self.hinges)):
            if rows.size and (rows.min() < 0 or rows.max() >= len(nodes)):
                row = int(np.argwhere((rows < 0) | (rows >= len(nodes)))[0, 0])
                raise ValueError(f"member {name}[{row}] = {rows[row].tolist()}: node out of "
                                 f"range [0, {len(nodes)})")
            length = np.linalg.norm(nodes[rows[:, 1]] - nodes[rows[:, 0]], axis=1)
            short = np.flatnonzero(length <= 1e-12 * scale)
            if short.size:
                row = int(short[0])
                what = "bar" if name == "bars" else "hinge's axis"
                raise ValueError(f"member {name}[{row}] = {rows[row].tolist()}: the {what} "
                                 "joins two nodes at one point (coincident nodes belong to "
                                 "different members: nothing may join them)")
        for row, (a, b, *wings) in enumerate(self.hinges.tolist()):
            axis = nodes[b] - nodes[a]
            for wing in wings:
                off = np.linalg.norm(np.cross(nodes[wing] - nodes[a], axis)) / np.linalg.norm(axis)
                if not off > 1e-9 * scale:   # the model's own test: no dihedral angle there
                    raise ValueError(f"member hinges[{row}] = {self.hinges[row].tolist()}: "
                                     f"wing node {wing} lies on the axis line {a} -> {b}")


def _as_built_angles(nodes, hinges, given) -> np.ndarray:
    """``given`` where set, the angle in ``nodes`` (exact form) where NaN."""
    if not len(hinges):
        return np.zeros(0)
    built = _core.elements.dihedral_angles(nodes, hinges, _core.elements.DihedralForm.exact)
    return np.where(np.isnan(given), built, given)


def _names(table, codes) -> list:
    """The names of ``codes`` in a law table (name -> code)."""
    name_of = {code: name for name, code in table.items()}
    return [name_of[int(code)] for code in codes]
