// The edge-edge mollifier of IPC (contact_mollifier.hpp).

#include "kresling/contact/contact_mollifier.hpp"

namespace kresling::contact {

double edge_edge_mollifier_threshold(const Vector3& ea0_rest, const Vector3& ea1_rest,
                                     const Vector3& eb0_rest, const Vector3& eb1_rest) {
  return 1e-3 * (ea1_rest - ea0_rest).squaredNorm() * (eb1_rest - eb0_rest).squaredNorm();
}

ScalarDerivatives<12> edge_edge_mollifier(const Vector3& ea0, const Vector3& ea1,
                                          const Vector3& eb0, const Vector3& eb1, double eps_x,
                                          bool with_hessian) {
  ScalarDerivatives<12> m;
  const ScalarDerivatives<6> x = cross_squared_norm(ea1 - ea0, eb1 - eb0, with_hessian);
  if (x.value >= eps_x) {
    m.value = 1.0;
    return m;
  }
  // x depends on ua = ea1 - ea0 and ub = eb1 - eb0: d(ua)/d(ea0) = -I, d(ua)/d(ea1) = I, ...
  Eigen::Matrix<double, 6, 12> A = Eigen::Matrix<double, 6, 12>::Zero();
  A.block<3, 3>(0, 0) = -Matrix3::Identity();
  A.block<3, 3>(0, 3) = Matrix3::Identity();
  A.block<3, 3>(3, 6) = -Matrix3::Identity();
  A.block<3, 3>(3, 9) = Matrix3::Identity();
  const double ratio = x.value / eps_x;
  const double dm = 2.0 / eps_x * (1.0 - ratio);  // m'(x)
  const double d2m = -2.0 / (eps_x * eps_x);      // m''(x)
  const Vector12 grad_x = A.transpose() * x.gradient;
  m.value = (2.0 - ratio) * ratio;
  m.gradient = dm * grad_x;
  if (with_hessian) {
    m.hessian = dm * (A.transpose() * x.hessian * A) + d2m * grad_x * grad_x.transpose();
  }
  return m;
}

}  // namespace kresling::contact
