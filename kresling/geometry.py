"""Generalized Kresling cell geometry (thesis chapter 2, eqns 1-9).

A cell is two regular ``n``-gons of circumradius ``R``; the top one is twisted by ``alpha``
and raised by ``L(alpha)``. The design variables are ``n``, ``R``, the angle ratio ``lam``
(0.5 < lam < 1) and the contracted height ``Lc``; every other length and angle follows.
The computations run in the C++ core (``kresling._core.geometry``).

Units: mm and rad.
"""

from __future__ import annotations

import math

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, as_integer, as_integer_array, as_real, show

__all__ = ["Design", "design_quantities", "STATES", "state_index", "as_design"]

#: The two stable states by name; the integer codes are the thesis's (0 and 1).
STATES = {"contracted": 0, "extended": 1}

_DERIVED = tuple(_core.geometry.DERIVED_NAMES)


def state_index(state) -> int:
    """Return the thesis's code of a stable state: 0 (contracted) or 1 (extended).

    Parameters
    ----------
    state : {0, 1, "contracted", "extended"}
    """
    if isinstance(state, str):
        if state.lower() in STATES:
            return STATES[state.lower()]
    elif isinstance(state, (int, np.integer)) and not isinstance(state, bool) and state in (0, 1):
        return int(state)
    raise ValueError(
        f"state = {state!r} is invalid: must be 0 or 'contracted', 1 or 'extended'"
    )


class Design:
    """A generalized Kresling cell.

    Parameters
    ----------
    n : int
        Number of sides of the base polygon, ``n >= 3``.
    lam : float
        Angle ratio lambda, ``0.5 < lam < 1``.
    Lc : float
        Contracted height in mm, ``Lc >= 0`` (``Lc = 0`` is the traditional Kresling).
    R : float, default 30.0
        Circumradius of the base polygon in mm, ``R > 0`` (the thesis uses 30 mm).
    chirality : {+1, -1}, default +1
        Handedness of the twist (the sign of lambda in the thesis's code).

    Raises
    ------
    ValueError
        If a parameter is outside the design space; the message names it.

    Notes
    -----
    Derived quantities (attributes, mm and rad), docs/thesis_equations.md, 'Geometry':

    ``phi = pi/n``; ``gamma = pi (n-2) / (2n)`` (eqn 2); polygon side ``P`` (eqn 1);
    traditional creases ``V`` and ``M`` (eqns 3-4); generalized creases ``Vg``, ``Mg``
    (eqns 6-7); flat-pattern facet angle ``theta_g`` (eqn 5); twists ``alpha0`` (contracted)
    and ``alpha_e`` (extended); extended height ``Le``; facet angles ``psi_con`` and
    ``psi_ext`` (interior dihedral between a perimeter triangle and the base polygon).

    Examples
    --------
    >>> d = Design(n=10, lam=0.9, Lc=15.0)
    >>> round(d.Le, 10), round(2 * d.Le, 3)
    (55.8194667798, 111.639)
    >>> bool(abs(d.height_at(d.alpha_e) - d.Le) < 1e-12)
    True
    """

    __slots__ = ("_core", "_derived")

    def __init__(self, n: int, lam: float, Lc: float, R: float = 30.0, chirality: int = 1):
        n = as_integer("n", n, minimum=3)
        chirality = as_integer("chirality", chirality)
        self._core = _core.geometry.Design(
            n, as_real("R", R), as_real("lam", lam), as_real("Lc", Lc), chirality
        )
        self._derived = self._core.derived()

    # -- design variables ------------------------------------------------------------
    @property
    def n(self) -> int:
        """Number of sides of the base polygon."""
        return self._core.n

    @property
    def lam(self) -> float:
        """Angle ratio lambda."""
        return self._core.lam

    @property
    def Lc(self) -> float:
        """Contracted height [mm]."""
        return self._core.Lc

    @property
    def R(self) -> float:
        """Circumradius of the base polygon [mm]."""
        return self._core.R

    @property
    def chirality(self) -> int:
        """Handedness, +1 or -1."""
        return self._core.chirality

    # -- derived quantities ----------------------------------------------------------
    phi = property(lambda self: self._derived["phi"], doc="pi / n [rad].")
    gamma = property(lambda self: self._derived["gamma"], doc="Half the polygon's internal angle [rad], eqn 2.")
    P = property(lambda self: self._derived["P"], doc="Polygon side [mm], eqn 1.")
    V = property(lambda self: self._derived["V"], doc="Traditional valley crease [mm], eqn 3.")
    M = property(lambda self: self._derived["M"], doc="Traditional mountain crease [mm], eqn 4.")
    Vg = property(lambda self: self._derived["Vg"], doc="Generalized valley crease [mm], eqn 6.")
    Mg = property(lambda self: self._derived["Mg"], doc="Generalized mountain crease [mm], eqn 7.")
    theta_g = property(lambda self: self._derived["theta_g"], doc="Flat-pattern facet angle between P and Vg [rad], eqn 5.")
    alpha0 = property(lambda self: self._derived["alpha0"], doc="Twist at the contracted state, 2 lam gamma [rad].")
    alpha_e = property(lambda self: self._derived["alpha_e"], doc="Twist at the extended state, pi - alpha0 - 2 phi [rad].")
    Le = property(lambda self: self._derived["Le"], doc="Extended height [mm].")
    psi_con = property(lambda self: self._derived["Psi_con"], doc="Facet angle Psi in the contracted state [rad].")
    psi_ext = property(lambda self: self._derived["Psi_ext"], doc="Facet angle Psi in the extended state [rad].")

    @property
    def psi_ratio(self) -> float:
        """Facet-angle ratio Psi_ext / Psi_con (compared with the K_B ratio in section 3.4).

        ``inf`` when ``Lc = 0``: the traditional Kresling folds flat (Psi_con = 0); also
        where the ratio exceeds the largest float (Psi_con below about 1e-308 rad, i.e.
        ``Lc / R`` below about 1e-308): the ratio is then beyond what a float holds, and
        ``inf`` is its rounding, as IEEE arithmetic rounds an overflow.
        """
        return self.psi_ext / self.psi_con if self.psi_con > 0.0 else math.inf

    # -- states and the kinematic path -----------------------------------------------
    def twist(self, state) -> float:
        """Unsigned twist of the top polygon in a stable state [rad] (``state``: 0/1 or name)."""
        return self._core.twist(state_index(state))

    def height(self, state) -> float:
        """Cell height in a stable state [mm]: ``Lc`` (0, contracted) or ``Le`` (1, extended)."""
        return self._core.height(state_index(state))

    def height_at(self, alpha):
        """Cell height L(alpha) on the truss path, eqn 8.

        Parameters
        ----------
        alpha : float or array_like
            Twist [rad]; between ``alpha_e`` and ``alpha0`` on the path between the states.

        Returns
        -------
        float or ndarray
            Height [mm], same shape as ``alpha``.

        Raises
        ------
        ValueError
            Where L(alpha)^2 < 0 (a twist the valley creases cannot reach) or alpha is not finite.
        """
        return _scalar_or_array(self._core.height_at, alpha)

    def mountain_length_at(self, alpha):
        """Mountain bar length m(alpha) on the truss path [mm], eqn 9; shape of ``alpha``."""
        return _scalar_or_array(self._core.mountain_length_at, alpha)

    def facet_angle_at(self, alpha):
        """Facet angle Psi at twist ``alpha`` on the truss path [rad]; shape of ``alpha``."""
        return _scalar_or_array(self._core.facet_angle_at, alpha)

    def vertices(self, state) -> np.ndarray:
        """Polygon vertices of the cell in a stable state.

        Bottom vertex ``i`` at angle ``2 pi i / n`` in the plane z = 0; top vertex ``i`` at
        ``2 pi i / n + chirality * twist(state)`` and height ``height(state)``.

        Returns
        -------
        ndarray, shape (2, n, 3)
            ``[0]`` the bottom polygon, ``[1]`` the top polygon, in mm.
        """
        angles = 2.0 * np.pi * np.arange(self.n) / self.n
        twist = self.chirality * self.twist(state)
        out = np.zeros((2, self.n, 3))
        out[0, :, 0], out[0, :, 1] = self.R * np.cos(angles), self.R * np.sin(angles)
        out[1, :, 0], out[1, :, 1] = self.R * np.cos(angles + twist), self.R * np.sin(angles + twist)
        out[1, :, 2] = self.height(state)
        return out

    # -- conveniences ----------------------------------------------------------------
    def mirrored(self) -> "Design":
        """The same design with the opposite chirality."""
        return Design(self.n, self.lam, self.Lc, self.R, -self.chirality)

    def quantities(self) -> dict:
        """Design variables and every derived quantity as a ``dict`` (mm, rad)."""
        out = {"n": self.n, "R": self.R, "lam": self.lam, "Lc": self.Lc, "chirality": self.chirality}
        out.update(self._derived)
        out["Psi_ratio"] = self.psi_ratio
        return out

    def _key(self):
        return (self.n, self.lam, self.Lc, self.R, self.chirality)

    def __reduce__(self):
        return (Design, self._key())

    def __eq__(self, other):
        return isinstance(other, Design) and self._key() == other._key()

    def __hash__(self):
        return hash(self._key())

    def __repr__(self):
        return (
            f"Design(n={self.n}, lam={self.lam!r}, Lc={self.Lc!r}, R={self.R!r}, "
            f"chirality={self.chirality:+d})"
        )


def as_design(value, name: str = "design") -> Design:
    """``value`` if it is a :class:`Design`; otherwise a ValueError naming ``name``.

    >>> as_design((10, 0.9, 15))
    Traceback (most recent call last):
    ...
    ValueError: design = (10, 0.9, 15) is invalid: must be a kresling.Design, e.g. Design(n=10, lam=0.9, Lc=15)
    """
    if not isinstance(value, Design):
        raise ValueError(f"{name} = {show(value)} is invalid: must be a kresling.Design, e.g. "
                         "Design(n=10, lam=0.9, Lc=15)")
    return value


def _scalar_or_array(function, alpha):
    array = as_float_array("alpha", alpha)
    result = function(array)
    return float(result) if array.ndim == 0 else result


def design_quantities(n, lam, Lc, R=30.0) -> dict:
    """Derived quantities of many designs in one call (vectorised in C++).

    Parameters
    ----------
    n, lam, Lc, R : array_like
        Design variables, broadcast against each other (see :class:`Design` for units and
        ranges). ``n`` must hold integers.

    Returns
    -------
    dict of str to ndarray
        Keys ``n, R, lam, Lc`` (the broadcast inputs) and ``phi, gamma, P, V, M, Vg, Mg,
        theta_g, alpha0, alpha_e, Le, Psi_con, Psi_ext, Psi_ratio``; every array has the
        broadcast shape. ``Psi_ratio`` is ``inf`` where ``Lc = 0`` (Psi_con = 0) or where it
        exceeds the largest float (see :attr:`Design.psi_ratio`).

    Raises
    ------
    ValueError
        If any design is invalid; the message names the parameter and its flat index,
        e.g. ``lam[12] = 1.2``.

    Examples
    --------
    The thesis's 100 x 100 grid for n = 10:

    >>> import numpy as np
    >>> Lc, lam = np.meshgrid(np.linspace(15, 60, 100), np.linspace(0.7, 0.9, 100))
    >>> q = design_quantities(10, lam, Lc)
    >>> q["Le"].shape
    (100, 100)
    """
    arrays = [as_float_array(name, value) if name != "n" else np.asarray(value)
              for name, value in (("n", n), ("lam", lam), ("Lc", Lc), ("R", R))]
    try:
        n_b, lam_b, Lc_b, R_b = np.broadcast_arrays(*arrays)
    except ValueError as error:
        raise ValueError(f"n, lam, Lc, R have shapes {[a.shape for a in arrays]} that do not "
                         f"broadcast together ({error})") from None
    shape = n_b.shape
    n_flat = as_integer_array("n", n_b.ravel())
    table = _core.geometry.derive_table(n_flat, R_b.ravel(), lam_b.ravel(), Lc_b.ravel())
    out = {
        "n": n_flat.reshape(shape).astype(int),
        "R": R_b.astype(float).copy(),
        "lam": lam_b.astype(float).copy(),
        "Lc": Lc_b.astype(float).copy(),
    }
    for k, name in enumerate(_DERIVED):
        out[name] = table[:, k].reshape(shape)
    with np.errstate(divide="ignore", over="ignore"):  # Lc -> 0 folds flat: ratio -> inf
        out["Psi_ratio"] = out["Psi_ext"] / out["Psi_con"]
    return out
