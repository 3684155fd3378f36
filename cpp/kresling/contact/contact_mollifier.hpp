#pragma once
/// \file contact_mollifier.hpp
/// The edge-edge mollifier of IPC (Li et al. 2020, Sec. 4.2): a factor that takes the
/// edge-edge barrier smoothly to zero as two edges become parallel.
///
///     ea0 o-----------o ea1        x = |(ea1 - ea0) x (eb1 - eb0)|^2
///
///          eb0 o-----------o eb1
///
/// Why: as two edges turn parallel, their common normal (the direction of the line-line
/// distance's gradient) has no limit: it depends on the side they approach from, so the
/// edge-edge distance's gradient jumps at parallel edges that touch. m(x) = (2 - x / eps_x)
/// x / eps_x below a threshold eps_x, 1 above it, vanishes like the angle squared, so the
/// mollified pair energy m(x) b(d) is continuously differentiable there; contact between
/// nearly parallel edges is carried by the point-triangle pairs of their panels. Vectors of
/// 12 are ordered (ea0, ea1, eb0, eb1).

#include "kresling/contact/contact_distance.hpp"

namespace kresling::contact {

/// eps_x = 1e-3 |ea1 - ea0|^2 |eb1 - eb0|^2 of the edges at rest (reference) positions:
/// mollification acts when the sine of the edges' angle falls below about 0.03.
double edge_edge_mollifier_threshold(const Vector3& ea0_rest, const Vector3& ea1_rest,
                                     const Vector3& eb0_rest, const Vector3& eb1_rest);

/// m(x) with its gradient and (when requested) Hessian in the edge positions; m = 1 and
/// zero derivatives when x >= eps_x. eps_x must be positive.
ScalarDerivatives<12> edge_edge_mollifier(const Vector3& ea0, const Vector3& ea1,
                                          const Vector3& eb0, const Vector3& eb1, double eps_x,
                                          bool with_hessian = true);

}  // namespace kresling::contact
