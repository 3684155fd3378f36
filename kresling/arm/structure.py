"""The manipulator as one bar-and-hinge structure: modules, guide plates and tendons.

``m`` modules of two generalized Kresling cells of opposite chirality (their twists cancel),
each module in its own state from a configuration string listed from the base ("010": base
contracted, middle extended, tip contracted). Modules are joined at stiff guide plates that
carry the three tendon holes at radius ``d`` (32 mm), 120 degrees apart, tendon 1 on +x; the
base plate is fixed; three sliding cables run from the base through every guide to the tip
guide, where they are anchored. The cells are the Kresling specimen's (same nodes, bars,
hinges and the thesis's stiffnesses), built in the C++ core (``cpp/kresling/model/arm.hpp``).

As built, every cell is stress-free in its own state and every tendon just taut (rest
length = path length, zero tension): the unloaded arm is stress-free and its tip sits at the
sum of the modules' heights, ``2 Le`` per extended and ``2 Lc`` per contracted module.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from kresling import _core
from kresling._validation import as_integer, as_real, show
from kresling.geometry import Design
from kresling.model import Model, SpecimenParameters, kresling_specimen

__all__ = ["ArmParameters", "Arm", "build_arm", "parse_configuration", "all_configurations",
           "THESIS_DESIGN"]

#: The thesis's optimum cell (n, lam, Lc, R): the default of every arm.
THESIS_DESIGN = (10, 0.9, 15.0, 30.0)


@dataclass(frozen=True)
class ArmParameters:
    """What the arm is made of beyond its cells.

    Parameters
    ----------
    tendon_radius : float, default 32.0
        d [mm]: radius of the tendon holes in the guides (thesis section 4.2).
    guide_radius : float, default 40.0
        Circumradius of the guide plates (regular n-gons aligned with the cells) [mm]. It
        only bounds where the holes may sit; the thesis gives no plate size (an assumption).
    guide_factor : float, default 1e4
        Hinges inside a guide plate get ``guide_factor * kf``: a stiff plate.
    tendon_stiffness : float, default 500.0
        Axial rigidity EA of each tendon [N]. The thesis does not give its tendon's material;
        500 N is a nylon line of about 0.4 mm (an assumption).
    specimen : SpecimenParameters
        The cells' stiffnesses (the thesis's by default).
    contact_distance : float, default 0.0
        d_hat [mm] of contact between the panels (the cells' side triangles and the levels'
        polygons, within and between modules; docs/contact.md, 'Panels in models and
        problem files'); 0: no contact. Below the smallest gap between two panels as built
        (0.60 mm in a contracted module of the thesis's optimum).
    contact_stiffness : float, default 0.0
        The barrier's stiffness kappa [N/mm^3]; > 0 with contact.
    """

    tendon_radius: float = 32.0
    guide_radius: float = 40.0
    guide_factor: float = 1e4
    tendon_stiffness: float = 500.0
    specimen: SpecimenParameters = field(default_factory=SpecimenParameters)
    contact_distance: float = 0.0
    contact_stiffness: float = 0.0

    def __post_init__(self):
        for name in ("tendon_radius", "guide_radius", "guide_factor", "tendon_stiffness",
                     "contact_distance", "contact_stiffness"):
            object.__setattr__(self, name, as_real(name, getattr(self, name)))
        if not isinstance(self.specimen, SpecimenParameters):
            raise ValueError(f"specimen = {show(self.specimen)} is invalid: must be a "
                             "kresling.model.SpecimenParameters")

    def to_core(self):
        """The C++ parameters object (values are range-checked there)."""
        p = _core.model.ArmParameters()
        p.specimen = self.specimen.to_core()
        p.tendon_radius = self.tendon_radius
        p.guide_radius = self.guide_radius
        p.guide_factor = self.guide_factor
        p.tendon_stiffness = self.tendon_stiffness
        p.contact_distance = self.contact_distance
        p.contact_stiffness = self.contact_stiffness
        return p


def parse_configuration(configuration, modules: int | None = None) -> tuple:
    """``"010"`` -> ``(0, 1, 0)``: one character per module from the base, 0 contracted and
    1 extended.

    Raises
    ------
    ValueError
        Naming ``configuration``: not a string, empty, other characters, or (with
        ``modules``) the wrong length.

    Examples
    --------
    >>> parse_configuration("011")
    (0, 1, 1)
    """
    if not isinstance(configuration, str):
        raise ValueError(f"configuration = {show(configuration)} is invalid: must be a string "
                         "of 0 (contracted) and 1 (extended), one per module from the base")
    count = 0 if modules is None else as_integer("modules", modules, minimum=1)
    return tuple(_core.model.parse_configuration(configuration, count))


def all_configurations(modules: int) -> list:
    """Every configuration of ``modules`` modules as strings, "00..0" to "11..1".

    >>> all_configurations(2)
    ['00', '01', '10', '11']
    """
    modules = as_integer("modules", modules, minimum=1)
    return ["".join(c) for c in itertools.product("01", repeat=modules)]


@dataclass(frozen=True, eq=False)
class Arm:
    """An arm's model and where its parts are (build it with :func:`build_arm`).

    Attributes
    ----------
    configuration : str
        Module states from the base.
    design : Design
    parameters : ArmParameters
    model : kresling.model.Model
        Nodes ``k (n+1) + j`` for vertex ``j`` of level ``k`` (centre ``j = n``) as in a
        Kresling specimen, then the tendon holes; three cables (the tendons).
    level_height : ndarray, shape (2 m + 1,)
        z of each level as built [mm]; guide ``g`` is level ``2 g``.
    holes : ndarray of int, shape (m + 1, 3)
        Node of tendon ``t``'s hole in guide ``g`` (row 0: the fixed base).
    slack_length : ndarray, shape (3,)
        Each tendon's path length as built [mm]: its rest length when just taut.
    """

    configuration: str
    design: Design
    parameters: ArmParameters
    model: Model
    level_height: np.ndarray
    holes: np.ndarray
    slack_length: np.ndarray
    _core: object = field(repr=False)

    @property
    def modules(self) -> int:
        return len(self.configuration)

    @property
    def n(self) -> int:
        return self.design.n

    @property
    def tip_node(self) -> int:
        """The tip guide's centre: where tip loads act and the tip position is read."""
        return int(self._core.tip_node)

    @property
    def tip_height(self) -> float:
        """The tip's height as built: the sum of the modules' heights [mm]."""
        return float(self.level_height[-1])

    def node(self, level: int, vertex: int) -> int:
        """Node of perimeter vertex ``vertex`` of ``level`` (its centre for ``vertex = n``)."""
        return int(self._core.node(level, vertex))

    @cached_property
    def hinge_family(self) -> np.ndarray:
        """Family of every hinge (for :mod:`kresling.view`): the cells' as in a Kresling
        specimen ("valley", "mountain", "polygon_edge", "polygon_spoke"), then "guide" for
        the hinges that hold the tendon holes in their plates."""
        states = [int(c) for c in self.configuration for _ in range(2)]
        cells = kresling_specimen(self.design, states, parameters=self.parameters.specimen)
        extra = len(self.model.hinges) - len(cells.hinge_family)
        return np.concatenate([cells.hinge_family, np.full(extra, "guide")])

    def tendon_paths(self, positions=None) -> list:
        """The three tendons' polylines, base to tip, as built or at ``positions`` (N, 3):
        a list of three (m + 1, 3) arrays [mm]."""
        x = self.model.nodes if positions is None else np.asarray(positions)
        return [x[self.holes[:, t]] for t in range(3)]

    def guide_centres(self, positions=None) -> np.ndarray:
        """Centres of the guides (base first), shape (m + 1, 3) [mm], as built or at
        ``positions`` (N, 3)."""
        x = self.model.nodes if positions is None else np.asarray(positions)
        return x[[self.node(2 * g, self.n) for g in range(self.modules + 1)]]


def build_arm(configuration="111", *, n: int = 10, lam: float = 0.9, Lc: float = 15.0,
              R: float = 30.0, design: Design | None = None,
              parameters: ArmParameters | None = None) -> Arm:
    """Build the arm of a configuration.

    Parameters
    ----------
    configuration : str, default "111"
        One character per module from the base: 0 contracted, 1 extended.
    n, lam, Lc, R
        The cell (the thesis's optimum by default: 10, 0.9, 15 mm, 30 mm); ignored when
        ``design`` is given.
    design : Design, optional
    parameters : ArmParameters, optional
        Tendon radius, guides, tendon stiffness, cell stiffnesses.

    Raises
    ------
    ValueError
        Naming the parameter: a bad configuration string, a design out of range, a tendon
        radius that is not positive or puts a hole outside the guide polygon, a guide radius
        below R, non-positive stiffnesses.

    Examples
    --------
    >>> arm = build_arm("010")
    >>> round(arm.tip_height, 4), arm.model.num_nodes, len(arm.model.cable_nodes)
    (171.6389, 89, 3)
    """
    states = parse_configuration(configuration)
    design = Design(n, lam, Lc, R) if design is None else design
    if not isinstance(design, Design):
        raise ValueError(f"design = {show(design)} is invalid: must be a kresling.Design")
    parameters = ArmParameters() if parameters is None else parameters
    if not isinstance(parameters, ArmParameters):
        raise ValueError(f"parameters = {show(parameters)} is invalid: must be an ArmParameters")
    core = _core.model.build_arm(design._core, list(states), parameters.to_core())
    model = Model._from_core(core.model)
    return Arm(configuration, design, parameters, model,
               np.asarray(core.level_height), np.asarray(core.holes, dtype=np.int64),
               np.asarray(core.slack_length), core)
