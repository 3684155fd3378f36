#pragma once
/// \file finite_differences.hpp
/// Central differences, the one reference the tests check analytic derivatives against.

#include <utility>

#include <Eigen/Core>

namespace kresling::test {

/// The central differences, with step h about x, of a function `at(y) -> (value, gradient)`
/// (a scalar and a vector of x's size): the gradient of the value and the Jacobian of the
/// gradient (its Hessian) they imply, column k from x +- h e_k. Their error is O(h^2) times
/// the third derivatives plus rounding of ~1e-16 |value| / h.
template <typename Vector, typename At>
auto central_differences(At&& at, const Vector& x, double h) {
  using Matrix = Eigen::Matrix<double, Vector::RowsAtCompileTime, Vector::RowsAtCompileTime>;
  struct Differences {
    Vector gradient;
    Matrix hessian;
  };
  Differences out{Vector::Zero(x.size()), Matrix::Zero(x.size(), x.size())};
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    Vector p = x, q = x;
    p[k] += h;
    q[k] -= h;
    const auto [value_p, gradient_p] = at(p);
    const auto [value_q, gradient_q] = at(q);
    out.gradient[k] = (value_p - value_q) / (2 * h);
    out.hessian.col(k) = (gradient_p - gradient_q) / (2 * h);
  }
  return out;
}

/// central_differences of an element's response `at(y)` (its `energy` and `force`, the
/// energy's gradient): the force and the stiffness they imply.
template <typename Vector, typename Response>
auto energy_differences(Response&& at, const Vector& x, double h) {
  return central_differences(
      [&](const Vector& y) {
        const auto r = at(y);
        return std::make_pair(r.energy, Vector(r.force));
      },
      x, h);
}

}  // namespace kresling::test
