#pragma once
// One mass on a linear spring: the model both time integrators' tests run against closed
// forms; and the implicit integrator's options those tests take.

#include <cstdint>
#include <memory>
#include <vector>

#include "kresling/model/model.hpp"
#include "kresling/model/spring_family.hpp"
#include "kresling/solvers/time_integration.hpp"

namespace kresling::test {

// One node on an isotropic anchor spring of stiffness k [N/mm] at the origin.
inline model::Model oscillator(double k) {
  NodeMatrix X(1, 3);
  X << 0.0, 0.0, 0.0;
  auto springs = std::make_shared<model::SpringFamily>(
      std::vector<model::AnchorSpring>{{0, Vector3(k, k, k), Vector3::Zero()}});
  return model::Model(X, std::vector<std::uint8_t>(3, 0), {springs});
}

// Steps of dt over duration [s], Newton to `tolerance` [mm] (far below what the tests
// compare).
inline solvers::TimeIntegrationOptions newmark_options(double dt, double duration,
                                                       double tolerance = 1e-12) {
  solvers::TimeIntegrationOptions o;
  o.time_step = dt;
  o.duration = duration;
  o.newton.tolerance = tolerance;
  return o;
}

}  // namespace kresling::test
