"""Figures drawn with Matplotlib at build time (``conf.py`` calls :func:`write_all`).

``kresling_cell.svg``: a generalized Kresling cell and its design variables, drawn from the
package's own geometry (``kresling.Design``), so the picture and the code cannot disagree.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from kresling import Design  # noqa: E402

#: The cell drawn: few sides so that the facets can be told apart.
CELL = dict(n=6, lam=0.8, Lc=20.0, R=30.0)
VALLEY, MOUNTAIN, POLYGON = "tab:blue", "tab:red", "0.2"


def _arc(centre, u, v, radius, start, stop, count=30):
    """Points of an arc about ``centre`` in the plane of unit vectors ``u`` and ``v``."""
    t = np.linspace(start, stop, count)[:, None]
    return centre + radius * (np.cos(t) * u + np.sin(t) * v)


def _cell_3d(ax, design: Design) -> None:
    """The folded cell in its extended state, with R, the heights and Psi on one edge."""
    bottom, top = design.vertices("extended")
    n = design.n
    for i in range(n):
        j = (i + 1) % n
        ax.add_collection3d(_facet([bottom[i], bottom[j], top[j]], 0.10))
        ax.add_collection3d(_facet([bottom[i], top[j], top[i]], 0.18))
    closed = lambda points: np.vstack([points, points[:1]])  # noqa: E731
    for ring in (bottom, top):
        ax.plot(*closed(ring).T, color=POLYGON, lw=1.6)
    for i in range(n):
        j = (i + 1) % n
        ax.plot(*np.array([bottom[i], top[i]]).T, color=MOUNTAIN, lw=1.3)   # mountain b_i-t_i
        ax.plot(*np.array([bottom[i], top[j]]).T, color=VALLEY, lw=1.3)     # valley b_i-t_i+1
    # R: centre of the base to a vertex.
    ax.plot([0, bottom[0, 0]], [0, bottom[0, 1]], [0, 0], color="k", lw=1.0, ls="--")
    ax.text(bottom[0, 0] / 2, bottom[0, 1] / 2 - 3, 0, "$R$", fontsize=16)
    # Height: the axis from the base's centre to the top's.
    ax.plot([0, 0], [0, 0], [0, design.Le], color="k", lw=1.0, ls=":")
    ax.text(1.5, 0, design.Le / 2, r"$L_e$ (extended)" "\n" r"$L_c$ (contracted)", fontsize=14)
    # Psi: the interior dihedral along the polygon edge b_k b_k+1, between the base (towards
    # its centre) and the facet (b_k, b_k+1, t_k+1).
    k = n // 2 + 1
    a, b, c = bottom[k], bottom[(k + 1) % n], top[(k + 1) % n]
    mid = (a + b) / 2
    edge = (b - a) / np.linalg.norm(b - a)
    inward = -mid / np.linalg.norm(mid)
    up = c - a - np.dot(c - a, edge) * edge
    up /= np.linalg.norm(up)
    psi = np.arccos(np.clip(np.dot(inward, up), -1.0, 1.0))
    w = np.cross(edge, inward)
    w *= np.sign(np.dot(w, up))
    arc = _arc(mid, inward, w, 9.0, 0.0, psi)
    ax.plot(*arc.T, color="tab:green", lw=2.0)
    for direction in (inward, up):
        ax.plot(*np.array([mid, mid + 13.0 * direction]).T, color="tab:green", lw=0.8)
    label = _arc(mid, inward, w, 13.0, psi / 2, psi / 2, 1)[0]
    ax.text(*label, r"$\Psi$", color="tab:green", fontsize=17)
    ax.text(*(mid + np.array([0, 0, -6.0])), "$P$", fontsize=14)
    ax.set_box_aspect((1, 1, 0.9))
    ax.view_init(elev=18, azim=-62)
    ax.set_axis_off()
    ax.set_title("(a) the folded cell, extended", fontsize=14)


def _facet(points, alpha):
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    return Poly3DCollection([points], facecolor=(0.55, 0.7, 0.9, alpha), edgecolor="none")


def _top_view(ax, design: Design) -> None:
    """Seen from above: the twist alpha of the top polygon against the bottom one."""
    closed = lambda points: np.vstack([points, points[:1]])  # noqa: E731
    for state, style, twist_name in (("contracted", "--", r"\alpha_0"),
                                     ("extended", "-", r"\alpha_e")):
        bottom, top = design.vertices(state)
        if state == "contracted":
            ax.plot(*closed(bottom)[:, :2].T, color=POLYGON, lw=1.6, label="bottom polygon")
        ax.plot(*closed(top)[:, :2].T, color="tab:purple", lw=1.2, ls=style,
                label=f"top polygon, {state}")
        angle = design.twist(state)
        radius = 0.45 * design.R if state == "extended" else 0.7 * design.R
        t = np.linspace(0.0, angle, 40)
        ax.plot(radius * np.cos(t), radius * np.sin(t), color="tab:purple", lw=1.0, ls=style)
        ax.plot([0, top[0, 0]], [0, top[0, 1]], color="tab:purple", lw=0.8, ls=style)
        ax.text(1.12 * radius * np.cos(angle / 2), 1.12 * radius * np.sin(angle / 2),
                f"${twist_name}$", color="tab:purple", fontsize=16, ha="center", va="center")
    bottom, _ = design.vertices("extended")
    ax.plot([0, bottom[0, 0]], [0, bottom[0, 1]], color="k", lw=1.0, ls="--")
    ax.text(0.5 * design.R, -3.5, "$R$", fontsize=16)
    ax.plot([0], [0], "k.")
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(rf"(b) from above: the twist $\alpha$ ($n = {design.n}$)", fontsize=14)


def _flat_facet(ax, design: Design) -> None:
    """The traditional flat facet: the angle lambda*gamma between P and the valley crease."""
    gamma, lam = design.gamma, design.lam
    P = design.P
    b0, b1 = np.array([0.0, 0.0]), np.array([P, 0.0])
    valley = design.V * np.array([np.cos(lam * gamma), np.sin(lam * gamma)])
    ax.fill(*np.array([b0, b1, valley]).T, color=(0.55, 0.7, 0.9, 0.25))
    ax.plot(*np.array([b0, b1]).T, color=POLYGON, lw=1.6)
    ax.plot(*np.array([b0, valley]).T, color=VALLEY, lw=1.4)
    ax.plot(*np.array([b1, valley]).T, color=MOUNTAIN, lw=1.4)
    # gamma: half the polygon's interior angle, the full sector the facet angle is a part of.
    reach = 0.42 * P
    t = np.linspace(0.0, gamma, 40)
    ax.plot(reach * np.cos(t), reach * np.sin(t), color="0.55", lw=1.0, ls=":")
    ax.plot([0, 1.25 * reach * np.cos(gamma)], [0, 1.25 * reach * np.sin(gamma)],
            color="0.55", lw=0.8, ls=":")
    ax.text(1.3 * reach * np.cos(gamma), 1.3 * reach * np.sin(gamma), r"$\gamma$",
            color="0.4", fontsize=16)
    t = np.linspace(0.0, lam * gamma, 40)
    ax.plot(0.3 * P * np.cos(t), 0.3 * P * np.sin(t), color="k", lw=1.2)
    ax.text(0.34 * P * np.cos(lam * gamma / 2), 0.34 * P * np.sin(lam * gamma / 2),
            r"$\lambda\gamma$", fontsize=16, va="center")
    ax.text(P / 2, -0.09 * P, "$P$", ha="center", fontsize=14)
    ax.text(*(0.55 * valley + np.array([-0.12 * P, 0.0])), "$V$", color=VALLEY, fontsize=14)
    ax.text(*((b1 + valley) / 2 + np.array([0.05 * P, 0.0])), "$M$", color=MOUNTAIN,
            fontsize=14)
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title("(c) a traditional flat facet:\n" r"$\lambda$ = angle / $\gamma$", fontsize=14)


def draw_cell(path: Path) -> None:
    design = Design(**CELL)
    fig = plt.figure(figsize=(12.0, 5.0))
    grid = fig.add_gridspec(1, 3, width_ratios=(1.25, 1.0, 0.75), left=0.0, right=0.99,
                            bottom=0.12, top=0.9, wspace=0.08)
    _cell_3d(fig.add_subplot(grid[0], projection="3d"), design)
    _top_view(fig.add_subplot(grid[1]), design)
    _flat_facet(fig.add_subplot(grid[2]), design)
    fig.text(0.5, 0.03, "mountain creases red, valley creases blue; in (b) the bottom polygon "
             "black, the top one purple: solid extended, dashed contracted",
             ha="center", fontsize=12, color="0.3")
    fig.savefig(path, metadata={"Date": None})
    plt.close(fig)


def write_all(folder: Path) -> None:
    folder.mkdir(exist_ok=True)
    draw_cell(folder / "kresling_cell.svg")
