"""The facet angle Psi read from the built model (section 3.4, figure 3.8)."""

import numpy as np
import pytest

from kresling import Design
from kresling.analyses import facet_angle, facet_angle_ratio, facet_angles


@pytest.mark.parametrize("design", [Design(8, 0.8, 30), Design(8, 0.8, 15), Design(4, 0.7, 30),
                                    Design(10, 0.9, 15), Design(7, 0.55, 60, chirality=-1),
                                    Design(6, 0.99, 0.5)], ids=repr)
def test_built_model_matches_the_closed_form(design):
    for state, closed_form in ((1, design.psi_ext), (0, design.psi_con)):
        angles = facet_angles(design, state)
        assert angles.shape == (2 * design.n,)
        assert np.abs(angles - closed_form).max() <= 1e-12
    assert facet_angle_ratio(design) == pytest.approx(design.psi_ratio, rel=1e-12)
    assert facet_angle(design, 1) > facet_angle(design, 0)


def test_golden_value():
    # MERLIN2's golden model (n=4, Lc=30, lambda=0.7, extended), hinge 1 of folds.csv.
    assert facet_angle(Design(4, 0.7, 30), "extended") == pytest.approx(1.2878022801111912, abs=1e-12)


def test_section_3_4_trends_of_the_psi_ratio():
    # Like the K_B ratio: it rises with lambda and falls with Lc (figures 3.9-3.12).
    for n in (4, 6, 8, 10):
        by_lam = [facet_angle_ratio(Design(n, lam, 30)) for lam in np.linspace(0.7, 0.9, 5)]
        by_Lc = [facet_angle_ratio(Design(n, 0.8, Lc)) for Lc in np.linspace(15, 60, 5)]
        assert np.all(np.diff(by_lam) > 0) and np.all(np.diff(by_Lc) < 0)
