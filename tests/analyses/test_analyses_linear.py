"""The linearised bending stiffness (Appendix A's model) against the nonlinear test."""

import math

import pytest

from kresling import Design
from kresling.analyses import LinearBendingTester, bending_test, linear_bending_stiffness
from kresling.model import SpecimenParameters

DESIGNS = [Design(8, 0.8, 30), Design(8, 0.8, 15), Design(4, 0.7, 30), Design(10, 0.9, 15),
           Design(6, 0.75, 50)]


@pytest.mark.parametrize("design", DESIGNS, ids=repr)
def test_agrees_with_the_nonlinear_small_deflection_protocol(design):
    # At 0.001 rad the nonlinear K_B differs from the linear one by the geometric
    # nonlinearity, measured 4e-6 to 1.4e-5 relative on these designs: within 3e-5.
    tester = LinearBendingTester(design.n)
    for state in (0, 1):
        nonlinear = bending_test(design, state, "0.001rad").stiffness
        assert tester.run(design, state) == pytest.approx(nonlinear, rel=3e-5)


def test_gap_to_the_nonlinear_test_shrinks_with_the_deflection():
    # The gap is second order in the angle (M is odd in delta): 1.2e-5 at 1e-3 rad, 1.2e-7
    # at 1e-4 rad; the Newton tolerance (1e-6 mm) leaves it there.
    d = Design(10, 0.9, 15)
    linear = linear_bending_stiffness(d, 1)
    big = bending_test(d, 1, "0.001rad").stiffness / linear - 1
    small = bending_test(d, 1, "0.001rad", deflection_angle=1e-4).stiffness / linear - 1
    assert abs(small) < abs(big) / 50 and abs(small) < 1e-6


def test_pin_line_turned_against_the_load_changes_the_stiffness():
    # Turning the pin line by pi/n relative to the load moves K_B by 4-65 % (MERLIN2 runs;
    # docs/thesis_equations.md, 'Bending test').
    for design, low, high in ((Design(10, 0.9, 15), 0.03, 0.10), (Design(4, 0.7, 30), 0.5, 0.7)):
        for state in (0, 1):
            ratio = linear_bending_stiffness(design, state, pin_offset=math.pi / design.n) / \
                linear_bending_stiffness(design, state)
            assert low < ratio - 1 < high


def test_scales_with_kf():
    d = Design(6, 0.8, 20)
    base = linear_bending_stiffness(d, 0)
    assert linear_bending_stiffness(d, 0, parameters=SpecimenParameters(kf=0.47)) == \
        pytest.approx(10 * base, rel=1e-9)


@pytest.mark.parametrize("call, message", [
    (lambda: LinearBendingTester(5), r"n = 5 is invalid: must be even for the bending test"),
    (lambda: LinearBendingTester(8, cells=3), r"cells = 3 is invalid"),
    # a specimen of 22,011 nodes (the fuzz drew up to a million: ~36 GB to assemble)
    (lambda: LinearBendingTester(10, cells=2000), r"cells = 2000 is invalid .* at most 20000"),
    (lambda: bending_test(Design(10, 0.8, 30), 1, "5mm", cells=100002),
     r"cells = 100002 is invalid: .* <= 20000 \(n = 10: cells <= 1816\)"),
    (lambda: LinearBendingTester(8).run(Design(6, 0.8, 30), 1), r"design.n = 6 is invalid"),
    (lambda: LinearBendingTester(8).run(Design(8, 0.8, 30), 2), r"state = 2 is invalid"),
    (lambda: LinearBendingTester(8).run(Design(8, 0.8, 30), 1, angle=math.nan), r"angle = nan"),
])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()


# -- the C++ computation against an independent one in Python ------------------------------
#
# The reference builds the constraint map u = T q with the pins' edge points, condenses the
# tangent assembled in Python with scipy, and refines the solve in extended precision: the
# linearised test as it was computed in Python before it moved into the C++ core. K_B is the
# small difference of two large terms (e^T K_pp e is up to ~1e4 F) with cond(K_ff) up to
# ~1e6, so it is determined only to ~1e-11 relative by the rounding of the tangent's entries
# (the former Python path and the core, each against this reference: 2.6e-11 and 1.8e-11 at
# most over 432 cases); 1e-10 relative is asserted.

def _edge_point(n, angle):
    sector = 2 * math.pi / n
    phi = angle % (2 * math.pi)
    j = int(phi // sector) % n
    psi = phi - j * sector
    s = math.sin(psi) / (math.sin(psi) + math.sin(sector - psi))
    return j, (j + 1) % n, min(max(s, 0.0), 1.0)


def _reference_kb(design, state, angle, pin_offset, cells=4, reduced=False):
    """``reduced``: the pin line from each term modulo 2 pi (where their sum overflows)."""
    import numpy as np
    import scipy.sparse

    from kresling.assembly import tangent_stiffness
    from kresling.model.kresling_specimen import kresling_specimen
    n = design.n
    specimen = kresling_specimen(design, [state] * cells)
    held, slaves = set(), {}
    for level in (0, cells):
        held.add(specimen.centre(level))
        for side in (0.0, math.pi):
            pin = angle + pin_offset + side - specimen.level_angle[level]
            if reduced:
                pin = (angle % (2 * math.pi) + pin_offset % (2 * math.pi) + side
                       - specimen.level_angle[level] % (2 * math.pi))
            j, j1, s = _edge_point(n, pin)
            a, b = specimen.node(level, j), specimen.node(level, j1)
            if s <= 1e-12:
                held.add(a)
            elif s >= 1 - 1e-12:
                held.add(b)
            elif s >= 0.5:
                slaves[b] = (a, -(1 - s) / s)
            else:
                slaves[a] = (b, -s / (1 - s))
    middle = set(specimen.level_nodes(cells // 2).tolist())
    columns, imposed, count = {}, [], 0
    c, s_ = math.cos(angle), math.sin(angle)
    for node in range(specimen.model.num_nodes):
        if node in held or node in slaves:
            continue
        if node in middle:
            imposed.append(count)
            columns[3 * node] = [(count, -s_), (count + 1, c)]
            columns[3 * node + 1] = [(count, c), (count + 1, s_)]
            columns[3 * node + 2] = [(count + 2, 1.0)]
            count += 3
        else:
            for k in range(3):
                columns[3 * node + k] = [(count + k, 1.0)]
            count += 3
    for slave, (master, weight) in slaves.items():
        for k in range(3):
            columns[3 * slave + k] = [(col, weight * v) for col, v in columns[3 * master + k]]
    rows, cols, values = zip(*((dof, col, v) for dof, entries in columns.items()
                               for col, v in entries))
    T = scipy.sparse.csr_matrix((values, (rows, cols)), shape=(specimen.model.num_dofs, count))
    K = (T.T @ tangent_stiffness(specimen.model) @ T).tocsc()
    free = np.setdiff1d(np.arange(count), imposed)
    e = np.ones(len(imposed))
    b = K[free][:, imposed] @ e
    Kff = K[free][:, free].toarray()
    u = np.linalg.solve(Kff, b)
    for _ in range(2):
        residual = b.astype(np.longdouble) - Kff.astype(np.longdouble) @ u.astype(np.longdouble)
        u = u + np.linalg.solve(Kff, residual.astype(float))
    force = np.longdouble(e @ (K[imposed][:, imposed] @ e)) - b.astype(np.longdouble) @ u
    L = 2.0 * design.height(state)
    return float(force) * L * L * 1e-3


@pytest.mark.parametrize("design", DESIGNS + [Design(16, 0.9, 30), Design(12, 0.6, 5)],
                         ids=repr)
def test_core_matches_an_independent_condensation(design):
    tester = LinearBendingTester(design.n)
    for state in (0, 1):
        for angle, pin_offset in ((0.0, 0.0), (0.3, 0.0), (0.0, math.pi / design.n), (1.1, 0.2)):
            ours = tester.run(design, state, angle=angle, pin_offset=pin_offset)
            reference = _reference_kb(design, state, angle, pin_offset)
            assert ours == pytest.approx(reference, rel=1e-10), (state, angle, pin_offset)


@pytest.mark.parametrize("angle, pin_offset", [(1e308, 1e308), (-1.7e308, -1.7e308),
                                               (1.7976931348623157e308, 3.0)])
def test_angles_whose_sum_overflows(angle, pin_offset):
    # Each angle is finite but angle + pin_offset is not: the pin line's edge index was a
    # cast of NaN (a segfault). The line is now placed from each term modulo 2 pi.
    design = Design(8, 0.8, 30)
    ours = LinearBendingTester(8).run(design, 1, angle=angle, pin_offset=pin_offset)
    overflows = not math.isfinite(angle + pin_offset + math.pi)
    reference = _reference_kb(design, 1, angle, pin_offset, reduced=overflows)
    assert ours > 0
    assert ours == pytest.approx(reference, rel=1e-10)
