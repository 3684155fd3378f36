#include "kresling/elements/corner_angle.hpp"

#include <cmath>

namespace kresling::elements {

namespace {

// The corner at p with sides u = q - p, w = r - p: its angle, the angle's gradient with
// respect to u and w, and (when asked) its Hessian in the (u, w) variables.
struct Corner {
  double angle;
  Vector3 du, dw;
  Matrix3 uu, uw, ww;
};

Corner corner(const Vector3& u, const Vector3& w, bool with_hessian) {
  Corner k;
  const double lu = u.norm(), lw = w.norm();
  const Vector3 a = u / lu, b = w / lw;
  const double c = a.dot(b);
  const double s = a.cross(b).norm();
  k.angle = std::atan2(s, c);  // full precision near 0 and pi, where acos(c) would not be
  // Gradient of the cosine: dc/du = (b - c a) / |u|, dc/dw = (a - c b) / |w|.
  const Vector3 cu = (b - c * a) / lu, cw = (a - c * b) / lw;
  k.du = -cu / s;
  k.dw = -cw / s;
  if (!with_hessian) return k;
  const Matrix3 I = Matrix3::Identity();
  const Matrix3 Pa = I - a * a.transpose(), Pb = I - b * b.transpose();
  // Second derivatives of c = (u . w) / (|u| |w|).
  const Matrix3 c_uu = -(a * (b - c * a).transpose() + (b - c * a) * a.transpose() + c * Pa) /
                       (lu * lu);
  const Matrix3 c_ww = -(b * (a - c * b).transpose() + (a - c * b) * b.transpose() + c * Pb) /
                       (lw * lw);
  const Matrix3 c_uw = (Pb - a * (a - c * b).transpose()) / (lu * lw);
  // alpha = acos(c): alpha' = -1/s, alpha'' = -c/s^3.
  const double d1 = -1.0 / s, d2 = -c / (s * s * s);
  k.uu = d1 * c_uu + d2 * cu * cu.transpose();
  k.ww = d1 * c_ww + d2 * cw * cw.transpose();
  k.uw = d1 * c_uw + d2 * cu * cw.transpose();
  return k;
}

}  // namespace

std::array<double, 3> corner_angles(const Vector3& x0, const Vector3& x1, const Vector3& x2) {
  // The response's own formula, so that a triangle at its measured rest angles stores
  // nothing to the last bit.
  return {corner(x1 - x0, x2 - x0, false).angle, corner(x2 - x1, x0 - x1, false).angle,
          corner(x0 - x2, x1 - x2, false).angle};
}

CornerAngleResponse corner_angle_response(const Vector3& x0, const Vector3& x1,
                                          const Vector3& x2, const std::array<double, 3>& rest,
                                          double k, bool with_tangent) {
  CornerAngleResponse r;
  const std::array<const Vector3*, 3> x = {&x0, &x1, &x2};
  for (int i = 0; i < 3; ++i) {
    // Corner i at node p = i, its sides to q = i + 1 and r = i + 2 (cyclically).
    const int p = i, q = (i + 1) % 3, s = (i + 2) % 3;
    const Corner c = corner(*x[q] - *x[p], *x[s] - *x[p], with_tangent);
    r.angle[i] = c.angle;
    const double excess = c.angle - rest[i];
    r.energy += 0.5 * k * excess * excess;
    // p moves both sides: d/dp = -(d/du + d/dw).
    Vector9 g = Vector9::Zero();
    g.segment<3>(3 * q) = c.du;
    g.segment<3>(3 * s) = c.dw;
    g.segment<3>(3 * p) = -(c.du + c.dw);
    r.force += k * excess * g;
    r.gradients[i] = g;
    if (!with_tangent) continue;
    Matrix9 h = Matrix9::Zero();
    h.block<3, 3>(3 * q, 3 * q) = c.uu;
    h.block<3, 3>(3 * s, 3 * s) = c.ww;
    h.block<3, 3>(3 * q, 3 * s) = c.uw;
    h.block<3, 3>(3 * s, 3 * q) = c.uw.transpose();
    const Matrix3 pq = -(c.uu + c.uw.transpose()), ps = -(c.uw + c.ww);
    h.block<3, 3>(3 * p, 3 * q) = pq;
    h.block<3, 3>(3 * q, 3 * p) = pq.transpose();
    h.block<3, 3>(3 * p, 3 * s) = ps;
    h.block<3, 3>(3 * s, 3 * p) = ps.transpose();
    h.block<3, 3>(3 * p, 3 * p) = c.uu + c.uw + c.uw.transpose() + c.ww;
    r.stiffness += k * (g * g.transpose() + excess * h);
  }
  return r;
}

}  // namespace kresling::elements
