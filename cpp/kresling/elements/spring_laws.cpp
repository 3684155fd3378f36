#include "kresling/elements/spring_laws.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace kresling::elements {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

SpringResponse linear_spring(double theta, double theta0, double kp) {
  const double d = theta - theta0;
  return {kp * d, kp, 0.5 * kp * d * d};
}

SpringResponse enhanced_linear_spring(double theta, double theta0, double kp, double theta1,
                                      double theta2) {
  if (theta >= theta1 && theta <= theta2) return linear_spring(theta, theta0, kp);
  // Beyond a limit t: M = kp (t - theta0) + kp tan(q x) / q with q = p/2, x = theta - t;
  // energy = the linear energy at t + kp (t - theta0) x - kp ln(cos(q x)) / q^2.
  const bool below = theta < theta1;
  const double t = below ? theta1 : theta2;
  const double q = 0.5 * (below ? kPi / theta1 : kPi / (2.0 * kPi - theta2));
  const double x = theta - t;
  // The law's domain is 0 < theta < 2 pi: at a hinge folded flat onto itself (theta = 0 or
  // 2 pi, q |x| = pi/2) the moment is infinite. Said so (inf), not evaluated: tan and cos
  // there give finite rounding noise (|M| ~ 1e16 kp) whose sign flips with the last bit of
  // theta, which a solver would otherwise accept as an equilibrium force.
  if (theta <= 0.0 || theta >= 2.0 * kPi || !(std::abs(q * x) < 0.5 * kPi)) {
    const double inf = std::numeric_limits<double>::infinity();
    return {below ? -inf : inf, inf, inf};
  }
  const double c = std::cos(q * x);
  SpringResponse r;
  r.moment = kp * (t - theta0) + kp * std::tan(q * x) / q;
  r.stiffness = kp / (c * c);
  r.energy = 0.5 * kp * (t - theta0) * (t - theta0) + kp * (t - theta0) * x -
             kp * std::log(c) / (q * q);
  return r;
}

SpringResponse super_linear_bend_spring(double theta, double theta0, double kp) {
  const double d = theta - theta0;
  const double a = std::abs(d);
  // |d|^(4/3) = |d| |d|^(1/3) and |d|^(7/3) = |d|^2 |d|^(1/3): one cube root where pow
  // would take two general powers (pow was ~6 % of a sheet's adaptive path); both agree
  // with pow to a few units in the last place.
  const double root = std::cbrt(a);
  SpringResponse r;
  r.moment = (d < 0 ? -1.0 : 1.0) * kp * (a * root);
  r.stiffness = std::max(4.0 / 3.0 * kp * root, 1e-3 * kp);
  r.energy = 3.0 / 7.0 * kp * (a * a * root);
  return r;
}

SpringResponse SpringLaw::evaluate(double theta, double theta0, double kp) const {
  switch (kind) {
    case SpringLawKind::Linear:
      return linear_spring(theta, theta0, kp);
    case SpringLawKind::SuperLinearBend:
      return super_linear_bend_spring(theta, theta0, kp);
    case SpringLawKind::EnhancedLinear:
    default:
      return enhanced_linear_spring(theta, theta0, kp, theta1, theta2);
  }
}

RestAngleDerivative SpringLaw::rest_angle_derivative(double theta, double theta0,
                                                    double kp) const {
  const double d = theta - theta0;
  if (kind == SpringLawKind::SuperLinearBend) {
    const double root = std::cbrt(std::abs(d));
    return {-4.0 / 3.0 * kp * root, -(d < 0 ? -1.0 : 1.0) * kp * std::abs(d) * root};
  }
  return {-kp, -kp * d};
}

SpringLawKind spring_law_kind(long long code, const char* name) {
  if (code < static_cast<long long>(SpringLawKind::Linear) ||
      code > static_cast<long long>(SpringLawKind::SuperLinearBend)) {
    throw std::invalid_argument(std::string(name) + " = " + std::to_string(code) +
                                " is not a spring law code (see kresling.laws.SPRING_LAWS)");
  }
  return static_cast<SpringLawKind>(code);
}

}  // namespace kresling::elements
