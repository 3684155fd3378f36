#pragma once
/// \file corner_angle.hpp
/// Springs on the three interior angles of a triangle: the in-plane shear stiffness of a
/// panel that bars alone give only through their lengths (Origami Simulator's "face
/// stiffness", Ghassaei, Demaine and Gershenfeld 2018).
///
///               c
///              / \          alpha_i: the interior angle at corner i, in (0, pi),
///             /   \         alpha_i = atan2(|u x w|, u . w) with u, w the corner's two sides
///            / a_c \
///           a ----- b       energy  E = 1/2 k sum_i (alpha_i - alpha0_i)^2   [N mm]
///
/// One corner p with sides u = q - p and w = r - p, unit vectors a = u/|u|, b = w/|w|, cosine
/// c = a . b and sine s = |a x b| > 0:
///
///     d alpha / du = -(b - c a) / (s |u|),   d alpha / dw = -(a - c b) / (s |w|),
///     d alpha / dp = -(d alpha / du + d alpha / dw)      (alpha depends on u and w only)
///
/// and the Hessian follows from alpha = acos(c): d2 alpha = -(1/s) d2c - (c/s^3) dc dc^T,
/// with the second derivatives of the cosine in closed form (corner_angle.cpp). The angles
/// are invariant under rigid motions and under scaling; they are singular only where a
/// triangle degenerates (s = 0), which the family refuses in the reference state.

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kresling/core/types.hpp"

namespace kresling::elements {

using Vector9 = Eigen::Matrix<double, 9, 1>;
using Matrix9 = Eigen::Matrix<double, 9, 9>;

/// The three interior angles [rad] of the triangle (x0, x1, x2), at x0, x1 and x2.
std::array<double, 3> corner_angles(const Vector3& x0, const Vector3& x1, const Vector3& x2);

/// Energy, internal force and tangent of the triangle's corner springs.
struct CornerAngleResponse {
  double energy = 0.0;                    ///< E [N mm]
  std::array<double, 3> angle{};          ///< alpha_0, alpha_1, alpha_2 [rad]
  Vector9 force = Vector9::Zero();        ///< dE/dx over (x0, x1, x2) [N]
  Matrix9 stiffness = Matrix9::Zero();    ///< d2E/dx2 [N/mm]
  /// d alpha_i / dx over (x0, x1, x2): the force is k sum_i (alpha_i - alpha0_i) gradients[i],
  /// so dE/dalpha0_i = -k (alpha_i - alpha0_i) and d force / d alpha0_i = -k gradients[i].
  std::array<Vector9, 3> gradients{};
};

/// The corner springs of stiffness `k` [N mm/rad^2] of triangle (x0, x1, x2) resting at
/// `rest` [rad]; the tangent only when `with_tangent`.
CornerAngleResponse corner_angle_response(const Vector3& x0, const Vector3& x1,
                                          const Vector3& x2, const std::array<double, 3>& rest,
                                          double k, bool with_tangent = true);

}  // namespace kresling::elements
