#pragma once
/// \file contact_closest_points.hpp
/// The closest points of two contact primitives, for showing contact pairs (a segment
/// between the two points) rather than for their energies, which need only the distances
/// (contact_distance.hpp).
///
///            t2
///           /  \        o p          point-triangle: p and its nearest point of the triangle
///          /  q o-------'
///       t0 ------ t1                 edge-edge: the nearest point of each segment

#include <utility>

#include "kresling/core/types.hpp"

namespace kresling::contact {

/// The point of the triangle (t0, t1, t2) nearest to p (its closest features as
/// point_triangle_distance_type finds them).
Vector3 closest_point_on_triangle(const Vector3& p, const Vector3& t0, const Vector3& t1,
                                  const Vector3& t2);

/// The nearest points of the segments (ea0, ea1) and (eb0, eb1): first on a, then on b.
std::pair<Vector3, Vector3> closest_points_of_edges(const Vector3& ea0, const Vector3& ea1,
                                                    const Vector3& eb0, const Vector3& eb1);

}  // namespace kresling::contact
