// Which features of two contact primitives are closest (contact_distance.hpp).

#include <algorithm>
#include <array>

#include <Eigen/Geometry>

#include "kresling/contact/contact_distance.hpp"

namespace kresling::contact {

namespace {

// Edges whose sin^2 of angle is below this (relative to both lengths squared) are treated as
// parallel: the line-line formula divides by |ua x ub|^2, which then has no correct digit.
constexpr double kParallelSin2 = 2.5e-16;

// Position of p's projection along the segment e0 -> e1 (0 at e0, 1 at e1); 0 for a segment
// of zero length (its end e0 is then its closest point).
double segment_parameter(const Vector3& p, const Vector3& e0, const Vector3& e1) {
  const Vector3 e = e1 - e0;
  const double length2 = e.squaredNorm();
  return length2 > 0 ? e.dot(p - e0) / length2 : 0.0;
}

double point_segment_distance2(const Vector3& p, const Vector3& e0, const Vector3& e1) {
  const double t = std::clamp(segment_parameter(p, e0, e1), 0.0, 1.0);
  return (p - (e0 + t * (e1 - e0))).squaredNorm();
}

// Point against segment: 0 the first end, 1 the second, 2 the interior.
int point_segment_feature(const Vector3& p, const Vector3& e0, const Vector3& e1) {
  return static_cast<int>(point_edge_distance_type(p, e0, e1));
}

}  // namespace

PointEdgeDistanceType point_edge_distance_type(const Vector3& p, const Vector3& e0,
                                               const Vector3& e1) {
  const double t = segment_parameter(p, e0, e1);
  return t <= 0 ? PointEdgeDistanceType::P_E0
                : (t >= 1 ? PointEdgeDistanceType::P_E1 : PointEdgeDistanceType::P_E);
}

PointTriangleDistanceType point_triangle_distance_type(const Vector3& p, const Vector3& t0,
                                                       const Vector3& t1, const Vector3& t2) {
  // In the triangle's plane, each edge i (from vertex i to vertex i + 1) splits the plane
  // into its slab (0 < along_i < 1) and beyond; outside_i >= 0 on the side away from the
  // triangle. A point beyond an edge within its slab is closest to that edge; one past the
  // end of both edges at a vertex is closest to that vertex; any other to the interior.
  const std::array<Vector3, 3> v = {t0, t1, t2};
  const Vector3 normal = (t1 - t0).cross(t2 - t0);
  std::array<double, 3> along{};
  for (int i = 0; i < 3; ++i) {
    const Vector3 e = v[(i + 1) % 3] - v[i];
    const Vector3 r = p - v[i];
    along[i] = e.dot(r) / e.squaredNorm();
    const double outside = r.dot(e.cross(normal));
    if (outside >= 0 && along[i] > 0 && along[i] < 1) {
      return static_cast<PointTriangleDistanceType>(
          static_cast<int>(PointTriangleDistanceType::P_E0) + i);
    }
  }
  for (int j = 0; j < 3; ++j) {
    if (along[j] <= 0 && along[(j + 2) % 3] >= 1) {
      return static_cast<PointTriangleDistanceType>(j);  // P_T0, P_T1, P_T2
    }
  }
  return PointTriangleDistanceType::P_T;
}

EdgeEdgeDistanceType edge_edge_distance_type(const Vector3& ea0, const Vector3& ea1,
                                             const Vector3& eb0, const Vector3& eb1) {
  // The distance of two segments is that of their lines when the lines' closest points lie
  // inside both segments; otherwise it is attained with one end fixed, so it is the least
  // of the four end-to-segment distances (this also covers parallel and zero-length edges).
  const Vector3 u = ea1 - ea0, v = eb1 - eb0, w = ea0 - eb0;
  const double a = u.squaredNorm(), b = u.dot(v), c = v.squaredNorm();
  const double d = u.dot(w), e = v.dot(w);
  const double det = a * c - b * b;
  if (a > 0 && c > 0 && u.cross(v).squaredNorm() >= kParallelSin2 * a * c) {
    const double s = (b * e - c * d) / det;  // along edge a
    const double t = (a * e - b * d) / det;  // along edge b
    if (s > 0 && s < 1 && t > 0 && t < 1) return EdgeEdgeDistanceType::EA_EB;
  }
  using T = EdgeEdgeDistanceType;
  // Each end against the other segment: its distance, and the type for its three features.
  struct EndCase {
    double distance2;
    std::array<T, 3> types;  // closest to the other's first end, second end, interior
  };
  const std::array<EndCase, 4> cases = {{
      {point_segment_distance2(ea0, eb0, eb1), {T::EA0_EB0, T::EA0_EB1, T::EA0_EB}},
      {point_segment_distance2(ea1, eb0, eb1), {T::EA1_EB0, T::EA1_EB1, T::EA1_EB}},
      {point_segment_distance2(eb0, ea0, ea1), {T::EA0_EB0, T::EA1_EB0, T::EA_EB0}},
      {point_segment_distance2(eb1, ea0, ea1), {T::EA0_EB1, T::EA1_EB1, T::EA_EB1}},
  }};
  int best = 0;
  for (int k = 1; k < 4; ++k) {
    if (cases[k].distance2 < cases[best].distance2) best = k;
  }
  const int feature = best == 0   ? point_segment_feature(ea0, eb0, eb1)
                      : best == 1 ? point_segment_feature(ea1, eb0, eb1)
                      : best == 2 ? point_segment_feature(eb0, ea0, ea1)
                                  : point_segment_feature(eb1, ea0, ea1);
  return cases[best].types[feature];
}

}  // namespace kresling::contact
