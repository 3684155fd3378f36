"""The thesis's analyses on Kresling specimens (chapter 3): the three-point bending test in
both stable states and the bending-stiffness ratio; more analyses build on these."""

from kresling.analyses.bending import (PROTOCOLS, BendingComparison, BendingResult, BendingTester,
                                       bending_stiffness, bending_test)

__all__ = ["PROTOCOLS", "BendingResult", "BendingComparison", "BendingTester", "bending_test",
           "bending_stiffness"]
