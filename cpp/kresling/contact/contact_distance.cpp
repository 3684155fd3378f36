// Squared distances of contact primitives with exact gradients and Hessians
// (contact_distance.hpp).
//
// Each distance is written as a function f(y) of a few difference vectors y (r = p - t0,
// e1 = t1 - t0, ...), which are a constant linear map y = A x of the node positions x; then
// grad = A^T grad_y f and Hessian = A^T hess_y f A. The derivatives in y come from two
// building blocks, |a x b|^2 and (r . (a x b))^2, combined by the quotient rule.

#include "kresling/contact/contact_distance.hpp"

#include <array>

#include <Eigen/Geometry>

namespace kresling::contact {

namespace {

Matrix3 cross_matrix(const Vector3& v) {
  Matrix3 m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// u / v by the quotient rule (v > 0).
template <int N>
ScalarDerivatives<N> quotient(const ScalarDerivatives<N>& u, const ScalarDerivatives<N>& v,
                              bool with_hessian) {
  ScalarDerivatives<N> f;
  const double inv = 1.0 / v.value;
  f.value = u.value * inv;
  f.gradient = (u.gradient - f.value * v.gradient) * inv;
  if (with_hessian) {
    // H_f = (H_u - f H_v - grad_f grad_v^T - grad_v grad_f^T) / v
    f.hessian = (u.hessian - f.value * v.hessian - f.gradient * v.gradient.transpose() -
                 v.gradient * f.gradient.transpose()) *
                inv;
  }
  return f;
}

// f(A x): derivatives in x from those in y = A x.
template <int M, int N>
ScalarDerivatives<N> pull_back(const ScalarDerivatives<M>& f, const Eigen::Matrix<double, M, N>& A,
                               bool with_hessian) {
  ScalarDerivatives<N> g;
  g.value = f.value;
  g.gradient = A.transpose() * f.gradient;
  if (with_hessian) g.hessian = A.transpose() * f.hessian * A;
  return g;
}

// The map y = A x for difference vectors: each row block k of y is x_plus[k] - x_minus[k]
// (node indices of x, -1 for none).
template <int M, int N>
Eigen::Matrix<double, M, N> difference_map(const std::array<int, M / 3>& plus,
                                           const std::array<int, M / 3>& minus) {
  Eigen::Matrix<double, M, N> A = Eigen::Matrix<double, M, N>::Zero();
  for (int k = 0; k < M / 3; ++k) {
    A.template block<3, 3>(3 * k, 3 * plus[k]).setIdentity();
    if (minus[k] >= 0) A.template block<3, 3>(3 * k, 3 * minus[k]) -= Matrix3::Identity();
  }
  return A;
}

// (r . (a x b))^2 / |a x b|^2 in y = (r, a, b): the squared distance of a point from a
// plane (r from a point of the plane, a and b spanning it) and of two lines.
ScalarDerivatives<9> plane_distance(const Vector3& r, const Vector3& a, const Vector3& b,
                                    bool with_hessian) {
  const Vector3 n = a.cross(b);
  const double s = r.dot(n);  // the triple product
  Vector9 grad_s;
  grad_s << n, b.cross(r), r.cross(a);
  ScalarDerivatives<9> u;  // s^2
  u.value = s * s;
  u.gradient = 2 * s * grad_s;
  ScalarDerivatives<9> v;  // |a x b|^2, which does not depend on r
  const ScalarDerivatives<6> q = cross_squared_norm(a, b, with_hessian);
  v.value = q.value;
  v.gradient.tail<6>() = q.gradient;
  if (with_hessian) {
    // s is trilinear: its Hessian has only the mixed blocks, d(n)/da = -[b]x, d(n)/db = [a]x,
    // d(b x r)/db = -[r]x.
    Matrix9 hess_s = Matrix9::Zero();
    hess_s.block<3, 3>(0, 3) = -cross_matrix(b);
    hess_s.block<3, 3>(0, 6) = cross_matrix(a);
    hess_s.block<3, 3>(3, 6) = -cross_matrix(r);
    hess_s.block<3, 3>(3, 0) = hess_s.block<3, 3>(0, 3).transpose();
    hess_s.block<3, 3>(6, 0) = hess_s.block<3, 3>(0, 6).transpose();
    hess_s.block<3, 3>(6, 3) = hess_s.block<3, 3>(3, 6).transpose();
    u.hessian = 2 * grad_s * grad_s.transpose() + 2 * s * hess_s;
    v.hessian.bottomRightCorner<6, 6>() = q.hessian;
  }
  return quotient(u, v, with_hessian);
}

// Embed the derivatives of K / 3 nodes into those of N / 3, at the given node slots.
template <int N, int K>
ScalarDerivatives<N> scatter(const ScalarDerivatives<K>& f, const std::array<int, K / 3>& slot,
                             bool with_hessian) {
  ScalarDerivatives<N> g;
  g.value = f.value;
  for (int i = 0; i < K / 3; ++i) {
    g.gradient.template segment<3>(3 * slot[i]) = f.gradient.template segment<3>(3 * i);
    if (!with_hessian) continue;
    for (int j = 0; j < K / 3; ++j) {
      g.hessian.template block<3, 3>(3 * slot[i], 3 * slot[j]) =
          f.hessian.template block<3, 3>(3 * i, 3 * j);
    }
  }
  return g;
}

}  // namespace

ScalarDerivatives<6> cross_squared_norm(const Vector3& a, const Vector3& b, bool with_hessian) {
  const Vector3 c = a.cross(b);
  Eigen::Matrix<double, 3, 6> J;  // dc / d(a, b)
  J << -cross_matrix(b), cross_matrix(a);
  ScalarDerivatives<6> f;
  f.value = c.squaredNorm();
  f.gradient = 2 * J.transpose() * c;
  if (with_hessian) {
    // 2 J^T J plus 2 sum_k c_k d2c_k, whose only blocks are d2c_k / da_i db_j = eps_kij:
    // sum_k c_k eps_kij = -[c]x_ij.
    f.hessian = 2 * J.transpose() * J;
    f.hessian.block<3, 3>(0, 3) -= 2 * cross_matrix(c);
    f.hessian.block<3, 3>(3, 0) += 2 * cross_matrix(c);
  }
  return f;
}

ScalarDerivatives<6> point_point_distance(const Vector3& a, const Vector3& b, bool with_hessian) {
  ScalarDerivatives<6> f;
  const Vector3 r = a - b;
  f.value = r.squaredNorm();
  f.gradient << 2 * r, -2 * r;
  if (with_hessian) {
    const Matrix3 I2 = 2 * Matrix3::Identity();
    f.hessian << I2, -I2, -I2, I2;
  }
  return f;
}

ScalarDerivatives<9> point_line_distance(const Vector3& p, const Vector3& e0, const Vector3& e1,
                                         bool with_hessian) {
  // |r x e|^2 / |e|^2 in y = (r, e), r = p - e0, e = e1 - e0.
  const Vector3 r = p - e0, e = e1 - e0;
  const ScalarDerivatives<6> u = cross_squared_norm(r, e, with_hessian);
  ScalarDerivatives<6> v;
  v.value = e.squaredNorm();
  v.gradient.tail<3>() = 2 * e;
  if (with_hessian) v.hessian.bottomRightCorner<3, 3>() = 2 * Matrix3::Identity();
  const auto A = difference_map<6, 9>({0, 2}, {1, 1});
  return pull_back(quotient(u, v, with_hessian), A, with_hessian);
}

ScalarDerivatives<12> point_plane_distance(const Vector3& p, const Vector3& t0,
                                           const Vector3& t1, const Vector3& t2,
                                           bool with_hessian) {
  const auto f = plane_distance(p - t0, t1 - t0, t2 - t0, with_hessian);
  const auto A = difference_map<9, 12>({0, 2, 3}, {1, 1, 1});
  return pull_back(f, A, with_hessian);
}

ScalarDerivatives<12> line_line_distance(const Vector3& ea0, const Vector3& ea1,
                                         const Vector3& eb0, const Vector3& eb1,
                                         bool with_hessian) {
  const auto f = plane_distance(ea0 - eb0, ea1 - ea0, eb1 - eb0, with_hessian);
  const auto A = difference_map<9, 12>({0, 1, 3}, {2, 0, 2});
  return pull_back(f, A, with_hessian);
}

ScalarDerivatives<9> point_edge_distance(const Vector3& p, const Vector3& e0, const Vector3& e1,
                                         bool with_hessian) {
  switch (point_edge_distance_type(p, e0, e1)) {
    case PointEdgeDistanceType::P_E0:
      return scatter<9>(point_point_distance(p, e0, with_hessian), {0, 1}, with_hessian);
    case PointEdgeDistanceType::P_E1:
      return scatter<9>(point_point_distance(p, e1, with_hessian), {0, 2}, with_hessian);
    case PointEdgeDistanceType::P_E:
      break;
  }
  return point_line_distance(p, e0, e1, with_hessian);
}

ScalarDerivatives<12> point_triangle_distance(const Vector3& p, const Vector3& t0,
                                              const Vector3& t1, const Vector3& t2,
                                              PointTriangleDistanceType type,
                                              bool with_hessian) {
  using T = PointTriangleDistanceType;
  const bool h = with_hessian;
  switch (type) {
    case T::P_T0: return scatter<12>(point_point_distance(p, t0, h), {0, 1}, h);
    case T::P_T1: return scatter<12>(point_point_distance(p, t1, h), {0, 2}, h);
    case T::P_T2: return scatter<12>(point_point_distance(p, t2, h), {0, 3}, h);
    case T::P_E0: return scatter<12>(point_line_distance(p, t0, t1, h), {0, 1, 2}, h);
    case T::P_E1: return scatter<12>(point_line_distance(p, t1, t2, h), {0, 2, 3}, h);
    case T::P_E2: return scatter<12>(point_line_distance(p, t2, t0, h), {0, 3, 1}, h);
    case T::P_T: break;
  }
  return point_plane_distance(p, t0, t1, t2, h);
}

ScalarDerivatives<12> point_triangle_distance(const Vector3& p, const Vector3& t0,
                                              const Vector3& t1, const Vector3& t2,
                                              bool with_hessian) {
  return point_triangle_distance(p, t0, t1, t2, point_triangle_distance_type(p, t0, t1, t2),
                                 with_hessian);
}

ScalarDerivatives<12> edge_edge_distance(const Vector3& ea0, const Vector3& ea1,
                                         const Vector3& eb0, const Vector3& eb1,
                                         EdgeEdgeDistanceType type, bool with_hessian) {
  using T = EdgeEdgeDistanceType;
  const bool h = with_hessian;
  switch (type) {
    case T::EA0_EB0: return scatter<12>(point_point_distance(ea0, eb0, h), {0, 2}, h);
    case T::EA0_EB1: return scatter<12>(point_point_distance(ea0, eb1, h), {0, 3}, h);
    case T::EA1_EB0: return scatter<12>(point_point_distance(ea1, eb0, h), {1, 2}, h);
    case T::EA1_EB1: return scatter<12>(point_point_distance(ea1, eb1, h), {1, 3}, h);
    case T::EA_EB0: return scatter<12>(point_line_distance(eb0, ea0, ea1, h), {2, 0, 1}, h);
    case T::EA_EB1: return scatter<12>(point_line_distance(eb1, ea0, ea1, h), {3, 0, 1}, h);
    case T::EA0_EB: return scatter<12>(point_line_distance(ea0, eb0, eb1, h), {0, 2, 3}, h);
    case T::EA1_EB: return scatter<12>(point_line_distance(ea1, eb0, eb1, h), {1, 2, 3}, h);
    case T::EA_EB: break;
  }
  return line_line_distance(ea0, ea1, eb0, eb1, h);
}

ScalarDerivatives<12> edge_edge_distance(const Vector3& ea0, const Vector3& ea1,
                                         const Vector3& eb0, const Vector3& eb1,
                                         bool with_hessian) {
  return edge_edge_distance(ea0, ea1, eb0, eb1, edge_edge_distance_type(ea0, ea1, eb0, eb1),
                            with_hessian);
}

double point_plane_signed_distance(const Vector3& p, const Vector3& origin,
                                   const Vector3& normal) {
  return (p - origin).dot(normal) / normal.norm();
}

ScalarDerivatives<3> point_rigid_plane_distance(const Vector3& p, const Vector3& origin,
                                                const Vector3& normal) {
  // s^2 with s = (p - origin) . n_hat: gradient 2 s n_hat, Hessian 2 n_hat n_hat^T.
  const Vector3 n_hat = normal / normal.norm();
  const double s = (p - origin).dot(n_hat);
  ScalarDerivatives<3> f;
  f.value = s * s;
  f.gradient = 2 * s * n_hat;
  f.hessian = 2 * n_hat * n_hat.transpose();
  return f;
}

}  // namespace kresling::contact
