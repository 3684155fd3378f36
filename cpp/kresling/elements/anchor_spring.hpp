#pragma once
/// \file anchor_spring.hpp
/// Zero-length spring from a node to a fixed point, one stiffness per axis: an elastic
/// support (a node held near a position rather than fixed at it), a soft ground, or the
/// compliance of a clamp.
///
///          anchor a  x----/\/\/\----o  node x (= X + u)
///
///     energy  E = 1/2 sum_k k_k (x_k - a_k)^2      (k = x, y, z; stiffness k_k >= 0 [N/mm])
///     force   f = dE/dx = K (x - a),  K = diag(k_x, k_y, k_z)
///     tangent d2E/dx2 = K                          (constant: the spring is linear)
///
/// The spring has zero rest length, so it pulls the node towards the anchor along each axis
/// independently; with equal stiffnesses it is isotropic, and E = 1/2 k |x - a|^2.

#include "kresling/core/types.hpp"

namespace kresling::elements {

/// Energy, internal force and tangent stiffness of one anchor spring.
struct AnchorSpringResponse {
  double energy = 0.0;  ///< E [N mm]
  Vector3 force;        ///< dE/dx [N]
  Matrix3 stiffness;    ///< d2E/dx2 = diag(k) [N/mm]
};

/// The spring of stiffness `k` (per axis) between node position `x` and `anchor`.
AnchorSpringResponse anchor_spring_response(const Vector3& x, const Vector3& anchor,
                                            const Vector3& k);

}  // namespace kresling::elements
