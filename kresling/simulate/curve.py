"""The curve a simulation's view plots beside its scene.

By default: under displacement control, the drive's reaction against the driven
displacement (one driven DOF: its ``reaction_<node>_<axis>`` column of history.csv against
its displacement; several: the sum of their reactions weighted by their share of the
motion, the force that does the drive's work over the driven displacement of the largest
component); under force control and MGDCM, the load factor against the monitored
displacement (``[analysis.stop]``), else against the displacement that grows largest; a
fold (``method = "fold"``), the stored energy against the fold's progress in per cent (100
per stage); a motion in time (``method = "dynamic"``), the monitored displacement (or the
one that grows largest) against time.
``[output] curve = { x = "...", y = "..." }`` names any two quantities instead: a column of
history.csv (``step``, ``load_factor``, ``reaction_<node>_<axis>``, ``energy_bars``, ...,
``iterations``) or ``u_<node>_<axis>``, the displacement of any node [mm].
"""

from __future__ import annotations

import re

import numpy as np

__all__ = ["path_curve", "quantity", "moving_dof"]

_AXES = "xyz"
_DISPLACEMENT = re.compile(r"u_(\d+)_([xyz])")
_UNITS = {"step": "-", "load_factor": "-", "iterations": "-", "time": "s",
          "work_external": "N*mm"}


def quantity(simulation, name, columns) -> tuple:
    """``(values (S,), label)`` of a named quantity: a history column or ``u_<node>_<axis>``.

    Raises
    ------
    ValueError
        For a name that is neither, listing the columns there are.
    """
    match = _DISPLACEMENT.fullmatch(name)
    if match:
        node, axis = int(match.group(1)), match.group(2)
        dof = 3 * node + _AXES.index(axis)
        return (np.asarray(simulation.path.displacement)[:, dof],
                f"u{axis} of node {node} [mm]")
    if name not in columns:
        raise ValueError(f"{simulation.problem.source}: [output] key 'curve' names {name!r}, "
                         f"which is not a quantity of this run: allowed are "
                         f"{sorted(columns)} and u_<node>_<axis>")
    unit = "N" if name.startswith("reaction_") else "N*mm" if name.startswith("energy_") \
        else _UNITS.get(name, "mm")
    return np.asarray(columns[name], dtype=float), f"{name} [{unit}]"


def path_curve(simulation, columns) -> tuple:
    """``(x, y, x_label, y_label)`` of the view's curve, one value per increment.

    Parameters
    ----------
    simulation : kresling.simulate.Simulation
    columns : dict
        ``simulation.history_columns()``.
    """
    named = simulation.problem.output.curve
    if named is not None:
        (x, x_label), (y, y_label) = (quantity(simulation, n, columns) for n in named)
        return x, y, x_label, y_label
    return simulation.problem.method.curve(simulation, columns)


def moving_dof(simulation, stop):
    """The monitored DOF's displacement (or, without a monitor, the DOF that moves most)
    [mm] and its label."""
    if stop is not None:
        return (np.asarray(simulation.path.displacement)[:, stop.dof],
                f"u{stop.axis} of node {stop.node} [mm]")
    u = np.asarray(simulation.path.displacement, dtype=float)
    dof = int(np.argmax(np.abs(u).max(axis=0)))
    node, axis = divmod(dof, 3)
    return u[:, dof], f"u{_AXES[axis]} of node {node} [mm] (moves most)"
