"""Write problem.toml: a MEMS origami micro-mirror (two piezoelectric folding beams and a
mirror panel, 0.1 to 0.44 mm long) as [[bar]] and [[hinge]] members, in mm, N and t.

The structure and its numbers are those of Sim-FAST's micro-mirror example: each beam is a
strip of five segments, 100 um wide, of a SiO2/Pt/PZT/Pt laminate homogenised to 100 GPa,
braced by diagonal bars; its crossings are rotational springs of the laminate's bending
stiffness, the mirror panel's (25 um of silicon under 1 um of aluminium) 100 times stiffer.
Masses are lumped at the nodes, gravity acts at 45 deg between x and -z. A 5 V bias on the
PZT folds the right beam's creases by its piezoelectric moment beside the 45 deg each
beam is folded to, and the mirror panel by 1 deg.

    python examples/micro_mirror/make_problem.py

The stiffnesses are computed here from the layers (SI), then written in the problem file's
units: lengths in mm (x 1e3), moduli in N/mm^2 (x 1e-6), areas in mm^2 (x 1e6), moments
per radian in N mm/rad (x 1e3), masses in t (x 1e-3), forces in N.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent

# -- geometry [m] -----------------------------------------------------------------------
L1, L2, L3, L4, L5 = 300e-6, 100e-6, 600e-6, 400e-6, 440e-6  # overhang, beam width,
S = 5                                                          # mirror width, panel, beam
LA = 340e-6                   # the folding length of a beam (its ends are under aluminium)
FOLD_DEG = 45.0               # each beam's fold
MIRROR_DEG = 1.0              # the mirror panel's bend
V_DC, D31 = 5.0, -100e-12     # bias [V], piezoelectric coefficient [m/V]
V_PP = 10.0                   # the AC drive's peak-to-peak voltage [V]
F0, F1, SWEEP = 200.0, 700.0, 0.02   # the drive's linear sweep [Hz], [Hz], [s]
STEP = 2e-5                   # the time step [s]: ~150 steps per period at 318 Hz
ALPHA, BETA = 90.0, 1e-7      # Rayleigh damping [1/s], [s]

# -- layers (thickness [m], modulus [Pa], density [kg/m^3]) ------------------------------
T_SIO2, T_PT_TOP, T_PZT, T_PT_BOTTOM, T_AL = 1e-6, 0.1e-6, 1e-6, 0.15e-6, 1e-6
E_SIO2, E_PT, E_PZT, E_EQ = 66e9, 168e9, 70e9, 100e9
RHO_PZT, RHO_SIO2, RHO_PT, RHO_AL, RHO_SI, T_SI = 8000, 2600, 21000, 2700, 2300, 25e-6
G = 9.8                       # [m/s^2]


def structure():
    """Nodes [m] (N, 3), bars (B, 2) with their areas [m^2], springs [i, j, k, l] (H, 4)
    with stiffnesses [N m/rad], masses [kg] (N,), supported nodes, and the springs folded
    with their target dihedral angles [rad]; all indices 0-based."""
    ea = L2 * (T_SIO2 * E_SIO2 + T_PT_TOP * E_PT + T_PZT * E_PZT + T_PT_BOTTOM * E_PT)
    t_mean = ea / L2 / E_EQ
    a_long, a_across, a_diagonal = ea / E_EQ / 2, t_mean * L5 / 6, 7 / 4 / np.sqrt(2) * t_mean * L2
    t_panel = 25e-6
    perimeter = (2 * (L3 + 2 * L1 + 2 * L2) + 4 * L4 + 2 * np.sqrt(L4**2 + L3**3)
                 + 2 * np.sqrt(L4**2 + L2**3) + 2 * np.sqrt(L4**2 + L1**3))
    a_panel = 2 * (L3 + 2 * L1 + 2 * L2) * L4 * t_panel / perimeter
    # The laminate's neutral axis c and bending stiffness EI about it.
    layers = [(T_SIO2, E_SIO2), (T_PT_BOTTOM, E_PT), (T_PZT, E_PZT), (T_PT_TOP, E_PT)]
    base, first_moment = 0.0, 0.0
    for t, e in layers:
        first_moment += t * L2 * (t / 2 + base) * e
        base += t
    c = first_moment / ea
    base, ei = 0.0, 0.0
    for t, e in layers:
        ei += L2 * e * (t**3 / 12 + t * (c - t / 2 - base) ** 2)
        base += t
    k_beam, k_beam_diagonal = (S + 1) * ei / L5, 2 * np.sqrt(2) * ei / L2
    k_panel = 100 * k_beam
    z_pzt = c - T_PZT / 2 - T_PT_BOTTOM - T_SIO2
    dc_deg = np.degrees(D31 * V_DC / T_PZT * E_PZT * L2 * T_PZT * z_pzt / ei * LA)

    n = 4 * (S + 1) + 2 + 7
    X = np.zeros((n + 1, 3))          # 1-based, as the structure is numbered in its source
    X[1] = [-L5 / 3, L3 / 2 + L2, 0]
    X[2 * S + 4] = [-L5 / 3, -L3 / 2 - L2, 0]
    for i in range(1, S + 2):
        x = L5 * (i - 1) / S
        X[1 + i] = [x, L3 / 2 + L2, 0]
        X[S + 2 + i] = [x, L3 / 2, 0]
        X[2 * S + 4 + i] = [x, -L3 / 2 - L2, 0]
        X[3 * S + 5 + i] = [x, -L3 / 2, 0]
    p = 4 * (S + 1) + 2
    X[p + 1] = [L5, L3 / 2 + L2 + L1, 0]
    X[p + 2] = [L5, -L3 / 2 - L2 - L1, 0]
    X[p + 3] = [L5 + L4 / 2, 0, 0]
    X[p + 4] = [L5 + L4, L3 / 2 + L2 + L1, 0]
    X[p + 5] = [L5 + L4, L3 / 2, 0]
    X[p + 6] = [L5 + L4, -L3 / 2, 0]
    X[p + 7] = [L5 + L4, -L3 / 2 - L2 - L1, 0]

    bars, areas = [], []

    def bar(i, j, area):
        bars.append((i, j))
        areas.append(area)

    b1, b2, b3 = S + 1, 2 * (S + 1), 3 * (S + 1)
    for i, j in ((1, 2), (b2 + 2, b2 + 3), (1, 2 + b1), (b2 + 2, b3 + 3)):
        bar(i, j, a_long)
    for i in range(1, S + 1):
        for j, k in ((i + 1, i + 2), (b1 + 1 + i, b1 + 2 + i), (b2 + 2 + i, b2 + 3 + i),
                     (b3 + 2 + i, b3 + 3 + i)):
            bar(j, k, a_long)
    for i in range(1, S + 2):
        bar(1 + i, b1 + 1 + i, a_across)
        bar(b2 + 2 + i, b3 + 2 + i, a_across)

    springs, stiffness = [], []

    def spring(ijkl, k):
        springs.append(ijkl)
        stiffness.append(k)

    spring((1, 2, b1 + 2, b1 + 3), k_beam)
    spring((b2 + 2, b2 + 3, b3 + 3, b3 + 4), k_beam)
    for i in range(2, S + 1):
        if i % 2:
            spring((b1 + i, 1 + i, b1 + 1 + i, b1 + 2 + i), k_beam)
            spring((b3 + 1 + i, b2 + 2 + i, b3 + 2 + i, b3 + 3 + i), k_beam)
        else:
            spring((i, 1 + i, b1 + 1 + i, 2 + i), k_beam)
            spring((b2 + 1 + i, b2 + 2 + i, b3 + 2 + i, b2 + 3 + i), k_beam)
    spring((b1 + 1 + S, 2 + S, b1 + 2 + S, p + 5), k_beam)
    spring((b3 + 2 + S, b2 + 3 + S, b3 + 3 + S, p + 6), k_beam)
    for index in (0, 1, 2 * S, 2 * S + 1):          # the springs at the beams' roots
        stiffness[index] *= 2

    for i in range(1, S + 1):
        if i % 2:
            bar(i + 1, b1 + 2 + i, a_diagonal)
            bar(b2 + 2 + i, b3 + 3 + i, a_diagonal)
        else:
            bar(i + 2, b1 + 1 + i, a_diagonal)
            bar(b2 + 3 + i, b3 + 2 + i, a_diagonal)
    for i in range(1, S + 1):
        if i % 2:
            spring((b1 + 1 + i, i + 1, b1 + 2 + i, i + 2), k_beam_diagonal)
            spring((b3 + 2 + i, b2 + 2 + i, b3 + 3 + i, b2 + 3 + i), k_beam_diagonal)
        else:
            spring((i + 1, b1 + 1 + i, i + 2, b1 + 2 + i), k_beam_diagonal)
            spring((b2 + 2 + i, b3 + 2 + i, b2 + 3 + i, b3 + 3 + i), k_beam_diagonal)

    for i, j in ((b2 + 1, p), (p + 5, p + 6), (b1 + 1, p + 1), (b3 + 2, p + 2),
                 (p + 1, p + 4), (p + 2, p + 7), (p + 4, p + 5), (p + 6, p + 7),
                 (S + 2, p + 4), (b3 + 2, p + 7), (S + 2, p + 5), (b3 + 2, p + 6),
                 (b2 + 1, p + 5), (p, p + 6), (b2 + 1, p + 3), (p, p + 3), (p + 3, p + 5),
                 (p + 3, p + 6)):
        bar(i, j, a_panel)
    for ijkl in ((p + 1, b1 + 1, p + 4, p + 5), (p + 2, b3 + 2, p + 7, p + 6),
                 (p + 4, b1 + 1, p + 5, b2 + 1), (p, p + 6, b3 + 2, p + 7),
                 (b1 + 1, b2 + 1, p + 5, p + 3), (b3 + 2, p, p + 6, p + 3),
                 (b2 + 1, p + 3, p, p + 6), (p, p + 3, p + 6, p + 5),
                 (p + 6, p + 3, p + 5, b2 + 1), (p + 5, p + 3, b2 + 1, p)):
        spring(ijkl, k_panel)

    beam_mass = L5 * L2 * (T_SIO2 * RHO_SIO2 + 2 * T_PT_TOP * RHO_PT + T_PZT * RHO_PZT)
    panel_mass = (2 * L1 + 2 * L2 + L3) * L4 * (RHO_SI * T_SI + RHO_AL * T_AL)
    mass = np.zeros(n + 1)
    mass[1:p + 1] = beam_mass / (2 * (S + 1))
    for node in (b1 + 1, b2 + 1, b3 + 4, p, p + 1, p + 2, p + 3, p + 4, p + 5, p + 6, p + 7):
        mass[node] += panel_mass / 30

    mass[p + 3] = panel_mass * 2 / 3

    supported = (1, 2, S + 3, 2 + b2, 3 + b2, 3 + b3)
    left = [2 * i - 1 for i in range(2, S + 1)]
    right = [2 * i for i in range(2, S + 1)]
    mirror = [b2 + 2 * S + 5, b2 + 2 * S + 6]
    target = {}
    for h in left:
        target[h] = np.pi * (FOLD_DEG / 180 / (S - 1) + 1)
    for h in right:
        target[h] = np.pi * (FOLD_DEG / 180 / (S - 1) + dc_deg / 180 / (S - 1) + 1)
    for h in mirror:
        target[h] = np.pi * (MIRROR_DEG / 180 + 1)
    pp_deg = np.degrees(D31 * V_PP / T_PZT * E_PZT * L2 * T_PZT * z_pzt / ei * LA)
    # A dihedral angle theta0 + A y(t) is a fold angle rho0 - A y(t): the sweep's amplitude
    # per crease in fold angle, for y(t) = -sin(phi(t)).
    amplitude = pp_deg / 2 / (S - 1)
    return (X[1:], np.array(bars) - 1, np.array(areas), np.array(springs) - 1,
            np.array(stiffness), mass[1:], [s - 1 for s in supported],
            {h - 1: t for h, t in target.items()}, [h - 1 for h in right], amplitude)


HEADER = """\
# A MEMS origami micro-mirror: two piezoelectric beams (five segments each, 0.44 mm long,
# 0.1 mm wide) fold a mirror panel (0.84 x 1.4 mm) up out of the wafer, under gravity at
# 45 deg. Bars and hinges are given one by one ([[bar]], [[hinge]] in Sim-FAST's node order
# and angle convention); lengths are in mm, so the whole structure is under 1.5 mm across.
#
# Stage "flat_modes": the three lowest vibration modes of the flat structure. Stage "fold":
# each beam's four inner creases told to fold it by 45 deg (11.25 deg each; the right
# beam's 1.03 deg more each, the 5 V bias's piezoelectric moment), the mirror panel bent by
# 1 deg, with the nodes' weights ramped on over the same 20 increments; the segments'
# undriven diagonal creases hold the driven ones back. Stage "folded_modes": the modes about
# the folded state, with its rest angles and stress. Stage "chirp": the right beam's creases
# driven by the 10 V peak-to-peak AC voltage, +-1.03 deg of rest angle each, swept linearly
# from 200 to 700 Hz in 20 ms (Rayleigh damping, the weights held): the mirror's centre
# moves by up to 20 um peak to peak and the mirror twists by up to 0.15 deg (4_chirp/).
#
# Made by make_problem.py (edit that, not this file).
"""


def _rows(values, per=4, fmt="{:.17g}"):
    items = ["[" + ", ".join(fmt.format(v) for v in row) + "]" for row in values]
    return "[\n  " + ",\n  ".join(", ".join(items[i:i + per])
                                   for i in range(0, len(items), per)) + "]"


def problem_text() -> str:
    X, bars, areas, springs, k, mass, supported, target, right_creases, amplitude = \
        structure()
    mm, n_per_mm2, mm2, nmm, t = 1e3, 1e-6, 1e6, 1e3, 1e-3
    out = [HEADER]
    out.append("[pattern]\nvertices = " + _rows(X * mm, per=2) + "\npanels = []\n")
    for area in np.unique(areas):
        chosen = bars[areas == area]
        out.append("[[bar]]\nnodes = " + _rows(chosen, per=8, fmt="{:d}")
                   + f"\nmodulus = {E_EQ * n_per_mm2:.17g}\narea = {area * mm2:.17g}\n")
    for stiff in np.unique(k):
        chosen = springs[k == stiff]
        out.append('[[hinge]]\nconvention = "simfast"\nnodes = '
                   + _rows(chosen, per=4, fmt="{:d}") + f"\nstiffness = {stiff * nmm:.17g}\n")
    out.append("[[support]]\nnodes = [" + ", ".join(map(str, supported)) + ']\nfix = "xyz"\n')
    for node in np.flatnonzero(mass):
        out.append(f"[[mass]]\nnode = {node}\nmass = {mass[node] * t:.17g}\n")
    actuation = ", ".join(
        f"{{ edges = [[{springs[h][1]}, {springs[h][2]}]], "
        f"fold_angle_deg = {180.0 - np.degrees(theta):.17g} }}" for h, theta in target.items())
    gravity = ", ".join(
        f"{{ node = {node}, force = [{m * G / np.sqrt(2):.17g}, 0.0, {-m * G / np.sqrt(2):.17g}] }}"
        for node, m in enumerate(mass) if m > 0)
    out.append('[[stage]]\nname = "flat_modes"\nmethod = "modes"\nmodes = 3\n')
    out.append('[[stage]]\nname = "fold"\nmethod = "fold"\nsteps = 20\n'
               "# The segments' undriven diagonal creases resist the driven ones, which end\n"
               "# short of their rest angles by design: the fold counts as reaching its end\n"
               "# with each within 10 deg (summary.json's fold entry says how far each got).\n"
               "target_tolerance_deg = 10.0\n"
               f"actuation = [{actuation}]\nload = [{gravity}]\n")
    out.append('[[stage]]\nname = "folded_modes"\nmethod = "modes"\nmodes = 3\n')
    # The right beam's creases driven by the AC half of the voltage, swept from F0 to F1 Hz
    # (Sim-FAST's phase 90 deg cosine is this sine turned over: the same sweep), under the
    # weights the fold left on, with Rayleigh damping.
    swing = ", ".join(
        f"{{ edges = [[{springs[h][1]}, {springs[h][2]}]], "
        f"time = {{ chirp = [{amplitude:.17g}, {F0:g}, {F1:g}, {SWEEP:g}] }} }}"
        for h in right_creases)
    out.append('[[stage]]\nname = "chirp"\nmethod = "dynamic"\n'
               f'dynamics = {{ scheme = "newmark", time_step = {STEP:g}, duration = {SWEEP:g}, '
               f"damping = {{ alpha = {ALPHA:g}, beta = {BETA:g} }} }}\n"
               f"actuation = [{swing}]\n")
    return "\n".join(out)


if __name__ == "__main__":
    (HERE / "problem.toml").write_text(problem_text())
