"""Scale-free by default: the same pattern drawn at 1 um, 1 mm, 100 mm and 1 m, with its
stiffnesses scaled as a similar structure's are, follows the same normalised path with the
same Newton iterations, because Newton's default tolerance is relative to the pattern's size,
the tangent's diagonal shift relative to its stiffness, and the hinges' angle exact at flat."""

import numpy as np
import pytest

from kresling.io import miura_sheet
from kresling.simulate import load_problem, simulate

SHEET = miura_sheet(3, 2, a=1.0, b=1.0, sector_angle=60.0, fold_angle=40.0)


def _problem(scale, tolerance=None):
    """The unit Miura sheet at ``scale`` mm per unit. Lengths scale by s; with bar areas and
    hinge stiffnesses (per unit length) scaled by s^2 every energy scales by s^3, so forces
    scale by s^2 and displacements by s: the path normalised so is the same."""
    corner = int(np.argmax(SHEET.vertices[:, 0] + SHEET.vertices[:, 1]))
    problem = {
        "pattern": {"vertices": SHEET.vertices.tolist(), "panels": [list(f) for f in SHEET.faces],
                    "unit": "unit", "scale": scale},
        "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1e-2 * scale ** 2,
                     "fold_stiffness": 1e-3 * scale ** 2, "bend_stiffness": 1e-2 * scale ** 2},
        "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"},
                    {"node": 4, "fix": "z"}],
        "load": [{"node": corner, "displacement": [0.0, 0.0, -0.4 * scale]}],
        "analysis": {"method": "displacement_control", "steps": 8},
    }
    if tolerance is not None:
        problem["analysis"]["tolerance"] = tolerance
    return problem


def test_the_default_tolerance_is_relative_and_an_explicit_one_absolute():
    size = np.linalg.norm(np.ptp(SHEET.vertices, axis=0))
    for scale in (1.0, 100.0, 1000.0):
        assert load_problem(_problem(scale)).analysis.tolerance == pytest.approx(
            1e-8 * size * scale, rel=1e-12)
        assert load_problem(_problem(scale, tolerance=3e-5)).analysis.tolerance == 3e-5
    compat = _problem(100.0)
    compat["material"]["merlin2_compat"] = True
    assert load_problem(compat).analysis.tolerance == 1e-6


def test_the_same_pattern_at_1_mm_100_mm_and_1_m_follows_the_same_normalised_path():
    runs = {scale: simulate(_problem(scale), progress=False) for scale in (1.0, 100.0, 1000.0)}
    reference = runs[1.0].path
    assert reference.completed and reference.num_steps == 8
    for scale, run in runs.items():
        path = run.path
        assert path.completed
        np.testing.assert_array_equal(path.iterations, reference.iterations)
        # Each equilibrium is found to Newton's tolerance, 1e-8 of the size (2.3e-8 on the
        # unit sheet): the runs, rounded differently, agree to that, not to the last bit.
        tolerance = 1e-8 * np.linalg.norm(np.ptp(SHEET.vertices, axis=0))
        np.testing.assert_allclose(path.displacement / scale, reference.displacement,
                                   rtol=0, atol=tolerance)
        force = np.abs(reference.constraint_force).max()     # they differ by 5e-8 of it
        np.testing.assert_allclose(path.constraint_force / scale ** 2,
                                   reference.constraint_force, rtol=0, atol=1e-6 * force)
    # An explicit tolerance is absolute: 1e-9 mm is 1e-12 of the 1 m sheet, within reach of
    # the exact angle's rounding (MERLIN2's arccosine carried ~1e-8 rad near flat, and its
    # first increment then never converged).
    for scale in (1.0, 1000.0):
        assert simulate(_problem(scale, tolerance=1e-9), progress=False).path.completed


def _flat_grid(cells, size, compat=False):
    """A flat square sheet of cells x cells quads (N4B5), ``size`` mm across, lifted at a
    corner by 1e-4 of its size; stiffnesses scaled as in _problem (1e5 N/mm^2 bars)."""
    h = size / cells
    vertices = [[i * h, j * h, 0.0] for j in range(cells + 1) for i in range(cells + 1)]
    row = cells + 1
    panels = [[j * row + i, j * row + i + 1, (j + 1) * row + i + 1, (j + 1) * row + i]
              for j in range(cells) for i in range(cells)]
    s = size / 100.0
    return {"pattern": {"vertices": vertices, "panels": panels, "split": "N4B5"},
            "material": {"calibration": "manual", "bar_modulus": 1e5, "bar_area": s ** 2,
                         "fold_stiffness": s ** 2, "bend_stiffness": s ** 2,
                         "merlin2_compat": compat},
            "support": [{"node": 0, "fix": "xyz"}, {"node": cells, "fix": "yz"},
                        {"node": cells * row, "fix": "z"}],
            "load": [{"node": row * row - 1, "displacement": [0.0, 0.0, 1e-4 * size]}],
            "analysis": {"method": "displacement_control", "steps": 1,
                         "tolerance": 1e-8 * np.sqrt(2) * size}}


def test_a_flat_sheet_lifted_at_a_corner_converges_alike_at_1_um_1_mm_and_1_m():
    # A flat start is where rounding bites: the hinges sit at pi, where MERLIN2's arccosine
    # loses ~1e-8 rad, and the sheet's long-wave bending modes are soft beside a fixed
    # 1e-8 N/mm shift at micro scale. Measured: 8 Newton iterations at 1 um, 1 mm and 1 m.
    runs = {size: simulate(_flat_grid(30, size), progress=False).path
            for size in (1e-3, 1.0, 1e3)}
    for size, path in runs.items():
        assert path.completed, (size, path.message)
        np.testing.assert_array_equal(path.iterations, runs[1.0].iterations)
        np.testing.assert_allclose(path.constraint_force / (size / 100.0) ** 2,
                                   runs[1.0].constraint_force / 1e-4, rtol=1e-6)
    assert runs[1.0].iterations[0] <= 10


def test_merlin2_compat_keeps_merlin2s_arithmetic_and_stalls_where_merlin2_would():
    # The same lift with MERLIN2's arccosine and absolute shift, at 1 um: the correction
    # stagnates at the rounding the two leave (the run fails and says so).
    path = simulate(_flat_grid(6, 1e-3, compat=True), progress=False).path
    assert not path.completed
    assert "Newton did not converge" in path.message
