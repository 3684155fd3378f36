"""The manipulator model: m Kresling modules, their cell design, the tendons and the frame
convention (thesis section 4.2). Immutable, like pinocchio's ``Model``: every evaluation
takes it together with a configuration and tendon inputs.

A module is two cells of opposite chirality (section 4.1), so an extended module is
``2 Le`` long (eqn 30's L = 111.6 mm) and a contracted module's tendons rest at ``2 Lc``
(30 mm). Units: mm and rad.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np

from kresling import _core
from kresling._validation import as_integer, as_real, show
from kresling.geometry import Design

__all__ = ["Manipulator", "parse_configuration", "configuration_name", "all_configurations",
           "FRAMES", "MAX_MODULES"]

#: Frame conventions of a flexible module's end frame (see :class:`Manipulator`).
FRAMES = ("twist_free", "jones")

#: Most modules a manipulator may have (far beyond any arm built; bounds every per-module
#: array, and the time of the searches over configurations).
MAX_MODULES = int(_core.kinematics.MAX_MODULES)

#: The thesis's optimal cell (section 3.5), (n, lam, Lc, R): the default module cell.
THESIS_CELL = (10, 0.9, 15.0, 30.0)


def _thesis_design() -> Design:
    n, lam, Lc, R = THESIS_CELL
    return Design(n, lam, Lc, R)


@dataclass(frozen=True)
class Manipulator:
    """A tendon-driven chain of ``modules`` bistable Kresling modules.

    Parameters
    ----------
    modules : int, default 3
        Number of modules m, ``1 <= m <=`` :data:`MAX_MODULES` (10,000); there are ``2**m``
        configurations.
    design : Design, default ``Design(10, 0.9, 15.0, 30.0)``
        The cell every module is made of (the thesis's optimum).
    tendon_radius : float, default 32.0
        d [mm], the distance from the backbone to each of the three tendons.
    segments : int, default 1
        N, straight tendon segments per flexible module (eqn 27).
    cells_per_module : int, default 2
        Cells stacked in a module (two of opposite chirality in the thesis).
    frame : {"twist_free", "jones"}
        Orientation of a flexible module's end frame. ``"jones"`` is eqn 26 as printed: the
        end frame is turned by phi about its axis, and each later flexible module's phi is
        measured from that turned frame (Appendix E's ``phi = 0`` for later modules).
        ``"twist_free"`` keeps every frame's x axis on tendon 1. Marker positions are the
        same in both; only frame orientations about the backbone differ.
    tendon_bounds : (float, float), optional
        Allowed tendon length per flexible module [mm] for the inverse kinematics and
        workspace maps. Default: the extremes of the thesis's protocol at k = 10,
        ``(rest - 20, rest + 10)`` = (10, 40) mm.

    Raises
    ------
    ValueError
        For ``modules`` outside ``[1, MAX_MODULES]``, a non-positive ``tendon_radius``, ``segments < 1``, an unknown
        frame, or tendon bounds that some arc could not realise.

    Examples
    --------
    >>> arm = Manipulator()
    >>> round(arm.extended_length, 4), arm.rest_tendon_length
    (111.6389, 30.0)
    """

    modules: int = 3
    design: Design = field(default_factory=_thesis_design)
    tendon_radius: float = 32.0
    segments: int = 1
    cells_per_module: int = 2
    frame: str = "twist_free"
    tendon_bounds: tuple | None = None

    def __post_init__(self):
        set_ = object.__setattr__  # frozen: normalise the fields once, here
        set_(self, "modules", as_integer("modules", self.modules, minimum=1,
                                         maximum=MAX_MODULES))
        set_(self, "segments", as_integer("segments", self.segments, minimum=1))
        set_(self, "cells_per_module", as_integer("cells_per_module", self.cells_per_module, minimum=1))
        set_(self, "tendon_radius", as_real("tendon_radius", self.tendon_radius))
        if not isinstance(self.design, Design):
            raise ValueError(f"design = {self.design!r} is invalid: must be a kresling.Design")
        if self.frame not in FRAMES:
            raise ValueError(f"frame = {self.frame!r} is invalid: must be one of {FRAMES}")
        if not (math.isfinite(self.tendon_radius) and self.tendon_radius > 0):
            raise ValueError(f"tendon_radius = {show(self.tendon_radius)} is invalid: must be > 0")
        rest = self.rest_tendon_length
        bounds = (rest - 20.0, rest + 10.0) if self.tendon_bounds is None else self.tendon_bounds
        try:
            lower, upper = (as_real("tendon_bounds", b) for b in bounds)
        except TypeError:
            raise ValueError(f"tendon_bounds = {bounds!r} is invalid: must be (lower, upper) in mm") from None
        set_(self, "tendon_bounds", (lower, upper))
        convention = getattr(_core.kinematics.FrameConvention, self.frame)
        set_(self, "_chain", _core.kinematics.ChainModel(
            self.modules, self.extended_length, self.tendon_radius, self.segments, convention))
        # Raises for bounds whose corners no arc realises, or lower >= upper.
        _core.kinematics.sample_workspace(self._chain, (0,) * self.modules, lower, upper, 2)

    @property
    def extended_length(self) -> float:
        """L of eqn 30 [mm]: ``cells_per_module * Le`` (111.6389 mm for the thesis)."""
        return self.cells_per_module * self.design.Le

    @property
    def rest_tendon_length(self) -> float:
        """Tendon length of a contracted module at rest [mm]: ``cells_per_module * Lc``."""
        return self.cells_per_module * self.design.Lc

    @property
    def configurations(self) -> list:
        """All ``2**modules`` configurations, as tuples of 0/1 (base first)."""
        return all_configurations(self.modules)

    def with_frame(self, frame: str) -> "Manipulator":
        """The same manipulator in the other frame convention."""
        return Manipulator(self.modules, self.design, self.tendon_radius, self.segments,
                           self.cells_per_module, frame, self.tendon_bounds)

    def configuration(self, value) -> tuple:
        """``value`` parsed and checked against this manipulator's module count."""
        return parse_configuration(value, self.modules)


def parse_configuration(value, modules: int | None = None) -> tuple:
    """A configuration as a tuple of 0/1 per module, base first.

    Parameters
    ----------
    value : str or sequence of int
        ``"101"``, ``"(1 0 1)"``, ``"1,0,1"``, ``(1, 0, 1)`` or an integer array.
        0 = contracted (flexible), 1 = extended (rigid).
    modules : int, optional
        Required length m.

    Raises
    ------
    ValueError
        For entries other than 0/1, or the wrong length.
    """
    allowed = "0 (contracted) or 1 (extended) for each module, base first"
    if isinstance(value, str):
        digits = [c for c in value if c not in "()[] ,"]
        if not digits or any(c not in "01" for c in digits):
            raise ValueError(f"configuration = {value!r} is invalid: must be {allowed}, e.g. '101'")
        states = tuple(int(c) for c in digits)
    else:
        try:
            array = np.asarray(value)
            ok = (array.ndim == 1 and array.size > 0 and array.dtype != bool
                  and np.isin(array, (0, 1)).all())
        except (TypeError, ValueError):  # ragged or unhashable entries
            ok = False
        if not ok:
            raise ValueError(f"configuration = {show(value)} is invalid: must be {allowed}")
        states = tuple(int(v) for v in array)
    if modules is not None and len(states) != modules:
        raise ValueError(f"configuration = {value!r} is invalid: must have {modules} entries "
                         f"(one per module), not {len(states)}")
    return states


def configuration_name(configuration) -> str:
    """``(1, 0, 1)`` -> ``"101"``, the thesis's way of naming configurations."""
    return "".join(str(int(s)) for s in configuration)


#: Most modules whose ``2**modules`` configurations are listed (65536); a longer arm's
#: searches (inverse kinematics, workspaces) take the configurations to consider instead.
MAX_LISTED_MODULES = 16


def all_configurations(modules: int) -> list:
    """Every configuration of ``modules`` modules in binary order (000, 001, ..., 111).

    Raises
    ------
    ValueError
        For ``modules`` < 1 or above :data:`MAX_LISTED_MODULES` (2**modules entries).
    """
    modules = as_integer("modules", modules, minimum=1)
    if modules > MAX_LISTED_MODULES:
        raise ValueError(f"modules = {modules} is invalid for listing every configuration "
                         f"(2**{modules} of them): must be <= {MAX_LISTED_MODULES}; name the "
                         "configurations to consider instead")
    return [tuple(c) for c in itertools.product((0, 1), repeat=modules)]
