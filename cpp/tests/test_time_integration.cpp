// Implicit time integration (solvers/time_integration.hpp) on a mass on a linear spring,
// against the scheme's own closed forms.
//
// The average acceleration scheme applied to m a + c v + k u = 0 is the exact three-term
// recurrence
//   (m + dt c/2 + dt^2 k/4) u_{n+1} + (-2 m + dt^2 k/2) u_n + (m - dt c/2 + dt^2 k/4) u_{n-1} = 0,
// so undamped u_{n+1} + u_{n-1} = 2 cos(w_h dt) u_n with tan(w_h dt / 2) = w dt / 2, and its
// energy 1/2 m v^2 + 1/2 k u^2 is conserved. Newton's tolerance (1e-12 mm on unit amplitude)
// bounds the deviations: 1e-9 relative leaves three orders of headroom.

#include <cmath>
#include <memory>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include "kresling/model/model.hpp"
#include "oscillator_test_helpers.hpp"
#include "kresling/solvers/time_integration.hpp"

using namespace kresling;
using kresling::test::oscillator;

namespace {

constexpr double kPi = 3.14159265358979323846;

solvers::TimeIntegrationOptions options(double dt, double duration) {
  return test::newmark_options(dt, duration);
}

}  // namespace

TEST(Newmark, PeriodIsTheSchemesAndEnergyIsConservedOver1000Periods) {
  const double k = 4.0, m = 1e-3;  // w = sqrt(k / m) = 63.2 rad/s
  const double w = std::sqrt(k / m), T = 2 * kPi / w, dt = T / 20;
  const model::Model model = oscillator(k);
  const VectorX masses = VectorX::Constant(3, m);
  const VectorX u0 = (VectorX(3) << 1.0, 0.0, 0.0).finished();
  const auto h = solvers::integrate_newmark(model, masses, VectorX::Zero(3), {},
                                            options(dt, 1000 * T), u0);
  ASSERT_TRUE(h.path.completed) << h.path.message;
  ASSERT_EQ(h.path.steps.size(), 20000u);
  const double wh = 2.0 / dt * std::atan(w * dt / 2.0);
  const double energy0 = 0.5 * k;
  double worst_cos = 0.0, worst_energy = 0.0;
  for (std::size_t i = 1; i + 1 < h.path.steps.size(); ++i) {
    const double um = h.path.steps[i - 1].displacement[0], u = h.path.steps[i].displacement[0],
                 up = h.path.steps[i + 1].displacement[0];
    if (std::abs(u) > 0.5) worst_cos = std::max(worst_cos, std::abs((up + um) / (2 * u) - std::cos(wh * dt)));
    const double e = h.kinetic[i] + h.strain[i];
    worst_energy = std::max(worst_energy, std::abs(e - energy0) / energy0);
  }
  EXPECT_LT(worst_cos, 1e-9);
  EXPECT_LT(worst_energy, 1e-9);
  // The scheme's period, not the exact one: after 1000 periods the phase has drifted.
  EXPECT_GT(std::abs(wh - w) / w, 1e-3);
}

TEST(Newmark, RayleighDampingFollowsTheSchemesRecurrence) {
  const double k = 4.0, m = 1e-3, w = std::sqrt(k / m), dt = 2 * kPi / w / 40;
  const double am = 2.0, bk = 1e-3;  // C = am M + bk K
  const double c = am * m + bk * k;
  auto o = options(dt, 200 * dt);
  o.mass_damping = am;
  o.stiffness_damping = bk;
  const auto h = solvers::integrate_newmark(oscillator(k), VectorX::Constant(3, m),
                                            VectorX::Zero(3), {}, o,
                                            (VectorX(3) << 1.0, 0.0, 0.0).finished());
  ASSERT_TRUE(h.path.completed) << h.path.message;
  const double A = m + dt * c / 2 + dt * dt * k / 4, B = -2 * m + dt * dt * k / 2,
               C = m - dt * c / 2 + dt * dt * k / 4;
  for (std::size_t i = 1; i + 1 < h.path.steps.size(); ++i) {
    const double um = h.path.steps[i - 1].displacement[0], u = h.path.steps[i].displacement[0],
                 up = h.path.steps[i + 1].displacement[0];
    EXPECT_NEAR(A * up + B * u + C * um, 0.0, 1e-9 * m) << i;
  }
  // The energy balance closes: kinetic + strain + dissipated = the start's (no load).
  const std::size_t last = h.path.steps.size() - 1;
  EXPECT_NEAR(h.kinetic[last] + h.strain[last] + h.dissipated[last], 0.5 * k, 1e-9 * k);
  EXPECT_LT(h.kinetic[last] + h.strain[last], 0.1 * k);  // and it did decay
}

TEST(Newmark, HhtDampsWhatTheStepCannotResolveAndKeepsTheResolvedMode) {
  const double k = 4.0, m = 1e-3, w = std::sqrt(k / m);
  auto run = [&](double alpha, double dt, int steps) {
    auto o = options(dt, steps * dt);
    o.hht_alpha = alpha;
    const auto h = solvers::integrate_newmark(oscillator(k), VectorX::Constant(3, m),
                                              VectorX::Zero(3), {}, o,
                                              (VectorX(3) << 1.0, 0.0, 0.0).finished());
    EXPECT_TRUE(h.path.completed) << h.path.message;
    const std::size_t last = h.path.steps.size() - 1;
    return (h.kinetic[last] + h.strain[last]) / (0.5 * k);
  };
  // A mode 10 times faster than the step (w dt = 10): HHT alpha = -0.1 removes it, the
  // average acceleration scheme keeps its energy.
  EXPECT_LT(run(-0.1, 10.0 / w, 200), 1e-3);
  EXPECT_NEAR(run(0.0, 10.0 / w, 200), 1.0, 1e-9);
  // A well resolved mode (w dt = 2 pi / 100) keeps its energy to HHT's small loss per
  // step (fourth order in w dt, see below): 100 periods lose under 5 %.
  EXPECT_GT(run(-0.1, 2 * kPi / w / 100, 10000), 0.95);
}

// HHT-alpha on m a + k u = 0 is the exact linear recurrence x_{n+1} = A x_n on x = (u, v, a):
//   m a1 + (1 + alpha) k u1 - alpha k u0 = 0,
//   u1 = u0 + dt v0 + dt^2 ((1/2 - beta) a0 + beta a1),   v1 = v0 + dt ((1 - gamma) a0 + gamma a1).
// The run follows A^n x0 to Newton's tolerance; the modulus rho of A's principal roots is
// what each step keeps of a mode's amplitude: 1 - rho falls as (w dt)^4 for a resolved mode
// (about 0.01 (w dt)^4 at alpha = -0.1) and is large for an unresolved one.
namespace {

Eigen::Matrix3d hht_amplification(double k, double m, double dt, double alpha) {
  const double beta = 0.25 * (1 - alpha) * (1 - alpha), gamma = 0.5 - alpha;
  Eigen::Matrix3d L, R;
  L << (1 + alpha) * k, 0, m, 1, 0, -beta * dt * dt, 0, 1, -gamma * dt;
  R << alpha * k, 0, 0, 1, dt, (0.5 - beta) * dt * dt, 0, 1, (1 - gamma) * dt;
  return L.partialPivLu().solve(R);
}

double spectral_radius(const Eigen::Matrix3d& A) {
  const Eigen::Vector3cd roots = A.eigenvalues();
  return roots.cwiseAbs().maxCoeff();
}

}  // namespace

TEST(Newmark, HhtFollowsItsAmplificationMatrix) {
  const double k = 4.0, m = 1e-3, w = std::sqrt(k / m), alpha = -0.1;
  for (const double wdt : {2 * kPi / 50, 3.0}) {
    const double dt = wdt / w;
    const Eigen::Matrix3d A = hht_amplification(k, m, dt, alpha);
    auto o = options(dt, 400 * dt);
    o.hht_alpha = alpha;
    const VectorX u0 = (VectorX(3) << 1.0, 0.0, 0.0).finished();
    const auto h = solvers::integrate_newmark(oscillator(k), VectorX::Constant(3, m),
                                              VectorX::Zero(3), {}, o, u0);
    ASSERT_TRUE(h.path.completed) << h.path.message;
    Eigen::Vector3d x(1.0, 0.0, -k / m);  // a0 from the equation of motion
    double worst = 0.0;
    for (const auto& step : h.path.steps) {
      x = A * x;
      worst = std::max(worst, std::abs(step.displacement[0] - x[0]));
    }
    EXPECT_LT(worst, 1e-9) << "w dt = " << wdt;
  }
  // Resolved modes: fourth order in w dt (halving the step cuts the loss 16 times, to 10 %).
  const double loss = 1 - spectral_radius(hht_amplification(k, m, 0.1 / w, alpha));
  const double half = 1 - spectral_radius(hht_amplification(k, m, 0.05 / w, alpha));
  EXPECT_NEAR(loss / half, 16.0, 1.6);
  EXPECT_LT(loss, 0.02 * std::pow(0.1, 4));
  // Unresolved (w dt = 3): at least 5 % of the amplitude goes each step.
  EXPECT_LT(spectral_radius(hht_amplification(k, m, 3.0 / w, alpha)), 0.95);
}

TEST(Newmark, RefusesBadInput) {
  const model::Model model = oscillator(1.0);
  auto o = options(1e-3, 1e-2);
  EXPECT_THROW(solvers::integrate_newmark(model, VectorX::Zero(3), VectorX::Zero(3), {}, o),
               std::invalid_argument);  // a free DOF without mass
  o.hht_alpha = -0.5;
  EXPECT_THROW(solvers::integrate_newmark(model, VectorX::Ones(3), VectorX::Zero(3), {}, o),
               std::invalid_argument);
  o = options(1e-9, 1.0);  // 1e9 steps
  EXPECT_THROW(solvers::integrate_newmark(model, VectorX::Ones(3), VectorX::Zero(3), {}, o),
               std::invalid_argument);
}
