#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "kresling/analyses/arm_crease_switching.hpp"

using kresling::VectorX;
using kresling::analyses::ArmCreaseSwitchOptions;
using kresling::analyses::ArmSolver;
using kresling::analyses::arm_crease_switch;
using kresling::geometry::Design;

namespace {

// The thesis's optimum (Design(n, R, lambda, Lc)).
const Design kOptimum(10, 30.0, 0.9, 15.0);

}  // namespace

TEST(ArmCreaseSwitching, AllFoldsExtendAModuleRestingContracted) {
  const kresling::model::Arm arm = kresling::model::build_arm(kOptimum, {1});
  const kresling::model::Arm contracted = kresling::model::build_arm(kOptimum, {0});
  // The module at rest contracted: descent from the contracted geometry, tendons let out.
  ArmSolver solver(arm);
  const double let_out = 3.0 * (arm.cell_extended - arm.cell_contracted);
  const kresling::analyses::Pulls out{-let_out, -let_out, -let_out};
  // nodes() is row-major (N, 3): the map reads node by node, as the DOFs are numbered.
  const VectorX u = Eigen::Map<const VectorX>(
      (contracted.model.nodes() - arm.model.nodes()).eval().data(), arm.model.num_dofs());
  const auto rest = solver.release(solver.evaluate(u, out), out);
  ASSERT_TRUE(rest.converged) << rest.message;
  ASSERT_LT(rest.state.cell_height[0], 0.5 * (arm.cell_extended + arm.cell_contracted));

  const auto r = arm_crease_switch(kOptimum, {1}, {}, 0, {0, 1}, rest.state.displacement, true);
  ASSERT_TRUE(r.scan.switched) << r.scan.message;
  EXPECT_EQ(r.configuration_before, "0");
  EXPECT_EQ(r.configuration_after, "1");
  // It lands in the built extended state: both cells at Le (measured 1.5e-10 mm).
  for (double h : r.after.cell_height) EXPECT_NEAR(h, arm.cell_extended, 1e-6);
  // The actuation's work is the energy it adds (measured 2e-6 relative).
  EXPECT_NEAR(r.scan.work, r.scan.snap_energy - r.scan.start_energy, 1e-3 * r.scan.work);
  EXPECT_EQ(r.hinges.size(), 70u);  // 20 valleys and 50 polygon edges (mountains are cut)
}

TEST(ArmCreaseSwitching, BadInputIsRefused) {
  EXPECT_THROW(arm_crease_switch(kOptimum, {1}, {}, 1, {2}, VectorX(), false),
               std::invalid_argument);
  EXPECT_THROW(arm_crease_switch(kOptimum, {1, 1}, {}, 0, {2}, VectorX(), false),
               std::invalid_argument);
  EXPECT_THROW(arm_crease_switch(kOptimum, {1}, {}, 0, {0}, VectorX::Zero(3), false),
               std::invalid_argument);
  ArmCreaseSwitchOptions o;
  o.let_out = -1.0;
  EXPECT_THROW(arm_crease_switch(kOptimum, {1}, {}, 0, {0}, VectorX(), false, o),
               std::invalid_argument);
}
