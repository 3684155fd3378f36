#pragma once
// Shared by the contact kernel tests: random geometry and finite differences of a scalar
// with gradient and Hessian.
//
// Central differences with step h have truncation error ~h^2 |f'''| / 6 and rounding error
// ~eps |f| / h; with h = 1e-6 times the geometry's scale both stay below ~1e-9 of the
// derivative's scale for the smooth, O(1)-conditioned configurations used here, so a
// relative bound of 1e-6 (on the norm) leaves two or more orders of headroom and still
// catches any wrong term (those are O(1) relative).

#include <array>
#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "kresling/core/types.hpp"
#include "finite_differences.hpp"
#include "kresling/contact/contact_distance.hpp"

namespace kresling::contact_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStep = 1e-6;
constexpr double kRelTol = 1e-6;

inline Vector3 random_point(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

inline Matrix3 random_rotation(std::mt19937& rng) {
  const Vector3 axis = random_point(rng).normalized();
  return Eigen::AngleAxisd(std::uniform_real_distribution<double>(0, 2 * kPi)(rng), axis)
      .toRotationMatrix();
}

inline Vector12 stack(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d) {
  Vector12 v;
  v << a, b, c, d;
  return v;
}

inline std::array<Vector3, 4> unstack(const Vector12& v) {
  return {v.segment<3>(0), v.segment<3>(3), v.segment<3>(6), v.segment<3>(9)};
}

// Squared distances of four stacked nodes (p, t0, t1, t2) and (ea0, ea1, eb0, eb1).
inline double point_triangle_distance2(const Vector12& y) {
  const auto v = unstack(y);
  return contact::point_triangle_distance(v[0], v[1], v[2], v[3], false).value;
}

inline double edge_edge_distance2(const Vector12& y) {
  const auto v = unstack(y);
  return contact::edge_edge_distance(v[0], v[1], v[2], v[3], false).value;
}

// Central differences of f (returning ScalarDerivatives<N>) about x with step h: the
// gradient from the values and the Hessian from the gradients.
template <int N, typename F>
contact::ScalarDerivatives<N> finite_differences(F&& f, const Eigen::Matrix<double, N, 1>& x,
                                                  double h) {
  const auto d = test::central_differences(
      [&](const Eigen::Matrix<double, N, 1>& y) {
        const auto r = f(y);
        return std::make_pair(r.value, r.gradient);
      },
      x, h);
  contact::ScalarDerivatives<N> fd;
  fd.value = f(x).value;
  fd.gradient = d.gradient;
  fd.hessian = d.hessian;
  return fd;
}

// Relative error of a derivative against its finite difference, on the norm.
template <typename A, typename B>
double relative_error(const A& exact, const B& fd) {
  return (exact - fd).norm() / std::max(exact.norm(), 1e-300);
}

// Expect the derivatives f(x) gives (a ScalarDerivatives<N>) to match its central
// differences within kRelTol on the norms of the gradient and the Hessian.
template <int N, typename F>
void expect_derivatives_match(F&& f, const Eigen::Matrix<double, N, 1>& x, int trial) {
  const auto exact = f(x);
  const auto fd = finite_differences<N>(f, x, kStep);
  EXPECT_LE(relative_error(exact.gradient, fd.gradient), kRelTol) << "trial " << trial;
  EXPECT_LE(relative_error(exact.hessian, fd.hessian), kRelTol) << "trial " << trial;
}

// An edge-edge mollifier threshold for the edges (v[0], v[1]) and (v[2], v[3]) that
// mollifies them on even trials and not on odd ones: twice or half their |ea x eb|^2.
inline double alternating_mollifier_threshold(const std::array<Vector3, 4>& v, int trial) {
  const double cross2 = contact::cross_squared_norm(v[1] - v[0], v[3] - v[2]).value;
  return cross2 * (trial % 2 == 0 ? 2.0 : 0.5);
}

}  // namespace kresling::contact_test
