"""Natural frequencies of one cell in its two states: the stiffness switch as a frequency.

The cell is the snap-through test's (bottom polygon's ``n + 1`` nodes held, the thesis's
laminate as its mass, :mod:`kresling.analyses.laminate`); its modes
(:func:`kresling.analyses.modes.vibration_modes`) are taken about three states:

- **extended**: built stress-free extended, at rest;
- **contracted**: built stress-free contracted, at rest (how a cell made contracted would
  ring);
- **snapped**: the extended cell's second stable state, where the static snap-through
  test comes to rest (prestressed, and tilted for the thesis's optimum): the contracted
  state a built-extended cell actually reaches.

For the same mass, a frequency ratio ``r`` is a stiffness ratio ``r^2``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling._validation import as_integer
from kresling.analyses.modes import Modes, vibration_modes
from kresling.analyses.snap_dynamics import snap_test_cell
from kresling.geometry import Design, as_design

__all__ = ["CellFrequencies", "cell_frequencies"]


@dataclass(frozen=True)
class CellFrequencies:
    """The lowest modes of one cell about its states.

    Attributes
    ----------
    design : Design
    extended, contracted : Modes
        About the stress-free extended and contracted cells.
    snapped : Modes or None
        About the static snap-through test's second stable state (None when the cell is
        not bistable).
    mass : float
        The cell's mass [t] (the held bottom polygon's share included).
    """

    design: Design
    extended: Modes
    contracted: Modes
    snapped: Modes | None
    mass: float

    @property
    def ratio(self) -> float:
        """Lowest frequency extended over contracted (both stress-free)."""
        return float(self.extended.frequencies_hz[0] / self.contracted.frequencies_hz[0])

    @property
    def snapped_ratio(self) -> float:
        """Lowest frequency extended over snapped (NaN when not bistable)."""
        if self.snapped is None:
            return float("nan")
        return float(self.extended.frequencies_hz[0] / self.snapped.frequencies_hz[0])

    def rows(self) -> list:
        """One dict per mode: ``mode`` (1-based), the three states' frequencies [Hz] and the
        extended state's effective mass fractions along x, y, z."""
        out = []
        for i in range(self.extended.count):
            row = {"mode": i + 1,
                   "extended_hz": float(self.extended.frequencies_hz[i]),
                   "contracted_hz": float(self.contracted.frequencies_hz[i]),
                   "snapped_hz": (float(self.snapped.frequencies_hz[i])
                                  if self.snapped is not None else None)}
            for a, axis in enumerate("xyz"):
                row[f"extended_mass_{axis}"] = float(self.extended.effective_mass_fraction[i, a])
            out.append(row)
        return out


def cell_frequencies(design: Design, *, k: int = 6, parameters=None) -> CellFrequencies:
    """The ``k`` lowest natural frequencies of one cell extended, contracted and snapped.

    Parameters
    ----------
    design : Design
    k : int, default 6
        Modes per state (1 to 30).
    parameters : SpecimenParameters, optional
        Stiffness assignment (the thesis's by default).

    Returns
    -------
    CellFrequencies

    Examples
    --------
    >>> from kresling import Design
    >>> f = cell_frequencies(Design(10, 0.9, 15, 30), k=2)
    >>> round(f.ratio, 2)
    2.09
    """
    from kresling.analyses.snap_through import SnapThroughTester

    design = as_design(design)
    k = as_integer("k", k, minimum=1, maximum=30)
    extended, masses = snap_test_cell(design, parameters, "extended")
    contracted, contracted_masses = snap_test_cell(design, parameters, "contracted")
    tester = SnapThroughTester(design.n, parameters=parameters)
    core = tester._core.run(design._core)
    snapped = None
    if core.bistable:
        state = np.asarray(core.stable_state)
        snapped = vibration_modes(extended.model, masses, k, u=state)
    return CellFrequencies(design, vibration_modes(extended.model, masses, k),
                           vibration_modes(contracted.model, contracted_masses, k),
                           snapped, float(masses.sum()))
