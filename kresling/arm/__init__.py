"""The manipulator as a structure: tendons, load capacity, switching, joint lengths.

The thesis drives its arm with constant-curvature kinematics (:mod:`kresling.manipulator`);
here the whole arm is one bar-and-hinge model: ``m`` modules of two Kresling cells joined at
stiff guide plates, with three sliding, tension-only tendons from the fixed base to the tip
guide (:mod:`kresling.arm.structure`). On it, in the C++ core:

- :func:`tip_load`: tip displacement and the 3 x 3 tip compliance under a tip force;
- :func:`load_capacity`: the largest tip load before a module snaps or a tendon goes slack;
- :func:`pull_until_snap`: pull tendons (all, or some) until a module snaps: which one, the
  tendon force and the configuration it lands in;
- :func:`reach`: the configuration and tendon pulls that bring the tip to a point, on the
  exact tip Jacobian (:func:`tip_jacobian`), with or without the arm's own weight;
- :func:`plan_reach`: from the configuration the arm rests in, the module switches (tendon
  pulls, or crease actuation where tendons cannot), each checked on the model, then the move.

Submodules beyond these: ``capacity`` (the load-capacity table of every configuration),
``actuation`` (tendon commands in, the structure's shape out, beside the constant-curvature
model; module lengths against Table 5), ``switching`` (which pulls reach which
configurations), ``plots``. The command line is ``kresling arm``; the guide is docs/arm.md
and the report's section :mod:`kresling.report.sections.arm`.
"""

from kresling.arm.analyses import (CAPACITY_DIRECTIONS, DEFAULT_PRETENSION, ArmSolver, ArmState,
                                   CapacityResult, EquilibriumNotReached, SnapResult,
                                   TipLoadResult, arm_summary, load_capacity, pull_until_snap,
                                   tip_load)
from kresling.arm.plan import ReachPlan, plan_reach
from kresling.arm.reach import ReachResult, reach, tip_jacobian
from kresling.arm.structure import (THESIS_DESIGN, Arm, ArmParameters, all_configurations,
                                    build_arm, parse_configuration)

__all__ = ["Arm", "ArmParameters", "build_arm", "parse_configuration", "all_configurations",
           "THESIS_DESIGN", "ArmSolver", "ArmState", "EquilibriumNotReached",
           "DEFAULT_PRETENSION", "TipLoadResult",
           "tip_load", "SnapResult", "pull_until_snap", "CapacityResult", "load_capacity",
           "CAPACITY_DIRECTIONS", "arm_summary", "reach", "ReachResult", "tip_jacobian", "plan_reach",
           "ReachPlan"]
