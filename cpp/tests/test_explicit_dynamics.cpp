// Explicit central differences (solvers/explicit_dynamics.hpp) and their stable step
// (solvers/stable_time_step.hpp) on a mass on a linear spring, against closed forms.
//
// Undamped, the scheme is the recurrence u_{n+1} - 2 u_n + u_{n-1} = -(w dt)^2 u_n exactly
// (no Newton: only rounding, ~1e-16 per step, hence 1e-12 over 2,000 steps); it is stable
// for w dt <= 2, so the stable step of one mass on a spring is 2 / w.

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "kresling/model/model.hpp"
#include "oscillator_test_helpers.hpp"
#include "kresling/solvers/explicit_dynamics.hpp"
#include "kresling/solvers/stable_time_step.hpp"

using namespace kresling;
using kresling::test::oscillator;

namespace {

solvers::ExplicitOptions options(double dt, double duration) {
  solvers::ExplicitOptions o;
  o.time_step = dt;
  o.duration = duration;
  return o;
}

const VectorX kStart = (VectorX(3) << 1.0, 0.0, 0.0).finished();

}  // namespace

TEST(Explicit, StableStepOfAMassOnASpringIsTwoOverOmega) {
  const double k = 4.0, m = 1e-3, w = std::sqrt(k / m);
  const auto s = solvers::stable_time_step(oscillator(k), VectorX::Constant(3, m));
  EXPECT_NEAR(s.omega_max, w, 1e-12 * w);
  EXPECT_NEAR(s.time_step, 2.0 / w, 1e-12 / w);
  EXPECT_GE(s.omega_bound, s.omega_max * (1.0 - 1e-15));
  // Rayleigh damping shortens it: w dt = 2 (sqrt(1 + xi^2) - xi), xi = a / (2 w) + b w / 2.
  const double a = 3.0, b = 2e-3, xi = a / (2 * w) + b * w / 2;
  const auto d = solvers::stable_time_step(oscillator(k), VectorX::Constant(3, m), VectorX(), a, b);
  EXPECT_NEAR(d.time_step * w, 2.0 * (std::sqrt(1 + xi * xi) - xi), 1e-12);
}

TEST(Explicit, IsTheCentralDifferenceRecurrenceAndKeepsItsEnergyBounded) {
  const double k = 4.0, m = 1e-3, w = std::sqrt(k / m), dt = 0.2 / w;  // w dt = 0.2
  const auto h = solvers::integrate_explicit(oscillator(k), VectorX::Constant(3, m),
                                             solvers::TimeLoad{}, options(dt, 2000 * dt), kStart);
  ASSERT_TRUE(h.path.completed) << h.path.message;
  ASSERT_EQ(h.path.steps.size(), 2000u);
  EXPECT_NEAR(h.stable_time_step, 2.0 / w, 1e-12 / w);
  const double Omega2 = (w * dt) * (w * dt);
  double worst = 0.0, worst_energy = 0.0;
  for (std::size_t i = 1; i + 1 < h.path.steps.size(); ++i) {
    const double um = h.path.steps[i - 1].displacement[0], u = h.path.steps[i].displacement[0],
                 up = h.path.steps[i + 1].displacement[0];
    worst = std::max(worst, std::abs(up - (2.0 - Omega2) * u + um));
    worst_energy = std::max(worst_energy, std::abs(h.kinetic[i] + h.strain[i] - 0.5 * k) / (0.5 * k));
  }
  EXPECT_LT(worst, 1e-12);
  // The energy at whole steps differs from the scheme's conserved one by at most
  // (w dt)^2 / 4 of it: no drift over 64 periods.
  EXPECT_LT(worst_energy, Omega2 / 4 / (1 - Omega2 / 4));
  EXPECT_GT(worst_energy, 1e-3 * Omega2);  // (and it is the scheme's, not exact)
}

TEST(Explicit, AStepLoadOscillatesAboutItsStaticDeflectionAndBalancesWork) {
  const double k = 4.0, m = 1e-3, w = std::sqrt(k / m), dt = 0.01 / w, F = 2.0;
  solvers::TimeLoad load{{{(VectorX(3) << F, 0.0, 0.0).finished(), {}}}};
  const auto h = solvers::integrate_explicit(oscillator(k), VectorX::Constant(3, m), load,
                                             options(dt, 20 * 2 * 3.14159265358979 / w));
  ASSERT_TRUE(h.path.completed) << h.path.message;
  double top = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < h.path.steps.size(); ++i) {
    top = std::max(top, h.path.steps[i].displacement[0]);
    worst = std::max(worst, std::abs(h.kinetic[i] + h.strain[i] - h.work[i]));
  }
  EXPECT_NEAR(top, 2 * F / k, 1e-3 * F / k);
  EXPECT_LT(worst, 1e-4 * F * F / k);  // O((w dt)^2) = 1e-4 of the energy in play
}

TEST(Explicit, RefusesAStepAboveTheStableOneAndBadInput) {
  const double k = 4.0, m = 1e-3, w = std::sqrt(k / m);
  const VectorX masses = VectorX::Constant(3, m);
  EXPECT_THROW(solvers::integrate_explicit(oscillator(k), masses, {}, options(2.001 / w, 1.0), kStart),
               std::invalid_argument);
  const auto h = solvers::integrate_explicit(oscillator(k), masses, {}, options(1.999 / w, 1.0), kStart);
  EXPECT_TRUE(h.path.completed) << h.path.message;
  EXPECT_THROW(solvers::integrate_explicit(oscillator(k), VectorX::Zero(3), {}, options(1e-3, 1.0)),
               std::invalid_argument);
  auto o = options(1e-3, 1.0);
  o.record_every = 0;
  EXPECT_THROW(solvers::integrate_explicit(oscillator(k), masses, {}, o), std::invalid_argument);
  o = options(1e-12, 1.0);  // 1e12 steps
  EXPECT_THROW(solvers::integrate_explicit(oscillator(k), masses, {}, o), std::invalid_argument);
}
