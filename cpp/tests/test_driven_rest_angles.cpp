// Creases driven in time (time_integration.hpp's RestAngleSchedule) and the damping of the
// current tangent, on one hinge and on a linear oscillator: against the same motion with
// the rest angle set in the model, the energy balance with the actuation's work, and the
// refusals.

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/model/bar_family.hpp"
#include "kresling/model/hinge_family.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/time_integration.hpp"
#include "oscillator_test_helpers.hpp"
#include "wing_test_helpers.hpp"

using namespace kresling;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A wing (node 3) turning about the axis 0 -> 1 against a held wing (node 2), on stiff bars
// and a linear hinge of stiffness 1 N mm/rad at rest angle `rest`.
model::Model wing(double rest) {
  const NodeMatrix X = test::wing_nodes();
  model::Hinge h;
  h.nodes = {0, 1, 2, 3};
  h.stiffness = 1.0;
  h.rest_angle = rest;
  h.length = 1.0;
  h.law.kind = elements::SpringLawKind::Linear;
  std::vector<std::uint8_t> fixed(12, 1);
  fixed[9] = fixed[10] = fixed[11] = 0;
  return model::Model(X, fixed,
                      {std::make_shared<model::BarFamily>(test::wing_bars(X)),
                       std::make_shared<model::HingeFamily>(std::vector<model::Hinge>{h})});
}

solvers::TimeIntegrationOptions options(double dt, double duration) {
  return test::newmark_options(dt, duration, 1e-13);
}

solvers::RestAngleSchedule drive(double start, double delta, std::function<double(double)> f) {
  solvers::RestAngleSchedule s;
  s.terms.push_back({{0}, VectorX::Constant(1, start), VectorX::Constant(1, delta), std::move(f)});
  return s;
}

const VectorX kMasses = (VectorX(12) << 0, 0, 0, 0, 0, 0, 0, 0, 0, 1e-3, 1e-3, 1e-3).finished();

}  // namespace

TEST(DrivenRestAngles, AStepIsTheModelWithItsRestAngleSetFromTheStart) {
  const double delta = 0.05;
  const auto set = solvers::integrate_newmark(wing(kPi + delta), kMasses, VectorX::Zero(12), {},
                                              options(2e-3, 0.2));
  auto o = options(2e-3, 0.2);
  o.actuation = drive(kPi, delta, {});  // an empty factor: 1 from t = 0
  const model::Model flat = wing(kPi);
  const auto driven = solvers::integrate_newmark(flat, kMasses, VectorX::Zero(12), {}, o);
  ASSERT_TRUE(set.path.completed && driven.path.completed);
  ASSERT_EQ(set.path.steps.size(), driven.path.steps.size());
  // pi + delta and pi + 1 * delta round alike; Newton stops at 1e-13.
  for (std::size_t i = 0; i < set.path.steps.size(); ++i) {
    EXPECT_LT((set.path.steps[i].displacement - driven.path.steps[i].displacement).norm(), 1e-11);
    EXPECT_EQ(driven.actuation_work[i], 0.0);  // nothing moves the rest angle after t = 0
  }
}

TEST(DrivenRestAngles, AHarmonicRestAngleDoesTheWorkTheEnergiesBalance) {
  // w = sqrt(k / (m r^2)) = sqrt(1 / 1e-3) = 31.6 rad/s; the drive at 3 Hz, w dt = 0.003.
  auto o = options(1e-4, 1.0);
  o.actuation = drive(kPi, 0.1, [](double t) { return std::sin(2 * kPi * 3.0 * t); });
  const auto h = solvers::integrate_newmark(wing(kPi), kMasses, VectorX::Zero(12), {}, o);
  ASSERT_TRUE(h.path.completed) << h.path.message;
  double most = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < h.kinetic.size(); ++i) {
    most = std::max(most, std::abs(h.actuation_work[i]));
    worst = std::max(worst, std::abs(h.kinetic[i] + h.strain[i] - h.actuation_work[i]));
  }
  EXPECT_GT(most, 1e-4);  // 1/2 k (0.1 rad)^2 = 5e-3 N mm at most
  // The trapezoidal rule of the actuation's work against the average acceleration scheme
  // on a hinge nonlinear in the turn: O((w dt)^2) ~ 1e-5 of the energies, 1e-4 bounds it.
  EXPECT_LT(worst, 1e-4 * most);
}

TEST(DrivenRestAngles, RefusesHingesOutOfRangeAndMismatchedSizes) {
  auto o = options(1e-3, 1e-2);
  o.actuation = drive(kPi, 0.1, {});
  o.actuation.terms[0].hinges = {1};
  EXPECT_THROW(solvers::integrate_newmark(wing(kPi), kMasses, VectorX::Zero(12), {}, o),
               std::invalid_argument);
  o.actuation = drive(kPi, 0.1, {});
  o.actuation.terms[0].delta = VectorX::Zero(2);
  EXPECT_THROW(solvers::integrate_newmark(wing(kPi), kMasses, VectorX::Zero(12), {}, o),
               std::invalid_argument);
  o.actuation = drive(kPi, 0.1, [](double) { return NAN; });
  EXPECT_THROW(solvers::integrate_newmark(wing(kPi), kMasses, VectorX::Zero(12), {}, o),
               std::invalid_argument);
  // A rest angle driven beyond a flat fold (2 pi) at t = 5 ms.
  o.actuation = drive(kPi, 4.0, [](double t) { return t > 5e-3 ? 1.0 : 0.0; });
  EXPECT_THROW(solvers::integrate_newmark(wing(kPi), kMasses, VectorX::Zero(12), {}, o),
               std::invalid_argument);
}

TEST(CurrentTangentDamping, OnALinearOscillatorIsTheStartsTangents) {
  const double k = 4.0, m = 1e-3, dt = 2e-3;
  auto o = options(dt, 200 * dt);
  o.mass_damping = 2.0;
  o.stiffness_damping = 1e-3;
  const VectorX u0 = (VectorX(3) << 1.0, 0.5, 0.0).finished();
  const auto initial = solvers::integrate_newmark(test::oscillator(k), VectorX::Constant(3, m),
                                                  VectorX::Zero(3), {}, o, u0);
  o.damping_current_tangent = true;
  const auto current = solvers::integrate_newmark(test::oscillator(k), VectorX::Constant(3, m),
                                                  VectorX::Zero(3), {}, o, u0);
  ASSERT_EQ(initial.path.steps.size(), current.path.steps.size());
  for (std::size_t i = 0; i < initial.path.steps.size(); ++i) {
    EXPECT_LT((initial.path.steps[i].displacement - current.path.steps[i].displacement).norm(),
              1e-12);
    EXPECT_NEAR(initial.dissipated[i], current.dissipated[i], 1e-12);
  }
}
