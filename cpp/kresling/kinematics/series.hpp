#pragma once
/// \file series.hpp
/// Even functions that the constant-curvature formulas divide by zero in at the straight
/// case, written as functions of the squared argument so that they are smooth (and
/// differentiable by automatic differentiation) through zero:
///
///   sinc_of_square(t)    = sin(sqrt t) / sqrt t            (-> 1    as t -> 0)
///   versine_of_square(t) = (1 - cos(sqrt t)) / t           (-> 1/2  as t -> 0)
///   asin_ratio_of_square(y) = asin(sqrt y) / sqrt y        (-> 1    as y -> 0)
///
/// Below a threshold each uses its Taylor series (truncated where the next term is under
/// 1e-18 relative); above it the closed form, which has no cancellation there.
/// Templated on the scalar so that Eigen::AutoDiffScalar passes through.

#include <cmath>

namespace kresling::kinematics {

/// sin(sqrt t) / sqrt t for t >= 0.
template <typename Scalar>
Scalar sinc_of_square(const Scalar& t) {
  using std::sin;
  using std::sqrt;
  if (t < 1e-2) {  // next term t^6 / 13! < 2e-22
    return 1.0 + t * (-1.0 / 6 + t * (1.0 / 120 + t * (-1.0 / 5040 + t * (1.0 / 362880 +
                                                                       t * (-1.0 / 39916800)))));
  }
  const Scalar x = sqrt(t);
  return sin(x) / x;
}

/// (1 - cos(sqrt t)) / t for t >= 0, as 2 sin^2(sqrt(t)/2) / t away from 0 (no cancellation).
template <typename Scalar>
Scalar versine_of_square(const Scalar& t) {
  using std::sin;
  using std::sqrt;
  if (t < 1e-2) {  // next term t^5 / 12! < 3e-19
    return 0.5 + t * (-1.0 / 24 + t * (1.0 / 720 + t * (-1.0 / 40320 + t * (1.0 / 3628800))));
  }
  const Scalar half = 0.5 * sqrt(t);
  const Scalar s = sin(half);
  return 2.0 * s * s / t;
}

/// asin(sqrt y) / sqrt y for 0 <= y <= 1.
template <typename Scalar>
Scalar asin_ratio_of_square(const Scalar& y) {
  using std::asin;
  using std::sqrt;
  if (y < 1e-3) {  // coefficients (2n)! / (4^n n!^2 (2n+1)); next term 0.017 y^6 < 2e-20
    return 1.0 + y * (1.0 / 6 + y * (3.0 / 40 + y * (5.0 / 112 + y * (35.0 / 1152 +
                                                                     y * (63.0 / 2816)))));
  }
  const Scalar x = sqrt(y);
  return asin(x) / x;
}

}  // namespace kresling::kinematics
