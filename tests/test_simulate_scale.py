"""Scale-free by default: the same pattern drawn at 1 mm, 100 mm and 1 m, with its stiffnesses
scaled as a similar structure's are, follows the same normalised path with the same Newton
iterations, because Newton's default tolerance is relative to the pattern's size."""

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
    # One absolute tolerance for all: 1e-9 mm, met on the 1 mm sheet, is below the rounding
    # of the 1 m one, whose first increment then never converges.
    small, large = (simulate(_problem(scale, tolerance=1e-9), progress=False).path
                    for scale in (1.0, 1000.0))
    assert small.completed and not large.completed and large.num_steps == 0
