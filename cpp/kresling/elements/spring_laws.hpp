#pragma once
/// \file spring_laws.hpp
/// Rotational spring laws of hinges, per unit hinge length: the moment M(theta), its
/// derivative k = dM/dtheta and the stored energy, for stiffness kp [moment/rad per length]
/// and rest angle theta0. A hinge of length L0 multiplies all three by L0.

namespace kresling::elements {

/// Value of a spring law at one angle (per unit hinge length).
struct SpringResponse {
  double moment = 0.0;     ///< M
  double stiffness = 0.0;  ///< dM/dtheta (see SuperLinearBend for its one exception)
  double energy = 0.0;     ///< integral of M from theta0
};

enum class SpringLawKind : int {
  Linear = 0,          ///< M = kp (theta - theta0)
  EnhancedLinear = 1,  ///< linear between two limits, stiffening like tan() beyond them
  SuperLinearBend = 2, ///< M = kp sign(d) |d|^(4/3), d = theta - theta0 (panel bending)
};

/// A spring law with its parameters; limits in radians (EnhancedLinear only).
/// The law of `code` (a SpringLawKind's value); throws std::invalid_argument naming `name`
/// for any other number.
SpringLawKind spring_law_kind(long long code, const char* name);

/// The derivatives of a law's moment and energy with respect to its rest angle. The linear
/// and enhanced-linear laws are kp (theta - theta0) plus terms free of theta0 (the
/// stiffening beyond the limits depends on theta and the limits only), so
/// dM/dtheta0 = -kp and dE/dtheta0 = -kp (theta - theta0) everywhere in their domain (the
/// energy is the integral of M from theta0, and M(theta0) = 0). The super-linear law is a
/// function of d = theta - theta0: dM/dtheta0 = -4/3 kp |d|^(1/3) (the exact derivative,
/// not the floored stiffness evaluate() reports) and dE/dtheta0 = -M.
struct RestAngleDerivative {
  double moment = 0.0;  ///< dM/dtheta0
  double energy = 0.0;  ///< dE/dtheta0
};

struct SpringLaw {
  SpringLawKind kind = SpringLawKind::EnhancedLinear;
  double theta1 = 0.0;  ///< lower limit of the linear range, 0 < theta1 < theta0
  double theta2 = 0.0;  ///< upper limit of the linear range, theta0 < theta2 < 2 pi

  SpringResponse evaluate(double theta, double theta0, double kp) const;
  /// dM/dtheta0 and d(energy)/dtheta0 at theta (per unit hinge length).
  RestAngleDerivative rest_angle_derivative(double theta, double theta0, double kp) const;
};

/// Linear law.
SpringResponse linear_spring(double theta, double theta0, double kp);

/// MERLIN2's "enhanced linear" law: linear for theta1 <= theta <= theta2; below theta1,
/// M = kp (theta1 - theta0) + kp tan(p/2 (theta - theta1)) / (p/2) with p = pi / theta1, so
/// the moment grows without bound as the hinge closes flat (theta -> 0); above theta2 the
/// mirror image with p = pi / (2 pi - theta2). M and dM/dtheta are continuous at the limits.
/// Its domain is 0 < theta < 2 pi: at a hinge folded flat (theta = 0 or 2 pi) M, dM/dtheta
/// and the energy are infinite (-inf / +inf for M), so no solver accepts such a state.
SpringResponse enhanced_linear_spring(double theta, double theta0, double kp, double theta1,
                                      double theta2);

/// MERLIN2's "super-linear" bending law, M = kp sign(d) |d|^(4/3), energy 3/7 kp |d|^(7/3).
/// Its reported stiffness is max(4/3 kp |d|^(1/3), 1e-3 kp): floored so that the tangent of
/// an unbent panel is not singular (it is not the exact derivative for |d| < ~4.2e-10).
/// See docs/model.md, 'Spring laws'.
SpringResponse super_linear_bend_spring(double theta, double theta0, double kp);

}  // namespace kresling::elements
