"""Per-element fields drawn as colours on the edges: bar strain, hinge angle change and
stored energy.

Each field lives on edges (node pairs). An edge can carry several elements (MERLIN2's
topology puts one bar and one hinge on every pair of triangles sharing an edge, and every
hinge's axis is also a bar):

================================  ============  ===========================================
field                             unit          value of an edge
================================  ============  ===========================================
``"bar_strain"``                  [-]           the strain of its bar (of largest magnitude
                                                if it has several); every bar's edge
``"hinge_angle_change"``          [deg]         ``theta - theta_rest`` of its hinge,
                                                wrapped to (-180, 180] (of largest
                                                magnitude if several); every hinge's axis;
                                                positive: the hinge opens
``"energy"``                      [N*mm]        the energy stored in all its bars and
                                                hinges: the values add up to the model's
                                                total stored energy
================================  ============  ===========================================
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core

__all__ = ["FIELDS", "Field", "field_edges", "edge_values", "element_energy",
           "hinge_angle_change", "significant_decimals"]


@dataclass(frozen=True)
class Field:
    """How a field is shown.

    Attributes
    ----------
    label : str
        Colour bar title, with the unit.
    colorscale : str
        Plotly colour scale.
    signed : bool
        Diverging scale centred on zero (else it starts at zero).
    """

    label: str
    colorscale: str
    signed: bool


#: The fields a view can colour edges by.
FIELDS = {
    "bar_strain": Field("bar strain [-]", "RdBu_r", True),
    "hinge_angle_change": Field("hinge angle change [deg]", "PuOr_r", True),
    "energy": Field("stored energy [N·mm]", "Viridis", False),
}


def check_field(field):
    """``field`` if it is None or one of :data:`FIELDS`; else a ValueError."""
    if field is not None and (not isinstance(field, str) or field not in FIELDS):
        raise ValueError(f"field = {field!r} is invalid: must be None or one of "
                         f"{sorted(FIELDS)}")
    return field


def _edges_of(pairs):
    pairs = np.sort(np.asarray(pairs, dtype=np.int64).reshape(-1, 2), axis=1)
    if not len(pairs):
        return np.zeros((0, 2), dtype=np.int64), np.zeros(0, dtype=np.int64)
    edges, inverse = np.unique(pairs, axis=0, return_inverse=True)
    return edges, inverse.ravel()


def field_edges(model, field: str):
    """The edges a field colours and which elements lie on each.

    Parameters
    ----------
    model : kresling.model.Model
    field : str
        One of :data:`FIELDS`.

    Returns
    -------
    edges : ndarray of int, shape (E, 2)
        Sorted node pairs.
    bar_edge : ndarray of int, shape (B,)
        Edge of every bar (-1: not shown).
    hinge_edge : ndarray of int, shape (H,)
        Edge of every hinge's axis (-1: not shown).
    """
    check_field(field)
    bars, axes = np.asarray(model.bars), np.asarray(model.hinges)[:, :2]
    if field == "bar_strain":
        edges, bar_edge = _edges_of(bars)
        return edges, bar_edge, np.full(len(axes), -1, dtype=np.int64)
    if field == "hinge_angle_change":
        edges, hinge_edge = _edges_of(axes)
        return edges, np.full(len(bars), -1, dtype=np.int64), hinge_edge
    edges, inverse = _edges_of(np.vstack([bars.reshape(-1, 2), axes.reshape(-1, 2)]))
    return edges, inverse[:len(bars)], inverse[len(bars):]


def hinge_angle_change(model, hinge_angle) -> np.ndarray:
    """``hinge_angle - hinge_rest_angle`` wrapped to (-180, 180] [deg], shape (H,)."""
    change = np.asarray(hinge_angle, dtype=float) - model.hinge_rest_angle
    change = -np.remainder(-change + np.pi, 2 * np.pi) + np.pi  # (-pi, pi]
    return np.degrees(change)


def element_energy(model, u=None) -> dict:
    """Energy stored in every bar and every hinge at displacement ``u``.

    Parameters
    ----------
    model : kresling.model.Model
    u : array_like, shape (3N,) or (N, 3), optional
        Displacement [mm]; default zero.

    Returns
    -------
    dict
        ``bars`` (B,) and ``hinges`` (H,) [N*mm]; their sums are a path's
        ``energy_bars`` and ``energy_hinges``.
    """
    x = np.asarray(model.nodes, dtype=float)
    if u is not None:
        x = x + np.asarray(u, dtype=float).reshape(-1, 3)
    bars = np.asarray(model.bars)
    bar_energy = np.array([
        _core.elements.bar_response(x[p], x[q], float(area), float(rest), int(law),
                                    float(modulus))[0]
        for (p, q), area, rest, law, modulus in zip(
            bars.tolist(), model.bar_area, model.bar_rest_length, model.bar_law,
            model.bar_modulus)], dtype=float)
    theta = model.element_state(None if u is None else np.ravel(u))["hinge_angle"]
    hinge_energy = np.array([
        length * _core.elements.spring_law(int(law), float(t), float(rest), float(k),
                                           float(t1), float(t2))[2]
        for t, rest, k, length, law, (t1, t2) in zip(
            theta, model.hinge_rest_angle, model.hinge_stiffness, model.hinge_length,
            model.hinge_law, model.hinge_limits)], dtype=float)
    return {"bars": bar_energy.reshape(len(bars)), "hinges": hinge_energy.reshape(len(theta))}


def _largest_magnitude(values, edge, count):
    out = np.zeros(count)
    best = np.full(count, -1.0)
    for value, e in zip(values, edge):
        if e >= 0 and abs(value) > best[e]:
            best[e], out[e] = abs(value), value
    return out


def edge_values(model, field: str, u=None, *, edges=None) -> np.ndarray:
    """A field's value on every edge of :func:`field_edges` at displacement ``u``.

    Parameters
    ----------
    model : kresling.model.Model
    field : str
        One of :data:`FIELDS` (see the module's table for units and definitions).
    u : array_like, shape (3N,), optional
        Displacement [mm]; default zero.
    edges : tuple, optional
        :func:`field_edges`'s result, to reuse it.

    Returns
    -------
    ndarray, shape (E,)
    """
    edges, bar_edge, hinge_edge = edges if edges is not None else field_edges(model, field)
    if field == "energy":
        energy = element_energy(model, u)
        out = np.zeros(len(edges))
        np.add.at(out, bar_edge, energy["bars"])
        np.add.at(out, hinge_edge, energy["hinges"])
        return out
    state = model.element_state(u)
    if field == "bar_strain":
        return _largest_magnitude(state["bar_strain"], bar_edge, len(edges))
    return _largest_magnitude(hinge_angle_change(model, state["hinge_angle"]), hinge_edge,
                              len(edges))


def significant_decimals(values, digits: int = 6) -> int:
    """Decimals that keep ``digits`` significant digits of the largest ``|values|``."""
    largest = float(np.nanmax(np.abs(values))) if np.size(values) else 0.0
    if not np.isfinite(largest) or largest == 0.0:
        return digits
    return int(digits - np.floor(np.log10(largest)) - 1)
