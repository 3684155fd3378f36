#pragma once
/// \file module_transform.hpp
/// Homogeneous transforms of one manipulator module (thesis eqns 26 and 30).
///
/// State 0 (contracted, flexible): a constant-curvature arc (s, kappa, phi). Eqn 26 is
///   A0 = [Rz(phi) Rx(s kappa), Rz(phi) (0, -(1 - cos s kappa) / kappa, sin(s kappa) / kappa)]
/// State 1 (extended, rigid): a translation by L along z (eqn 30).
///
/// Frame conventions. Eqn 26 (Jones) leaves the end frame turned by phi about its own z
/// axis relative to the tendon guides, so the next module's phi must be measured from that
/// turned frame (Appendix E sets phi = 0 for later modules for this reason). The twist-free
/// convention appends Rz(-phi): A = Rz(phi) Rx(s kappa) Rz(-phi), a rotation by s kappa about
/// the horizontal axis (cos phi, sin phi, 0), so the end frame keeps the guides' x axis (on
/// tendon 1). Both give the same backbone point; only the end frame's twist differs.

#include <cmath>

#include <Eigen/Core>

#include "kresling/kinematics/constant_curvature.hpp"
#include "kresling/kinematics/series.hpp"

namespace kresling::kinematics {

/// How the end frame of a flexible module is oriented about its z axis.
enum class FrameConvention : int {
  Jones = 0,      ///< eqn 26 as printed: end frame turned by phi
  TwistFree = 1,  ///< Rz(phi) Rx(s kappa) Rz(-phi): end frame aligned with the tendon guides
};

/// Eqn 26 (Jones) or its twist-free variant for an arc (s [mm], kappa [1/mm], phi [rad]).
/// Exact at kappa = 0 (a translation by s along z): (1 - cos s kappa) / kappa and
/// sin(s kappa) / kappa are evaluated as s times smooth functions of (s kappa)^2.
Eigen::Matrix4d flexible_module_transform(double s, double kappa, double phi,
                                          FrameConvention convention);

/// Eqn 30: translation by `length` [mm] along z.
Eigen::Matrix4d rigid_module_transform(double length);

/// Rotation and translation of a rigid motion, for any scalar type.
template <typename Scalar>
struct RigidMotion {
  Eigen::Matrix<Scalar, 3, 3> rotation;
  Eigen::Matrix<Scalar, 3, 1> translation;
};

/// Twist-free transform of a flexible module as a smooth function of its tendon lengths
/// (no validation: call decompose_tendons first). Writing eqns 27-29 in terms of the bend
/// vector omega = s kappa (cos phi, sin phi, 0) = (2 / 3d) G(y) (b, a, 0), with
/// G(y) = asin(sqrt y) / sqrt y, removes the 0/0 of phi at the straight case, so the map is
/// differentiable there (the inverse-kinematics Jacobian uses it with AutoDiffScalar).
///   rotation    = I + A(t) [omega]x + B(t) [omega]x^2        (Rodrigues, t = |omega|^2)
///   translation = s (B(t) omega_y, -B(t) omega_x, A(t)),  s = mean(l) G(y)
/// with A(t) = sin(sqrt t) / sqrt t and B(t) = (1 - cos sqrt t) / t.
template <typename Scalar>
RigidMotion<Scalar> twist_free_motion_from_tendons(const Eigen::Matrix<Scalar, 3, 1>& l,
                                                   const TendonLayout& layout) {
  const double root3 = std::sqrt(3.0);
  const Scalar mean = (l[0] + l[1] + l[2]) / 3.0;
  const Scalar a = 0.5 * (l[1] + l[2] - 2.0 * l[0]);
  const Scalar b = 0.5 * root3 * (l[1] - l[2]);
  const double scale = 3.0 * layout.segments * layout.radius;
  const Scalar G = asin_ratio_of_square(Scalar((a * a + b * b) / (scale * scale)));
  const Scalar wx = (2.0 / (3.0 * layout.radius)) * G * b;
  const Scalar wy = (2.0 / (3.0 * layout.radius)) * G * a;
  const Scalar t = wx * wx + wy * wy;
  const Scalar A = sinc_of_square(t);
  const Scalar B = versine_of_square(t);
  Eigen::Matrix<Scalar, 3, 3> W;  // [omega]x with omega = (wx, wy, 0)
  W << Scalar(0), Scalar(0), wy,
       Scalar(0), Scalar(0), -wx,
       -wy, wx, Scalar(0);
  RigidMotion<Scalar> out;
  out.rotation = Eigen::Matrix<Scalar, 3, 3>::Identity() + A * W + B * (W * W);
  const Scalar s = mean * G;
  out.translation << s * B * wy, -s * B * wx, s * A;
  return out;
}

}  // namespace kresling::kinematics
