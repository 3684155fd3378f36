#pragma once
/// \file contact_distance.hpp
/// Squared distances between contact primitives and their exact first and second
/// derivatives (pure kernels, no allocation), as the incremental-potential-contact (IPC)
/// formulation uses them: a point against a triangle, an edge against an edge, a point
/// against a rigid plane.
///
///     point-triangle                    edge-edge
///
///            t2                       ea0 o-----------o ea1
///           /  \        o p
///          /    \                          eb0 o-----------o eb1
///       t0 ------ t1
///
/// Vectors of 12 are ordered (p, t0, t1, t2) and (ea0, ea1, eb0, eb1). Every distance here is
/// the *squared* Euclidean distance (as in IPC: it is polynomial over rational, so smooth
/// wherever the closest features do not change). Which features are closest (a vertex, an
/// edge's interior, the triangle's interior) is decided first by the regions of the closest
/// point (`*_distance_type`); the distance is then that of the two features, point-point,
/// point-line, point-plane or line-line, which is smooth inside a region and continuous with
/// continuous first derivatives across the region borders.

#include "kresling/core/types.hpp"

namespace kresling::contact {

using Vector9 = Eigen::Matrix<double, 9, 1>;
using Matrix9 = Eigen::Matrix<double, 9, 9>;

/// A scalar of N coordinates with its gradient and (when requested) its Hessian.
template <int N>
struct ScalarDerivatives {
  double value = 0.0;
  Eigen::Matrix<double, N, 1> gradient = Eigen::Matrix<double, N, 1>::Zero();
  Eigen::Matrix<double, N, N> hessian = Eigen::Matrix<double, N, N>::Zero();
};

/// The closest features of a point p and a triangle (t0, t1, t2). Codes as in IPC: P_T0..2
/// a vertex, P_E0 the edge t0 t1, P_E1 t1 t2, P_E2 t2 t0, P_T the interior.
enum class PointTriangleDistanceType { P_T0 = 0, P_T1, P_T2, P_E0, P_E1, P_E2, P_T };

/// The closest features of two edges: an end (EA0, EA1 / EB0, EB1) or the interior (EA / EB)
/// of each. Codes as in IPC.
enum class EdgeEdgeDistanceType {
  EA0_EB0 = 0, EA0_EB1, EA1_EB0, EA1_EB1, EA_EB0, EA_EB1, EA0_EB, EA1_EB, EA_EB
};

/// The closest features of a point p and a segment (e0, e1): an end or the interior.
enum class PointEdgeDistanceType { P_E0 = 0, P_E1, P_E };

/// The closest features of a point and a segment (a zero-length segment: its end e0).
PointEdgeDistanceType point_edge_distance_type(const Vector3& p, const Vector3& e0,
                                               const Vector3& e1);

/// The closest features of a point and a triangle, from the regions of the closest point.
/// A degenerate triangle (zero area) has no interior; callers validate geometry first.
PointTriangleDistanceType point_triangle_distance_type(const Vector3& p, const Vector3& t0,
                                                       const Vector3& t1, const Vector3& t2);

/// The closest features of two segments. Nearly parallel segments (sin^2 of their angle
/// below 2.5e-16, where the line-line formula loses all its digits) are classified by their
/// overlap along the first edge instead, so that an end of one always enters.
EdgeEdgeDistanceType edge_edge_distance_type(const Vector3& ea0, const Vector3& ea1,
                                             const Vector3& eb0, const Vector3& eb1);

/// |a - b|^2, ordered (a, b).
ScalarDerivatives<6> point_point_distance(const Vector3& a, const Vector3& b,
                                          bool with_hessian = true);

/// Squared distance of p from the line through e0 and e1, |(p - e0) x (e1 - e0)|^2 / |e1 -
/// e0|^2, ordered (p, e0, e1).
ScalarDerivatives<9> point_line_distance(const Vector3& p, const Vector3& e0, const Vector3& e1,
                                         bool with_hessian = true);

/// Squared distance of p from the plane through t0, t1, t2, ((p - t0) . n)^2 / |n|^2 with
/// n = (t1 - t0) x (t2 - t0), ordered (p, t0, t1, t2).
ScalarDerivatives<12> point_plane_distance(const Vector3& p, const Vector3& t0,
                                           const Vector3& t1, const Vector3& t2,
                                           bool with_hessian = true);

/// Squared distance of the lines through (ea0, ea1) and (eb0, eb1), ((ea0 - eb0) . n)^2 /
/// |n|^2 with n = (ea1 - ea0) x (eb1 - eb0); undefined for parallel lines.
ScalarDerivatives<12> line_line_distance(const Vector3& ea0, const Vector3& ea1,
                                         const Vector3& eb0, const Vector3& eb1,
                                         bool with_hessian = true);

/// Squared distance of a point from a segment (the closest of its ends or its interior),
/// ordered (p, e0, e1).
ScalarDerivatives<9> point_edge_distance(const Vector3& p, const Vector3& e0, const Vector3& e1,
                                         bool with_hessian = true);

/// Squared distance of a point from a triangle, for the given closest features.
ScalarDerivatives<12> point_triangle_distance(const Vector3& p, const Vector3& t0,
                                              const Vector3& t1, const Vector3& t2,
                                              PointTriangleDistanceType type,
                                              bool with_hessian = true);

/// Squared distance of a point from a triangle, closest features found first.
ScalarDerivatives<12> point_triangle_distance(const Vector3& p, const Vector3& t0,
                                              const Vector3& t1, const Vector3& t2,
                                              bool with_hessian = true);

/// Squared distance of two segments, for the given closest features.
ScalarDerivatives<12> edge_edge_distance(const Vector3& ea0, const Vector3& ea1,
                                         const Vector3& eb0, const Vector3& eb1,
                                         EdgeEdgeDistanceType type, bool with_hessian = true);

/// Squared distance of two segments, closest features found first.
ScalarDerivatives<12> edge_edge_distance(const Vector3& ea0, const Vector3& ea1,
                                         const Vector3& eb0, const Vector3& eb1,
                                         bool with_hessian = true);

/// Signed distance of p from a rigid plane through `origin` with normal `normal` (any
/// non-zero length; positive on the side the normal points to): (p - origin) . n / |n|.
double point_plane_signed_distance(const Vector3& p, const Vector3& origin,
                                   const Vector3& normal);

/// Squared distance of p from a rigid plane, ((p - origin) . n)^2 / |n|^2, with its
/// gradient and Hessian in p alone (the plane does not move).
ScalarDerivatives<3> point_rigid_plane_distance(const Vector3& p, const Vector3& origin,
                                                const Vector3& normal);

/// |a x b|^2, ordered (a, b): the building block of the distances above and of the
/// edge-edge mollifier.
ScalarDerivatives<6> cross_squared_norm(const Vector3& a, const Vector3& b,
                                        bool with_hessian = true);

}  // namespace kresling::contact
