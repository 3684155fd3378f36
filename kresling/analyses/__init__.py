"""The thesis's analyses on Kresling specimens (chapter 3): the three-point bending test in
both stable states and the bending-stiffness ratio, its linearised (infinitesimal) form, and
the snap-through test of bistability strength, and the facet angle Psi of the built cells."""

from kresling.analyses.bending import (PROTOCOLS, BendingComparison, BendingResult, BendingTester,
                                       bending_stiffness, bending_test)
from kresling.analyses.facet_angle import facet_angle, facet_angle_ratio, facet_angles
from kresling.analyses.linear_bending import LinearBendingTester, linear_bending_stiffness
from kresling.analyses.snap_through import SnapThroughResult, SnapThroughTester, snap_through

__all__ = ["PROTOCOLS", "BendingResult", "BendingComparison", "BendingTester", "bending_test",
           "bending_stiffness", "LinearBendingTester", "linear_bending_stiffness",
           "SnapThroughResult", "SnapThroughTester", "snap_through", "facet_angles",
           "facet_angle", "facet_angle_ratio"]
