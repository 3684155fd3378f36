// Nonlinear solvers against closed forms: the von Mises two-bar truss (limit points, passed
// by MGDCM), Newton's reported status, and displacement control of a bar chain whose
// answer is linear in position.
//
// The truss: bars of the linear (Saint Venant-Kirchhoff) law, S = C0 E, half-span a, rise h,
// length L = sqrt(a^2 + h^2). With the apex at height z it carries
//     P(z) = A C0 z (h^2 - z^2) / L^3,
// with limit points at z = +-h / sqrt(3), P_max = 2 A C0 h^3 / (3 sqrt(3) L^3). The load acts
// through a soft vertical spring bar (Ogden law, axial force A C0/4 (s^4 - 1), monotone in
// the stretch s) on top of the apex, so that the loaded point snaps back.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/solvers/displacement_control.hpp"
#include "kresling/solvers/force_control.hpp"
#include "kresling/solvers/mgdcm.hpp"
#include "kresling/solvers/newton.hpp"

using namespace kresling;
using elements::BarLawKind;

namespace {

constexpr double kHalfSpan = 10.0, kRise = 1.0, kModulus = 1000.0, kArea = 1.0;
constexpr double kSpringLength = 10.0, kSpringArea = 0.005;  // 0.5 N/mm < max |dP/dz| ~ 0.98
const double kLength = std::hypot(kHalfSpan, kRise);
const double kMaxLoad =
    2 * kArea * kModulus * std::pow(kRise, 3) / (3 * std::sqrt(3.0) * std::pow(kLength, 3));
constexpr Index kApexZ = 3 * 2 + 2, kTopZ = 3 * 3 + 2;
// Newton stops at ||du|| <= 1e-6 mm and converges quadratically: the residual left is orders
// below 1e-9 of the load scale P_max (~0.38 N), which still resolves any wrong term.
constexpr double kEquilibriumTol = 1e-9;

double truss_load(double z) {
  return kArea * kModulus * z * (kRise * kRise - z * z) / std::pow(kLength, 3);
}
double spring_compression(double length) {
  const double s = length / kSpringLength;
  return -kSpringArea * kModulus / 4 * (std::pow(s, 4) - 1);
}

// Nodes: the two supports, the apex, the spring's top; apex and top move along z only.
model::Model truss(double rise = kRise) {
  NodeMatrix X(4, 3);
  X << -kHalfSpan, 0, 0, kHalfSpan, 0, 0, 0, 0, rise, 0, 0, rise + kSpringLength;
  const double L = std::hypot(kHalfSpan, rise);
  const elements::BarLaw svk{BarLawKind::Linear, kModulus}, ogden{BarLawKind::Ogden, kModulus};
  std::vector<model::Bar> bars = {{{0, 2}, kArea, L, svk},
                                  {{1, 2}, kArea, L, svk},
                                  {{2, 3}, kSpringArea, kSpringLength, ogden}};
  return model::Model(X, bars, {}, {1, 1, 1, 1, 1, 1, 1, 1, 0, 1, 1, 0});
}

VectorX load_on(const model::Model& m, Index dof, double value) {
  VectorX f = VectorX::Zero(m.num_dofs());
  f[dof] = value;
  return f;
}

}  // namespace

TEST(Newton, ConvergedStatusAndEquilibriumOfTheTruss) {
  const model::Model m = truss();
  assembly::Assembler a(m, assembly::unmasked_dofs(m.fixed()), 1e-8, assembly::Storage::Lower);
  solvers::TangentSolver solver;
  VectorX u = VectorX::Zero(m.num_dofs());
  const double P = 0.5 * kMaxLoad;
  const auto out = solvers::newton_equilibrium(a, solver, u, load_on(m, kTopZ, -P), {});
  ASSERT_TRUE(out.converged) << out.failure;
  EXPECT_TRUE(out.failure.empty());
  // Quadratic convergence from rest: a handful of iterations, at least one.
  EXPECT_GE(out.iterations, 2);
  EXPECT_LE(out.iterations, 8);
  EXPECT_EQ(out.negative_eigenvalues, 0);  // the near branch below the limit load is stable
  const double z = kRise + u[kApexZ];
  EXPECT_GT(z, kRise / std::sqrt(3.0));
  EXPECT_NEAR(truss_load(z), P, kEquilibriumTol * kMaxLoad);
}

// NewtonOptions::give_up_wandering: a solve that closes in on the equilibrium near its start
// is unchanged by it, to the last bit; one whose corrections grow past that many times its
// first ends there, saying so, instead of wandering on. From the equilibrium at 0.9 P_max,
// 1.05 P_max has no equilibrium near: plain Newton wanders for its 50 iterations (measured:
// corrections of 0.2 to 5 mm, never converging), watched it stops at iteration 4, its
// correction 17.5 times its first.
TEST(Newton, GivesUpWhenItsCorrectionsWanderOff) {
  const model::Model m = truss();
  assembly::Assembler a(m, assembly::unmasked_dofs(m.fixed()), 1e-8, assembly::Storage::Lower);
  solvers::TangentSolver solver;
  solvers::NewtonOptions watched;
  watched.give_up_wandering = 10.0;
  const VectorX below = load_on(m, kTopZ, -0.5 * kMaxLoad);
  VectorX u_plain = VectorX::Zero(m.num_dofs()), u_watched = u_plain;
  const auto plain = solvers::newton_equilibrium(a, solver, u_plain, below, {});
  const auto near = solvers::newton_equilibrium(a, solver, u_watched, below, watched);
  ASSERT_TRUE(plain.converged && near.converged) << near.failure;
  EXPECT_EQ(near.iterations, plain.iterations);
  EXPECT_EQ(u_watched, u_plain);

  VectorX start = VectorX::Zero(m.num_dofs());
  ASSERT_TRUE(
      solvers::newton_equilibrium(a, solver, start, load_on(m, kTopZ, -0.9 * kMaxLoad), {})
          .converged);
  const VectorX above = load_on(m, kTopZ, -1.05 * kMaxLoad);
  VectorX u = start;
  const auto wandered = solvers::newton_equilibrium(a, solver, u, above, watched);
  EXPECT_FALSE(wandered.converged);
  EXPECT_LE(wandered.iterations, 6);
  EXPECT_NE(wandered.failure.find("Newton wandered off"), std::string::npos)
      << wandered.failure;
  VectorX v = start;
  const auto unwatched = solvers::newton_equilibrium(a, solver, v, above, {});
  EXPECT_FALSE(unwatched.converged);
  EXPECT_EQ(unwatched.iterations, solvers::NewtonOptions{}.max_iterations);
}

TEST(Newton, NonConvergenceIsAStatusNotAnException) {
  const model::Model m = truss();
  assembly::Assembler a(m, assembly::unmasked_dofs(m.fixed()), 1e-8, assembly::Storage::Lower);
  solvers::TangentSolver solver;
  // Two iterations cannot reach 1e-6 mm from rest under 0.9 P_max (the first correction is
  // ~0.3 mm and the problem is far from linear there).
  for (int limit_by_argument : {0, 2}) {
    VectorX u = VectorX::Zero(m.num_dofs());
    solvers::NewtonOptions options;
    if (limit_by_argument == 0) options.max_iterations = 2;
    solvers::NewtonOutcome out;
    const VectorX load = load_on(m, kTopZ, -0.9 * kMaxLoad);
    EXPECT_NO_THROW(out = solvers::newton_equilibrium(a, solver, u, load, options,
                                                     limit_by_argument));
    EXPECT_FALSE(out.converged);
    EXPECT_EQ(out.iterations, 2);
    EXPECT_NE(out.failure.find("did not converge in 2 iterations"), std::string::npos)
        << out.failure;
  }
  // A flat truss has no stiffness across its span at rest: the apex is a mechanism, which
  // the diagonal shift turns into an unbounded correction, reported as such.
  const model::Model flat = truss(0.0);
  assembly::Assembler b(flat, assembly::unmasked_dofs(flat.fixed()), 1e-8,
                        assembly::Storage::Lower);
  solvers::TangentSolver flat_solver;
  VectorX u = VectorX::Zero(flat.num_dofs());
  const auto out = solvers::newton_equilibrium(b, flat_solver, u, load_on(flat, kApexZ, -1.0), {});
  EXPECT_FALSE(out.converged);
  EXPECT_EQ(out.iterations, 1);
  EXPECT_NE(out.failure.find("mechanism"), std::string::npos) << out.failure;
}

TEST(ForceControl, TrussFollowsTheClosedFormThenSnapsThrough) {
  // Load-stepped Newton cannot follow the falling branch: past P_max the apex snaps to the
  // inverted branch (z < -h), where the closed form admits the load again.
  const model::Model m = truss();
  const double total = 1.2 * kMaxLoad;
  const auto r = solvers::solve_force_control(m, load_on(m, kTopZ, -total), 12);
  ASSERT_TRUE(r.completed) << r.message;
  ASSERT_EQ(r.steps.size(), 12u);
  for (const auto& step : r.steps) {
    const double z = kRise + step.displacement[kApexZ], P = step.load_factor * total;
    EXPECT_NEAR(truss_load(z), P, kEquilibriumTol * kMaxLoad);
    if (P <= kMaxLoad) EXPECT_GT(z, kRise / std::sqrt(3.0)) << "P = " << P;
    else EXPECT_LT(z, -kRise) << "P = " << P;
  }
}

TEST(Mgdcm, PassesTheLimitPointsOfTheTrussInEquilibrium) {
  const model::Model m = truss();
  const VectorX F = load_on(m, kTopZ, -1.0);
  solvers::MgdcmOptions o;
  o.initial_load_factor = 0.01;
  o.max_step_factor = 0.01;
  o.max_increments = 5000;
  o.monitor_dof = kApexZ;
  o.max_displacement = 2.2 * kRise;
  const auto r = solvers::solve_mgdcm(m, F, o);
  ASSERT_TRUE(r.completed) << r.message;
  EXPECT_LT(r.steps.back().displacement[kApexZ], -2.2 * kRise);

  assembly::Assembler a(m, assembly::unmasked_dofs(m.fixed()), 0.0);
  VectorX f;
  std::size_t peak = 0, trough = 0;
  bool top_rose = false, top_fell = false;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const auto& s = r.steps[i];
    a.assemble(s.displacement, f, false);
    const VectorX residual = solvers::gather_rows(a, s.load_factor * F - f);
    ASSERT_LE(residual.norm(), kEquilibriumTol * kMaxLoad) << "step " << i;
    const double z = kRise + s.displacement[kApexZ];
    EXPECT_NEAR(truss_load(z), s.load_factor, kEquilibriumTol * kMaxLoad) << "step " << i;
    const double top = kRise + kSpringLength + s.displacement[kTopZ];
    EXPECT_NEAR(spring_compression(top - z), s.load_factor, kEquilibriumTol * kMaxLoad);
    if (i == 0) continue;
    const double dtop = s.displacement[kTopZ] - r.steps[i - 1].displacement[kTopZ];
    top_fell |= dtop < 0;
    top_rose |= dtop > 1e-6;
    const double dl = s.load_factor - r.steps[i - 1].load_factor;
    if (peak == 0 && dl < 0) peak = i - 1;
    if (peak != 0 && trough == 0 && dl > 0) trough = i - 1;
  }
  // The load rises to the limit load, sampled to within the step (O(dz^2) below it), falls
  // through zero to -P_max and rises again; the loaded point moves back up on the way (a
  // snap-back, which displacement control of that point could not follow).
  ASSERT_GT(peak, 0u);
  ASSERT_GT(trough, peak);
  EXPECT_LE(r.steps[peak].load_factor, kMaxLoad * (1 + 1e-9));
  EXPECT_GE(r.steps[peak].load_factor, kMaxLoad * (1 - 1e-3));
  EXPECT_GE(r.steps[trough].load_factor, -kMaxLoad * (1 + 1e-9));
  EXPECT_LE(r.steps[trough].load_factor, -kMaxLoad * (1 - 1e-3));
  EXPECT_TRUE(top_fell && top_rose);
}

TEST(DisplacementControl, BarChainStretchesUniformly) {
  // Collinear bars of one law, modulus and area, different lengths, the far end driven
  // along the line: equal forces mean equal stretches s, so every node moves in proportion
  // to its distance from the support (exactly, at any strain), and the actuator feels
  // -A S(E) s with E = (s^2 - 1) / 2.
  // Node 5, held and unattached, only anchors the line: a rotation about the chain's own
  // line moves none of its nodes, and the rigid-body check would count it as free.
  NodeMatrix X(6, 3);
  X << 0, 0, 0, 1.0, 0, 0, 2.5, 0, 0, 3.0, 0, 0, 5.0, 0, 0, 0, 1.0, 1.0;
  std::vector<model::Bar> bars;
  for (Index i = 0; i < 4; ++i) {
    bars.push_back({{i, i + 1}, kArea, X(i + 1, 0) - X(i, 0), {BarLawKind::Linear, kModulus}});
  }
  std::vector<std::uint8_t> fixed(18, 1);
  for (int i = 1; i < 5; ++i) fixed[3 * i] = 0;  // x free, y and z held
  const model::Model m(X, bars, {}, fixed);
  for (double end : {1.0, -1.0}) {  // stretched to s = 1.2, compressed to s = 0.8
    VectorX prescribed = VectorX::Zero(18);
    prescribed[12] = end;
    const auto r = solvers::solve_displacement_control(m, prescribed, 10);
    ASSERT_TRUE(r.completed) << r.message;
    ASSERT_EQ(r.steps.size(), 10u);
    ASSERT_EQ(r.constraint_dofs, std::vector<Index>{12});
    for (std::size_t k = 0; k < r.steps.size(); ++k) {
      const auto& step = r.steps[k];
      // k * (1 / steps) against (k + 1) / 10: a rounding or two apart.
      EXPECT_NEAR(step.load_factor, (k + 1) / 10.0, 1e-14);
      const double s = 1 + step.load_factor * end / 5.0;
      // Newton's last correction is at most 1e-6 mm and quadratic convergence leaves far
      // less; 1e-9 mm (and the force it implies, C0 A / L 1e-9) resolves any error.
      for (Index i = 1; i < 5; ++i) {
        EXPECT_NEAR(step.displacement[3 * i], (s - 1) * X(i, 0), 1e-9) << "node " << i;
      }
      EXPECT_NEAR(step.constraint_force[0], -kArea * kModulus * (s * s - 1) / 2 * s,
                  1e-9 * kModulus);
    }
  }
}

TEST(DisplacementControl, ExtrapolatedStartsReachTheSameEquilibria) {
  // The truss's spring top driven 0.5 mm down in 20 increments, each Newton solve started
  // from the last equilibrium or from a linear, quadratic or cubic extrapolation through the
  // last 2, 3 or 4: every step is an equilibrium of the closed form (the spring's force is
  // the truss's load at the apex), the apex within Newton's tolerance of the one from the
  // last equilibrium, and a higher order never needs more iterations in all.
  const model::Model m = truss();
  VectorX prescribed = VectorX::Zero(m.num_dofs());
  prescribed[kTopZ] = -0.5 * kRise;
  std::vector<solvers::PathResult> paths;
  for (int order = 0; order <= 3; ++order) {
    solvers::DisplacementControlOptions o;
    o.extrapolation = order;
    paths.push_back(solvers::solve_displacement_control(m, prescribed, 20, o));
    const auto& r = paths.back();
    ASSERT_TRUE(r.completed) << "order " << order << ": " << r.message;
    ASSERT_EQ(r.steps.size(), 20u);
    for (std::size_t k = 0; k < r.steps.size(); ++k) {
      const VectorX& u = r.steps[k].displacement;
      const double z = kRise + u[kApexZ];
      const double spring = spring_compression(kSpringLength + u[kTopZ] - u[kApexZ]);
      EXPECT_NEAR(spring, truss_load(z), kEquilibriumTol) << "order " << order << ", step " << k;
      EXPECT_NEAR(u[kApexZ], paths.front().steps[k].displacement[kApexZ], 1e-6)
          << "order " << order << ", step " << k;
    }
  }
  auto iterations = [](const solvers::PathResult& r) {
    int total = 0;
    for (const auto& step : r.steps) total += step.iterations;
    return total;
  };
  for (int order = 1; order <= 3; ++order) {
    EXPECT_LE(iterations(paths[order]), iterations(paths[order - 1])) << "order " << order;
  }
  EXPECT_LT(iterations(paths[3]), iterations(paths[0]));
  solvers::DisplacementControlOptions quartic;
  quartic.extrapolation = 4;
  try {
    solvers::solve_displacement_control(m, prescribed, 20, quartic);
    ADD_FAILURE() << "extrapolation = 4 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0, 1, 2 or 3"), std::string::npos) << e.what();
  }
}

TEST(DisplacementControl, ExtrapolatedStartsFollowASnapAsThePreviousEquilibriumDoes) {
  // The spring top driven 1.5 mm down: the spring (0.5 N/mm) is softer than the truss at
  // its steepest, so past the limit load the apex snaps through to the far branch. An
  // extrapolated guess then lies beyond the end of the near branch and Newton fails there;
  // the increment is retried from the previous equilibrium, from which Newton reaches the
  // far branch as in MERLIN2's sequence. Before, the extrapolated starts halved the
  // increment ten times and gave up at 90 % of the motion. Every order now runs to the end
  // on the same far branch (measured: the apex at -0.877 mm, the same to 2e-14 mm), every
  // step an equilibrium of the closed form.
  const model::Model m = truss();
  VectorX prescribed = VectorX::Zero(m.num_dofs());
  prescribed[kTopZ] = -1.5 * kRise;
  double far = 0.0;
  for (int order = 0; order <= 3; ++order) {
    solvers::DisplacementControlOptions o;
    o.extrapolation = order;
    const auto r = solvers::solve_displacement_control(m, prescribed, 20, o);
    ASSERT_TRUE(r.completed) << "order " << order << ": " << r.message;
    for (const auto& step : r.steps) {
      const VectorX& u = step.displacement;
      const double spring = spring_compression(kSpringLength + u[kTopZ] - u[kApexZ]);
      EXPECT_NEAR(spring, truss_load(kRise + u[kApexZ]), kEquilibriumTol) << "order " << order;
    }
    const double apex = kRise + r.steps.back().displacement[kApexZ];
    EXPECT_LT(apex, -kRise / std::sqrt(3.0)) << "order " << order;  // past the lower limit point
    if (order == 0) far = apex;
    EXPECT_NEAR(apex, far, 1e-6) << "order " << order;
  }
}

TEST(DisplacementControl, APathAdaptiveIncrementsCannotFinishIsFollowedInFixedSteps) {
  // The spring top driven 3.4 mm down in 5 samples: past the snap the adaptive increments'
  // predictor leads Newton nowhere and they give up (at 0.4 of the motion), while fixed
  // steps from the last equilibrium cross it. The solver follows the path again in fixed
  // steps and returns their result, bit for bit, the attempts of both runs counted.
  const model::Model m = truss();
  VectorX prescribed = VectorX::Zero(m.num_dofs());
  prescribed[kTopZ] = -3.4 * kRise;
  solvers::DisplacementControlOptions o;
  o.extrapolation = 2;
  const auto fixed = solvers::solve_displacement_control(m, prescribed, 5, o);
  o.adaptive = true;
  const auto adaptive = solvers::solve_displacement_control(m, prescribed, 5, o);
  ASSERT_TRUE(fixed.completed) << fixed.message;
  ASSERT_TRUE(adaptive.completed) << adaptive.message;
  ASSERT_EQ(adaptive.steps.size(), fixed.steps.size());
  for (std::size_t k = 0; k < fixed.steps.size(); ++k) {
    EXPECT_EQ(adaptive.steps[k].load_factor, fixed.steps[k].load_factor);
    EXPECT_EQ((adaptive.steps[k].displacement - fixed.steps[k].displacement).cwiseAbs().maxCoeff(),
              0.0);
    EXPECT_EQ(adaptive.steps[k].constraint_force[0], fixed.steps[k].constraint_force[0]);
  }
  EXPECT_GT(adaptive.attempted_increments, fixed.attempted_increments);
  EXPECT_LT(kRise + fixed.steps.back().displacement[kApexZ], -kRise / std::sqrt(3.0));
}

TEST(DisplacementControl, RefusesFreeRigidBodyMotions) {
  const model::Model m = truss();
  const model::Model loose(m.nodes(), m.bars(), {}, std::vector<std::uint8_t>(12, 0));
  VectorX prescribed = VectorX::Zero(12);
  prescribed[kTopZ] = -1.0;
  EXPECT_THROW(solvers::solve_displacement_control(loose, prescribed, 5), std::invalid_argument);
}

TEST(DisplacementControl, KeepsItsWorkspaceAndNoModelBetweenSolves) {
  // A reusable solver outlives the models it solved (a test run over many designs builds
  // each specimen inside its run): solving a model that is then destroyed, then another of
  // the same connectivity, reuses the workspace and refers to nothing of the first (under
  // make sanitize a read of the dead model would be reported). Each path equals a fresh
  // solver's bitwise: the reused pattern and factorisation change no arithmetic.
  solvers::DisplacementControl reused;
  VectorX prescribed;
  {
    const model::Model gone = truss(kRise * 1.1);
    prescribed = VectorX::Zero(gone.num_dofs());
    prescribed[11] = -0.5 * kRise;
    ASSERT_TRUE(reused.solve(gone, prescribed, 10).completed);
  }
  for (double rise : {kRise, 0.9 * kRise}) {
    const model::Model m = truss(rise);
    const auto r = reused.solve(m, prescribed, 10);
    const auto fresh = solvers::solve_displacement_control(m, prescribed, 10);
    ASSERT_TRUE(r.completed) << r.message;
    ASSERT_EQ(r.steps.size(), fresh.steps.size());
    for (std::size_t k = 0; k < r.steps.size(); ++k) {
      EXPECT_EQ((r.steps[k].displacement - fresh.steps[k].displacement).cwiseAbs().maxCoeff(), 0.0);
      EXPECT_EQ(r.steps[k].constraint_force[0], fresh.steps[k].constraint_force[0]);
    }
  }
}

TEST(DisplacementControl, AdaptiveLocatesALawKinkInAFewSolves) {
  // One hinge of the enhanced linear law: a fixed triangle (0, 1, 2) and a wing node 3 held
  // by two stiff bars to the axis 0 -> 1, driven 3 mm down so that the hinge opens 0.39 rad,
  // past its limit 0.3 rad from rest (at 0.75 of the motion). The adaptive path must agree
  // with the fixed steps' Newton-converged samples to 1e-8 of the largest force (its
  // stated accuracy, with the 1e-9 tolerance) and locate the kink by aimed steps. Its force
  // error keeps the increments at one sample here, so the attempts beyond one per sample are
  // the start, the location and the step on to the next sample: 4 (two aimed solves); a
  // bisection from one sample to 1e-3 of one needs 10 halvings.
  const double alpha = 0.5;
  NodeMatrix X(4, 3);
  X << 0, 0, 0, 10, 0, 0, 5, -8, 0, 5, 8 * std::cos(alpha), 8 * std::sin(alpha);
  const Vector3 a = X.row(0), b = X.row(1), c = X.row(2), d = X.row(3);
  const double rest = elements::dihedral_angle(a, b, c, d);
  const elements::BarLaw svk{BarLawKind::Linear, 1e4};
  std::vector<model::Bar> bars = {{{0, 3}, 1.0, (d - a).norm(), svk},
                                  {{1, 3}, 1.0, (d - b).norm(), svk}};
  elements::SpringLaw law;
  law.theta1 = rest - 0.3;
  law.theta2 = rest + 0.3;
  std::vector<model::Hinge> hinges = {{{0, 1, 2, 3}, 1.0, rest, 10.0, law}};
  const model::Model m(X, bars, hinges, {1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0});
  VectorX prescribed = VectorX::Zero(m.num_dofs());
  prescribed[11] = -3.0;
  const int steps = 20;
  const auto fixed = solvers::solve_displacement_control(m, prescribed, steps);
  solvers::DisplacementControlOptions options;
  options.adaptive = true;
  const auto adaptive = solvers::solve_displacement_control(m, prescribed, steps, options);
  ASSERT_TRUE(fixed.completed) << fixed.message;
  ASSERT_TRUE(adaptive.completed) << adaptive.message;
  ASSERT_EQ(adaptive.steps.size(), fixed.steps.size());
  double largest = 0.0;
  for (const auto& step : fixed.steps) {
    largest = std::max(largest, std::abs(step.constraint_force[0]));
  }
  for (std::size_t k = 0; k < fixed.steps.size(); ++k) {
    EXPECT_NEAR(adaptive.steps[k].constraint_force[0], fixed.steps[k].constraint_force[0],
                1e-8 * largest)
        << "sample " << k + 1;
  }
  // The kink is crossed: the last sample's hinge is past the limit.
  const VectorX& u = fixed.steps.back().displacement;
  const Vector3 d_end = d + u.segment<3>(9);
  const double theta_end = elements::dihedral_angle(a, b, c, d_end);
  EXPECT_TRUE(theta_end < law.theta1 || theta_end > law.theta2) << theta_end;
  EXPECT_LE(adaptive.attempted_increments, steps + 6);
}

// Displacement control's Newton stops at max_iterations even where reject_iterations (25 by
// default) would let an increment take more: no accepted increment exceeds either bound.
TEST(DisplacementControl, NewtonNeverExceedsMaxIterations) {
  for (int max_iterations : {2, 3, 50}) {
    solvers::DisplacementControlOptions o;
    o.newton.max_iterations = max_iterations;
    o.newton.tolerance = 1e-12;
    for (bool adaptive : {false, true}) {
      o.adaptive = adaptive;
      // The truss's spring top driven down 1.5 mm: the apex follows through the spring.
      const model::Model model = truss();
      const auto path = solvers::solve_displacement_control(model, load_on(model, kTopZ, -1.5),
                                                            4, o);
      for (const auto& step : path.steps) {
        EXPECT_LE(step.iterations, std::min(max_iterations, o.reject_iterations - 1))
            << max_iterations << (adaptive ? " adaptive" : " fixed");
      }
    }
  }
}
