// MGDCM as a configuration of the path follower: its control (the corrector that solves the
// load factor with the displacements) and its step policy, run through follow_path on a
// one-DOF snap-through whose equilibrium path is known in closed form.
//
// The von Mises two-bar truss, apex free along z only: bars of the linear (Saint
// Venant-Kirchhoff) law S = C0 E, half-span a, rise h, L = sqrt(a^2 + h^2). With the apex at
// height z it carries the downward load
//     P(z) = A C0 z (h^2 - z^2) / L^3,
// which rises to P_max = 2 A C0 h^3 / (3 sqrt(3) L^3) at z = h / sqrt(3), falls through zero
// at z = 0 to -P_max at z = -h / sqrt(3) and rises again: a load-driven path must pass two
// limit points, between which the tangent stiffness dP/dz is negative.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/mgdcm.hpp"
#include "kresling/solvers/path_follower.hpp"

using namespace kresling;

namespace {

constexpr double kHalfSpan = 10.0, kRise = 1.0, kModulus = 1000.0, kArea = 1.0;
const double kLength = std::hypot(kHalfSpan, kRise);
const double kStiffnessScale = kArea * kModulus / std::pow(kLength, 3);  // P = c z (h^2 - z^2)
const double kMaxLoad = 2 * kStiffnessScale * std::pow(kRise, 3) / (3 * std::sqrt(3.0));
constexpr Index kApexZ = 3 * 2 + 2;

double truss_load(double z) { return kStiffnessScale * z * (kRise * kRise - z * z); }

model::Model one_dof_truss() {
  NodeMatrix X(3, 3);
  X << -kHalfSpan, 0, 0, kHalfSpan, 0, 0, 0, 0, kRise;
  const elements::BarLaw svk{elements::BarLawKind::Linear, kModulus};
  std::vector<model::Bar> bars = {{{0, 2}, kArea, kLength, svk}, {{1, 2}, kArea, kLength, svk}};
  return model::Model(X, bars, {}, {1, 1, 1, 1, 1, 1, 1, 1, 0});
}

}  // namespace

TEST(MgdcmFollowPath, OneDofTrussPassesBothLimitPointsOnTheClosedForm) {
  const model::Model m = one_dof_truss();
  VectorX F = VectorX::Zero(m.num_dofs());
  F[kApexZ] = -1.0;  // unit downward reference load: lambda is the load P [N]
  solvers::MgdcmOptions o;
  o.initial_load_factor = 0.01;
  o.max_step_factor = 0.02;
  o.max_increments = 2000;
  o.monitor_dof = kApexZ;
  o.max_displacement = 1.5 * kRise + kRise;  // stop at z < -1.5 h, past the second limit

  assembly::Assembler assembler(m, assembly::unmasked_dofs(m.fixed()), o.shift,
                                assembly::Storage::Lower);
  solvers::TangentSolver solver(o.newton.cholesky);
  solvers::MgdcmControl control(m, F, o);
  solvers::MgdcmSteps steps(control, o);
  solvers::FollowOptions follow;
  follow.newton = o.newton;
  follow.stop = solvers::mgdcm_stop_rule(o);
  VectorX u = VectorX::Zero(m.num_dofs());
  solvers::PathResult r;
  solvers::follow_path(control, assembler, solver, u, steps, follow, r);
  ASSERT_TRUE(r.completed) << r.message;
  ASSERT_GT(r.steps.size(), 10u);
  EXPECT_LT(kRise + r.steps.back().displacement[kApexZ], -1.5 * kRise);
  EXPECT_EQ(u, r.steps.back().displacement);  // follow_path leaves u at the last step

  // With one free DOF the corrector's constraint (corrections orthogonal to the predictor)
  // leaves z where the predictor put it, and its second iteration solves lambda F = f_int(z)
  // for lambda alone, exactly up to rounding: what is left is the rounding of the bars'
  // forces (~1e3 N/mm^2 times strains ~1e-2, a few ulps; measured: 3e-14 of P_max ~ 0.38 N
  // at worst). 1e-12 of P_max is well above that and far below any wrong term (the
  // predictor's own error, O(dz^2 P''), is ~1e-4 of P_max at these steps).
  constexpr double kClosedFormTol = 1e-12;
  double largest_dz = 0.0, peak = NAN, trough = NAN;
  std::size_t peak_at = 0, trough_at = 0;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const auto& s = r.steps[i];
    const double z = kRise + s.displacement[kApexZ];
    EXPECT_NEAR(s.load_factor, truss_load(z), kClosedFormTol * kMaxLoad) << "step " << i;
    // Between the limit points the tangent dP/dz is negative: one negative eigenvalue
    // (away from them, where the shift of the diagonal could not tip the count).
    if (std::abs(z) < 0.9 * kRise / std::sqrt(3.0)) EXPECT_EQ(s.negative_eigenvalues, 1);
    if (std::abs(z) > 1.1 * kRise / std::sqrt(3.0)) EXPECT_EQ(s.negative_eigenvalues, 0);
    if (i > 0) {
      const double dz = s.displacement[kApexZ] - r.steps[i - 1].displacement[kApexZ];
      EXPECT_LT(dz, 0.0) << "the apex moves down all along, step " << i;
      largest_dz = std::max(largest_dz, std::abs(dz));
    }
    // The first sample after which the load falls is the peak, the first after which it
    // rises again the trough.
    if (i + 1 < r.steps.size()) {
      const double next = r.steps[i + 1].load_factor;
      if (peak_at == 0 && next < s.load_factor) peak = s.load_factor, peak_at = i;
      if (peak_at != 0 && trough_at == 0 && next > s.load_factor) {
        trough = s.load_factor, trough_at = i;
      }
    }
  }
  // The load factor turns at both limit points: it rises to P_max, sampled within the step
  // (a sample within dz of the peak lies at most |P''| dz^2 / 2 below it, |P''| = 6 c z),
  // falls to -P_max, and rises again after it.
  const double sampling = 0.5 * 6 * kStiffnessScale * kRise / std::sqrt(3.0) * largest_dz *
                          largest_dz;
  EXPECT_LE(peak, kMaxLoad * (1 + kClosedFormTol));
  EXPECT_GE(peak, kMaxLoad - sampling);
  EXPECT_GE(trough, -kMaxLoad * (1 + kClosedFormTol));
  EXPECT_LE(trough, -kMaxLoad + sampling);
  ASSERT_GT(peak_at, 0u);
  ASSERT_GT(trough_at, peak_at);

  // solve_mgdcm is this configuration: the same path, bit for bit.
  const solvers::PathResult same = solvers::solve_mgdcm(m, F, o);
  ASSERT_EQ(same.steps.size(), r.steps.size());
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    EXPECT_EQ(same.steps[i].load_factor, r.steps[i].load_factor) << "step " << i;
    EXPECT_EQ(same.steps[i].displacement, r.steps[i].displacement) << "step " << i;
  }
  EXPECT_EQ(same.attempted_increments, r.attempted_increments);
  EXPECT_EQ(same.newton_iterations, r.newton_iterations);
}

TEST(MgdcmFollowPath, RefusesExtraTermsAndAnEmptyIterationBudget) {
  const model::Model m = one_dof_truss();
  VectorX F = VectorX::Zero(m.num_dofs());
  F[kApexZ] = -1.0;
  solvers::MgdcmOptions o;
  assembly::Assembler assembler(m, assembly::unmasked_dofs(m.fixed()), o.shift,
                                assembly::Storage::Lower);
  solvers::TangentSolver solver;
  solvers::MgdcmControl control(m, F, o);
  solvers::MgdcmSteps steps(control, o);
  struct NoTerms final : solvers::ExtraTerms {
    void add_force(const VectorX&, VectorX&) override {}
    void add_tangent(const VectorX&, assembly::Workspace&) override {}
  } none;
  solvers::FollowOptions follow;
  follow.extra = &none;
  VectorX u = VectorX::Zero(m.num_dofs());
  solvers::PathResult r;
  EXPECT_THROW(solvers::follow_path(control, assembler, solver, u, steps, follow, r),
               std::invalid_argument);
  // An increment of more than shrink_above_iterations iterations is rejected: below 1,
  // every increment would be.
  o.shrink_above_iterations = 0;
  try {
    solvers::solve_mgdcm(m, F, o);
    ADD_FAILURE() << "shrink_above_iterations = 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("shrink_above_iterations"), std::string::npos)
        << e.what();
  }
}
