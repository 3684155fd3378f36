#pragma once
// Shared by the panel-contact model tests: two triangles 2 mm apart, one above the other,
// in a model whose only family is their self-contact, and displacements lowering the upper
// one onto the lower.

#include <memory>
#include <random>
#include <vector>

#include "kresling/model/model.hpp"
#include "kresling/model/self_contact_family.hpp"

namespace kresling::contact_test {

constexpr double kTwoTrianglesDHat = 0.5;  // [mm]

// Skewed so that point-triangle and edge-edge pairs both enter as the upper one comes down.
// `thickness` [mm]: the panels' (0: none).
inline model::Model two_triangles(
    model::SelfContactFamily::TangentForm form = model::SelfContactFamily::TangentForm::Adaptive,
    double thickness = 0.0) {
  NodeMatrix X(6, 3);
  X << 0, 0, 0, 4, 0, 0, 0, 4, 0,  //
      1, 1, 2, 5, 1.5, 2, 0.5, 5, 2;
  auto family = std::make_shared<model::SelfContactFamily>(
      std::vector<Index>{0, 1, 2, 3, 4, 5}, kTwoTrianglesDHat, 10.0, form,
      contact::JoinedNodes{}, thickness);
  return model::Model(X, std::vector<std::uint8_t>(18, 0), {family});
}

// Displacement lowering the upper triangle by `drop` [mm], with a small twist from `seed`.
inline VectorX lowered(double drop, unsigned seed = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  VectorX u = VectorX::Zero(18);
  for (int n = 3; n < 6; ++n) {
    u[3 * n + 2] = -drop;
    for (int k = 0; k < 3; ++k) u[3 * n + k] += jitter(rng);
  }
  return u;
}

}  // namespace kresling::contact_test
