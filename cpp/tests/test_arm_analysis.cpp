// The arm as a structure: tip loads (linear, Maxwell-Betti), the lever arm of a contracted
// module, pretension, tension sensitivities, pulling until a module snaps, load capacity.
// Every test runs in well under a second (arms of one to three modules of the optimum).

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/snap_through.hpp"

using namespace kresling;
using analyses::ArmSolver;

namespace {

geometry::Design optimum() { return geometry::Design(10, 30.0, 0.9, 15.0); }

model::Arm arm_of(const std::string& config) {
  return model::build_arm(optimum(), model::parse_configuration(config));
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(ArmAnalysis, BuiltArmIsStableAndUnloaded) {
  for (const std::string config : {"0", "1", "010"}) {
    const auto arm = arm_of(config);
    ArmSolver solver(arm);
    const auto s = solver.built();
    EXPECT_EQ(s.negative_eigenvalues, 0) << config;
    EXPECT_EQ(s.energy, 0.0);
    EXPECT_EQ(s.cell_states, arm.cell_states);
    EXPECT_NEAR(s.tip_position.z(), arm.level_height.back(), 1e-12);
  }
}

TEST(ArmAnalysis, PretensionReachesItsTensionAndItsSensitivityMatchesFiniteDifferences) {
  const auto arm = arm_of("01");
  ArmSolver solver(arm);
  const auto p = solver.pretension(solver.built(), 1.0);
  ASSERT_TRUE(p.completed) << p.message;
  const auto& s = p.states.back();
  for (int t = 0; t < 3; ++t) EXPECT_NEAR(s.tension[t], 1.0, 1e-8);
  EXPECT_LE(p.states.size(), 8u);  // Newton on the pulls: a few iterations
  // dT/dpull against re-solved equilibria (central differences, 1e-4 mm).
  const Eigen::Matrix3d S = solver.tension_sensitivity(s);
  for (int j = 0; j < 3; ++j) {
    analyses::Pulls up = s.pulls, down = s.pulls;
    up[j] += 1e-4, down[j] -= 1e-4;
    const auto a = solver.ramp(s, up, s.load).states.back();
    const auto b = solver.ramp(s, down, s.load).states.back();
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(S(i, j), (a.tension[i] - b.tension[i]) / 2e-4, 1e-4 * S.cwiseAbs().maxCoeff())
          << i << ", " << j;
    }
  }
  EXPECT_GT(S(0, 0), 0.0);  // pulling a tendon tightens it
}

TEST(ArmAnalysis, SmallTipLoadsAreLinearAndTheComplianceIsSymmetric) {
  // Pretensioned (1 N per tendon), 0.01 N. The compliance's columns are central
  // differences (u(+F) - u(-F)) / 2F: a transverse load also lowers the tip by a term of
  // second order (the arm's shortening as it bends, ~ u_x^2 / 2L), which is not compliance.
  const auto arm = arm_of("010");
  ArmSolver solver(arm);
  const double F = 0.01;
  Eigen::Matrix3d secant;
  analyses::ArmState pretensioned;
  auto tip_motion = [&](const Vector3& load) {
    const auto r = analyses::arm_tip_load(solver, load);
    EXPECT_TRUE(r.completed) << r.message;
    pretensioned = r.pretensioned;
    return Vector3(r.path.states.back().tip_position - r.pretensioned.tip_position);
  };
  for (int k = 0; k < 3; ++k) {
    const Vector3 u1 = tip_motion(F * Vector3::Unit(k)), u2 = tip_motion(2 * F * Vector3::Unit(k));
    EXPECT_NEAR(u2[k] / u1[k], 2.0, 0.02) << "direction " << k;  // twice the load, twice it (1 %)
    secant.col(k) = (u1 - tip_motion(-F * Vector3::Unit(k))) / (2 * F);
  }
  const double largest = secant.cwiseAbs().maxCoeff();
  EXPECT_LT((secant - secant.transpose()).cwiseAbs().maxCoeff(), 1e-3 * largest) << secant;
  const Eigen::Matrix3d C = solver.tip_compliance(pretensioned);
  EXPECT_LT((C - C.transpose()).cwiseAbs().maxCoeff(), 1e-9 * largest);
  EXPECT_LT((C - secant).cwiseAbs().maxCoeff(), 0.02 * largest) << C << "\n" << secant;
}

TEST(ArmAnalysis, AContractedModuleAtTheBaseCostsMoreTipDeflectionThanAtTheTip) {
  // The lever arm: the soft module at the base turns the whole rest of the arm.
  double deflection[2];
  int i = 0;
  for (const std::string config : {"011", "110"}) {
    const auto arm = arm_of(config);
    ArmSolver solver(arm);
    const auto r = analyses::arm_tip_load(solver, Vector3(0.05, 0.0, 0.0));
    ASSERT_TRUE(r.completed) << r.message;
    deflection[i++] = r.path.states.back().tip_position.x() - r.pretensioned.tip_position.x();
  }
  EXPECT_GT(deflection[0], 1.2 * deflection[1]);
}

TEST(ArmAnalysis, PullingAllTendonsSnapsAnExtendedModuleNearTheCellsSnapForce) {
  const auto arm = arm_of("1");
  ArmSolver solver(arm);
  const auto r = analyses::arm_pull_until_snap(solver, solver.built(), {1.0, 1.0, 1.0}, 30.0);
  ASSERT_TRUE(r.snapped) << r.message;
  const double cell = analyses::snap_through(optimum()).snap_force;  // 8.99 N
  EXPECT_NEAR(r.tension_sum / cell, 1.0, 0.2) << r.tension_sum << " vs " << cell;
  EXPECT_EQ(r.snapped_module, 0);
  EXPECT_TRUE(r.release_converged) << r.message;
  ASSERT_EQ(r.snapped_cells.size(), 1u);  // one cell snaps; the tendon slackens, the other re-extends
  EXPECT_EQ(r.configuration_after, "x");
  EXPECT_EQ(r.after.negative_eigenvalues, 0);
  // The path passed the force's maximum (about the cell's snap force) before it was lost.
  double peak = 0.0;
  for (const auto& s : r.path.states) peak = std::max(peak, s.tension[0] + s.tension[1] + s.tension[2]);
  EXPECT_NEAR(peak / cell, 1.0, 0.05);
  EXPECT_LT(r.tension_sum, peak);
}

TEST(ArmAnalysis, LoadCapacityStopsWhereATendonGoesSlack) {
  const auto arm = arm_of("1");
  ArmSolver solver(arm);
  const auto p = solver.pretension(solver.built(), 1.0);
  ASSERT_TRUE(p.completed);
  const auto r = analyses::arm_load_capacity(solver, p.states.back(), Vector3(1.0, 0.0, 0.0), 30.0);
  EXPECT_EQ(r.limit, "slack") << r.message;
  EXPECT_EQ(r.tendon, 0);  // tendon 1 (on +x) is on the side that shortens
  EXPECT_GT(r.load, 0.1);
  EXPECT_LT(r.path.states.back().tension[0], 0.01);
  // Just below the limit the tendon is still taut.
  EXPECT_GT(r.path.states.back().tension[0], 0.0);
}

TEST(ArmAnalysis, BadInputNamesTheParameter) {
  const auto arm = arm_of("1");
  ArmSolver solver(arm);
  EXPECT_NE(error_of([&] { analyses::arm_tip_load(solver, Vector3::Zero(), {-1.0, 0.0, 0.0}); })
                .find("pulls[0] = -1 mm makes tendon 1 longer than its slack length"),
            std::string::npos);
  EXPECT_NE(error_of([&] { solver.ramp(solver.built(), {0.0, 200.0, 0.0}, Vector3::Zero()); })
                .find("pulls[1] = 200 is invalid: must be below tendon 2's slack length"),
            std::string::npos);
  // Letting a tendon out is an actuation input of the ramp: it just goes slack.
  const auto out = solver.ramp(solver.built(), {0.0, -1.0, 0.0}, Vector3::Zero());
  EXPECT_TRUE(out.completed);
  EXPECT_EQ(out.states.back().tension[1], 0.0);
  EXPECT_NE(error_of([&] { analyses::arm_pull_until_snap(solver, solver.built(), {1, -1, 1}, 5.0); })
                .find("direction[1]"),
            std::string::npos);
  EXPECT_NE(error_of([&] { analyses::arm_tip_load(solver, Vector3::Zero(), {}, -1.0); })
                .find("pretension"),
            std::string::npos);
  EXPECT_NE(error_of([&] { analyses::arm_load_capacity(solver, solver.built(), Vector3::Zero(), 1.0); })
                .find("direction"),
            std::string::npos);
  EXPECT_NE(error_of([&] { analyses::arm_load_capacity(solver, solver.built(), Vector3::UnitX(), -1.0); })
                .find("max_load"),
            std::string::npos);
  analyses::ArmOptions o;
  o.steps = 0;
  EXPECT_NE(error_of([&] { ArmSolver bad(arm, o); }).find("steps"), std::string::npos);
}

TEST(ArmAnalysis, TheSoftestModeAtTheSnapPointsAtTheModuleThatSnaps) {
  // Where pulling all tendons loses equilibrium, the mode losing its stiffness changes the
  // height of a cell of the module that the release then finds switched.
  for (const std::string config : {"1", "110", "011"}) {
    const auto arm = arm_of(config);
    ArmSolver solver(arm);
    const auto r = analyses::arm_pull_until_snap(solver, solver.built(), {1.0, 1.0, 1.0}, 60.0);
    ASSERT_TRUE(r.snapped) << config << ": " << r.message;
    ASSERT_GE(r.path.critical_cell, 0) << config;
    EXPECT_EQ(r.path.critical_cell / 2, r.snapped_module) << config;
  }
}
