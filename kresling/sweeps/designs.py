"""The designs a sweep runs over: a grid over n x Lc x lambda, or any list of designs.

A :class:`DesignSet` is four aligned columns (``n, Lc, lam, R``); its :attr:`~DesignSet.key`
identifies it exactly (a hash of the values), which is how a sweep directory knows it is
being resumed with the same designs.
"""

from __future__ import annotations

import hashlib
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from kresling._validation import as_float_array, as_integer, as_integer_array, as_real, show
from kresling.geometry import Design, design_quantities

__all__ = ["DesignSet", "design_grid", "as_design_set", "THESIS_N", "THESIS_LAM"]

#: The thesis's study (section 3.4): n in {4, 6, 8, 10}, lambda in [0.7, 0.9], and
#: Lc in [R/2, 2R] (15-60 mm for R = 30 mm).
THESIS_N = (4, 6, 8, 10)
THESIS_LAM = (0.7, 0.9)


@dataclass(frozen=True)
class DesignSet:
    """Designs as aligned columns.

    Attributes
    ----------
    n : ndarray of int, shape (N,)
    Lc, lam, R : ndarray of float, shape (N,)
        Contracted height [mm], angle ratio, circumradius [mm].
    spec : dict
        How the set was made (the grid's arguments, or ``{"kind": "list"}``); kept in a
        sweep's manifest for people to read.
    """

    n: np.ndarray
    Lc: np.ndarray
    lam: np.ndarray
    R: np.ndarray
    spec: dict = field(default_factory=lambda: {"kind": "list"})

    def __post_init__(self):
        sizes = {len(self.n), len(self.Lc), len(self.lam), len(self.R)}
        if len(sizes) != 1:
            raise ValueError(f"n, Lc, lam and R must have one length, got {sorted(sizes)}")

    def __len__(self) -> int:
        return len(self.n)

    def design(self, i: int) -> Design:
        """The ``i``-th design as a :class:`~kresling.Design`."""
        return Design(int(self.n[i]), float(self.lam[i]), float(self.Lc[i]), float(self.R[i]))

    def __iter__(self):
        return (self.design(i) for i in range(len(self)))

    @property
    def key(self) -> str:
        """SHA-256 of the exact values (float bits), in order: equal keys, equal designs."""
        digest = hashlib.sha256()
        digest.update(np.asarray(self.n, dtype="<i8").tobytes())
        for column in (self.Lc, self.lam, self.R):
            digest.update(np.asarray(column, dtype="<f8").tobytes())
        return digest.hexdigest()


#: Points along each axis of a grid, and designs in one sweep, at most (the thesis's study is
#: 100 x 100 x 4 = 40 000 designs).
MAX_GRID_SIZE = 10_000
MAX_DESIGNS = 10_000_000


def design_grid(n=THESIS_N, size=100, *, Lc=None, lam=THESIS_LAM, R=30.0) -> DesignSet:
    """An evenly spaced grid over Lc x lambda for each n (the thesis's study by default).

    Parameters
    ----------
    n : int or sequence of int, default (4, 6, 8, 10)
        Sides of the base polygon.
    size : int or (int, int), default 100
        Points along Lc and along lambda (one number: both).
    Lc : (float, float), optional
        Range of the contracted height [mm], ends included; default ``(R/2, 2R)``.
    lam : (float, float), default (0.7, 0.9)
        Range of the angle ratio, ends included.
    R : float, default 30
        Circumradius [mm].

    Returns
    -------
    DesignSet
        ``len(n) * size_Lc * size_lam`` designs ordered by n, then Lc, then lambda (fastest).

    Raises
    ------
    ValueError
        For an empty grid, a size below 1, a reversed range, or a design outside the design
        space (the message names the parameter).

    Examples
    --------
    >>> grid = design_grid((8, 10), 5)
    >>> len(grid), float(grid.Lc.min()), float(grid.Lc.max()), float(grid.lam.max())
    (50, 15.0, 60.0, 0.9)
    """
    ns = [as_integer("n", k, minimum=3) for k in np.atleast_1d(n)]
    if not ns:
        raise ValueError("n is empty: the grid needs at least one polygon size")
    sizes = np.atleast_1d(size)
    if len(sizes) == 1:
        sizes = np.repeat(sizes, 2)
    if len(sizes) != 2:
        raise ValueError(f"size = {size!r} is invalid: must be one or two integers")
    n_Lc, n_lam = (as_integer("size", s, minimum=1, maximum=MAX_GRID_SIZE) for s in sizes)
    if len(ns) * n_Lc * n_lam > MAX_DESIGNS:
        raise ValueError(f"size = {show(size)} is invalid with {len(ns)} n: the grid would hold "
                         f"{len(ns) * n_Lc * n_lam} designs; must hold at most {MAX_DESIGNS}")
    R = as_real("R", R)
    Lc = (R / 2, 2 * R) if Lc is None else Lc
    Lc_values = _axis("Lc", Lc, n_Lc)
    lam_values = _axis("lam", lam, n_lam)
    N, L, A = np.meshgrid(ns, Lc_values, lam_values, indexing="ij")
    spec = {"kind": "grid", "n": ns, "size": [n_Lc, n_lam], "Lc": [float(v) for v in Lc],
            "lam": [float(v) for v in lam], "R": R}
    return _checked(N.ravel(), L.ravel(), A.ravel(), np.full(N.size, R), spec)


def _axis(name, bounds, count) -> np.ndarray:
    try:
        low, high = (as_real(name, v) for v in bounds)
    except (TypeError, ValueError):  # not a pair (None, 3 numbers), or not numbers
        raise ValueError(f"{name} = {show(bounds)} is invalid: must be a (low, high) pair of "
                         "numbers") from None
    if not low <= high or (count > 1 and low == high):
        raise ValueError(f"{name} = ({low}, {high}) is invalid: must be an increasing range")
    return np.array([low]) if count == 1 else np.linspace(low, high, count)


def as_design_set(designs) -> DesignSet:
    """Normalise what :func:`~kresling.sweeps.sweep` accepts to a :class:`DesignSet`.

    Parameters
    ----------
    designs : DesignSet, iterable of Design, or mapping
        A mapping needs keys ``n``, ``Lc`` and ``lam`` (``R`` optional, 30 mm), each
        array_like of one length.

    Raises
    ------
    ValueError
        If there are no designs, or one is outside the design space.
    """
    if isinstance(designs, DesignSet):
        if len(designs) == 0:
            raise ValueError("the design set is empty: nothing to sweep")
        return designs
    if isinstance(designs, Mapping):
        missing = [k for k in ("n", "Lc", "lam") if k not in designs]
        if missing:
            raise ValueError(f"designs is missing the column(s) {', '.join(missing)}")
        n = np.atleast_1d(np.asarray(designs["n"]))
        try:
            R = np.broadcast_to(as_float_array("R", designs.get("R", 30.0)), n.shape)
        except ValueError as error:
            raise ValueError(f"designs['R'] does not match designs['n'] ({error})") from None
        return _checked(n, np.atleast_1d(as_float_array("Lc", designs["Lc"])),
                        np.atleast_1d(as_float_array("lam", designs["lam"])), R,
                        {"kind": "list"})
    if isinstance(designs, (Design, str, bytes)):
        raise ValueError("designs must be a collection of designs (wrap one Design in a list)")
    if not hasattr(designs, "__iter__"):
        raise ValueError(f"designs = {designs!r} is invalid: must be Design objects, a DesignSet "
                         "or a mapping of columns")
    items = list(designs)
    bad = [type(d).__name__ for d in items if not isinstance(d, Design)]
    if bad:
        raise ValueError(f"designs must be Design objects, a DesignSet or a mapping of columns; "
                         f"got {bad[0]}")
    return _checked(np.array([d.n for d in items]), np.array([d.Lc for d in items]),
                    np.array([d.lam for d in items]), np.array([d.R for d in items]),
                    {"kind": "list"})


def _checked(n, Lc, lam, R, spec) -> DesignSet:
    if len(n) == 0:
        raise ValueError("the grid is empty: nothing to sweep")
    n = as_integer_array("n", n).astype(np.int64)
    Lc, lam, R = (np.asarray(v, dtype=float) for v in (Lc, lam, R))
    design_quantities(n, lam, Lc, R)  # raises ValueError naming the first invalid design
    return DesignSet(n, Lc, lam, R, spec)
