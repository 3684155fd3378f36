// IPC's log barrier and the pair contact energies (contact_barrier.hpp).

#include "kresling/contact/contact_barrier.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "kresling/core/check.hpp"
#include "kresling/contact/contact_mollifier.hpp"
#include "kresling/contact/contact_offset.hpp"

namespace kresling::contact {

BarrierValue log_barrier(double s, double s_hat) {
  BarrierValue b;
  if (s >= s_hat) return b;
  if (!(s > 0)) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {inf, -inf, inf};
  }
  const double gap = s - s_hat;  // negative inside the range
  const double log_ratio = std::log(s / s_hat);
  const double r = s_hat / s;
  b.value = -gap * gap * log_ratio;
  b.first = -gap * (2 * log_ratio - r + 1);    // (s_hat - s)(2 ln(s / s_hat) - s_hat / s + 1)
  b.second = (r + 2) * r - 2 * log_ratio - 3;  // s_hat^2 / s^2 + 2 s_hat / s - 2 ln(..) - 3
  return b;
}

template <int N>
Eigen::Matrix<double, N, N> project_to_psd(const Eigen::Matrix<double, N, N>& matrix) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(matrix);
  const Eigen::Matrix<double, N, 1> clamped = eigen.eigenvalues().cwiseMax(0.0);
  return eigen.eigenvectors() * clamped.asDiagonal() * eigen.eigenvectors().transpose();
}

template <int N>
ScalarDerivatives<N> barrier_energy(const ScalarDerivatives<N>& distance, double d_hat,
                                    double stiffness, BarrierHessian hessian) {
  ScalarDerivatives<N> e;
  if (distance.value >= d_hat * d_hat) return e;
  if (!(distance.value > 0)) {
    // Touching or crossing: no direction is defined; the energy says "not admissible".
    e.value = std::numeric_limits<double>::infinity();
    return e;
  }
  const BarrierValue b = log_barrier(distance.value, d_hat * d_hat);
  e.value = stiffness * b.value;
  e.gradient = stiffness * b.first * distance.gradient;
  if (hessian == BarrierHessian::None) return e;
  e.hessian = stiffness * (b.second * distance.gradient * distance.gradient.transpose() +
                           b.first * distance.hessian);
  if (hessian == BarrierHessian::Projected) e.hessian = project_to_psd<N>(e.hessian);
  return e;
}

ScalarDerivatives<12> point_triangle_barrier(const Vector3& p, const Vector3& t0,
                                             const Vector3& t1, const Vector3& t2,
                                             double d_hat, double stiffness,
                                             BarrierHessian hessian, double offset) {
  const bool with_hessian = hessian != BarrierHessian::None;
  return barrier_energy<12>(
      offset_squared_distance<12>(point_triangle_distance(p, t0, t1, t2, with_hessian), offset,
                                  with_hessian),
      d_hat, stiffness, hessian);
}

ScalarDerivatives<12> edge_edge_barrier(const Vector3& ea0, const Vector3& ea1,
                                        const Vector3& eb0, const Vector3& eb1, double eps_x,
                                        double d_hat, double stiffness,
                                        BarrierHessian hessian, double offset) {
  const bool with_hessian = hessian != BarrierHessian::None;
  const auto distance = offset_squared_distance<12>(
      edge_edge_distance(ea0, ea1, eb0, eb1, with_hessian), offset, with_hessian);
  if (distance.value >= d_hat * d_hat) return {};
  // The unmollified energy B = kappa b(s) with its exact Hessian, then the product m B (the
  // projection, if asked for, is of the product's Hessian).
  const auto B = barrier_energy<12>(
      distance, d_hat, stiffness, with_hessian ? BarrierHessian::Exact : BarrierHessian::None);
  const auto m = edge_edge_mollifier(ea0, ea1, eb0, eb1, eps_x, with_hessian);
  ScalarDerivatives<12> e;
  e.value = m.value * B.value;
  e.gradient = m.value * B.gradient + B.value * m.gradient;
  if (!with_hessian) return e;
  e.hessian = m.value * B.hessian + B.value * m.hessian + m.gradient * B.gradient.transpose() +
              B.gradient * m.gradient.transpose();
  if (hessian == BarrierHessian::Projected) e.hessian = project_to_psd<12>(e.hessian);
  return e;
}

ScalarDerivatives<3> point_plane_barrier(const Vector3& p, const Vector3& origin,
                                         const Vector3& normal, double d_hat, double stiffness,
                                         BarrierHessian hessian, double offset) {
  return barrier_energy<3>(
      offset_squared_distance<3>(point_rigid_plane_distance(p, origin, normal), offset),
      d_hat, stiffness, hessian);
}

void check_barrier_parameters(double d_hat, double stiffness) {
  require_positive("d_hat", d_hat);
  require_positive("stiffness", stiffness, true);
}

template Eigen::Matrix<double, 3, 3> project_to_psd<3>(const Eigen::Matrix<double, 3, 3>&);
template Eigen::Matrix<double, 12, 12> project_to_psd<12>(const Eigen::Matrix<double, 12, 12>&);
template ScalarDerivatives<3> barrier_energy<3>(const ScalarDerivatives<3>&, double, double,
                                                BarrierHessian);
template ScalarDerivatives<12> barrier_energy<12>(const ScalarDerivatives<12>&, double, double,
                                                  BarrierHessian);

}  // namespace kresling::contact
