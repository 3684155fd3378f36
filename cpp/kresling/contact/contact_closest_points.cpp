// Closest points of contact primitives (contact_closest_points.hpp).

#include "kresling/contact/contact_closest_points.hpp"

#include <algorithm>
#include <array>

#include <Eigen/Geometry>

#include "kresling/contact/contact_distance.hpp"

namespace kresling::contact {

namespace {

// The point of segment (e0, e1) nearest to p (e0 for a segment of zero length).
Vector3 on_segment(const Vector3& p, const Vector3& e0, const Vector3& e1) {
  const Vector3 e = e1 - e0;
  const double length2 = e.squaredNorm();
  const double t = length2 > 0 ? std::clamp(e.dot(p - e0) / length2, 0.0, 1.0) : 0.0;
  return e0 + t * e;
}

}  // namespace

Vector3 closest_point_on_triangle(const Vector3& p, const Vector3& t0, const Vector3& t1,
                                  const Vector3& t2) {
  const std::array<Vector3, 3> v = {t0, t1, t2};
  const int type = static_cast<int>(point_triangle_distance_type(p, t0, t1, t2));
  if (type <= 2) return v[type];                                        // a vertex
  if (type <= 5) return on_segment(p, v[type - 3], v[(type - 2) % 3]);  // an edge
  const Vector3 n = (t1 - t0).cross(t2 - t0);
  return p - ((p - t0).dot(n) / n.squaredNorm()) * n;                   // the interior
}

std::pair<Vector3, Vector3> closest_points_of_edges(const Vector3& ea0, const Vector3& ea1,
                                                    const Vector3& eb0, const Vector3& eb1) {
  // Minimise |ea0 + s a - eb0 - t b|^2 over [0, 1]^2: the unconstrained s clamped, then t for
  // it, then s again for the clamped t (exact for the convex quadratic on the square).
  const Vector3 a = ea1 - ea0, b = eb1 - eb0, r = ea0 - eb0;
  const double aa = a.squaredNorm(), bb = b.squaredNorm(), ab = a.dot(b);
  const double ar = a.dot(r), br = b.dot(r);
  const double det = aa * bb - ab * ab;
  double s = det > 1e-14 * aa * bb ? std::clamp((ab * br - bb * ar) / det, 0.0, 1.0) : 0.0;
  double t = bb > 0 ? std::clamp((ab * s + br) / bb, 0.0, 1.0) : 0.0;
  s = aa > 0 ? std::clamp((ab * t - ar) / aa, 0.0, 1.0) : 0.0;
  return {ea0 + s * a, eb0 + t * b};
}

}  // namespace kresling::contact
