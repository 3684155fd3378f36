"""The thesis's analyses on Kresling specimens (chapter 3): the three-point bending test in
both stable states and the bending-stiffness ratio (section 3.4), its linearised form and the
orientation study (Appendix A), the facet angle Psi of the built cells (figure 3.8) and the
snap-through test of bistability strength (section 3.5), and the exact derivatives of the
bending stiffnesses, their ratio, the snap force and the energy barrier by the design
(``design_gradient``), with which the specimen's stiffnesses are fitted to records on the
full model (``fit_specimen_stiffness``, ``fit_bending_stiffnesses``).

Submodules beyond these: ``table3`` (Table 3 side by side), ``plots`` (figures 3.5-3.7,
3.14, 3.16), ``specimen_views`` (FOLD export, 3D plot), ``paths`` (the bending and
snap-through paths with every node at every increment, for views). The report's section on them is
:mod:`kresling.report.sections.analyses`.
"""

from kresling._lazy import lazy_names
from kresling.analyses.bending import (PROTOCOLS, BendingComparison, BendingResult, BendingTester,
                                       bending_stiffness, bending_test)
# facet_angle and snap_through are also modules' names: imported here, not when first used.
from kresling.analyses.facet_angle import facet_angle, facet_angle_ratio, facet_angles
from kresling.analyses.snap_through import SnapThroughResult, SnapThroughTester, snap_through

# Imported when first used (``kresling bend`` needs none of them).
__getattr__, __dir__ = lazy_names(__name__, {
    **dict.fromkeys(["DESIGN_VARIABLES", "GRADIENT_QUANTITIES", "DesignGradient",
                     "bending_gradient", "design_gradient", "snap_through_gradient"],
                    "design_sensitivity"),
    **dict.fromkeys(["LinearBendingTester", "linear_bending_stiffness"], "linear_bending"),
    **dict.fromkeys(["OrientationStudy", "orientation_study"], "orientation"),
    **dict.fromkeys(["BendingRecord", "StiffnessFit", "fit_bending_stiffnesses",
                     "fit_specimen_stiffness"], "stiffness_fit")})

__all__ = ["PROTOCOLS", "BendingResult", "BendingComparison", "BendingTester", "bending_test",
           "bending_stiffness", "LinearBendingTester", "linear_bending_stiffness",
           "SnapThroughResult", "SnapThroughTester", "snap_through", "facet_angles",
           "facet_angle", "facet_angle_ratio", "OrientationStudy", "orientation_study",
           "DESIGN_VARIABLES", "GRADIENT_QUANTITIES", "DesignGradient", "design_gradient",
           "bending_gradient", "snap_through_gradient", "BendingRecord", "StiffnessFit",
           "fit_specimen_stiffness", "fit_bending_stiffnesses"]
