#include "kresling/elements/dihedral.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace kresling::elements {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// Keep an angle in [0, 2 pi): 2 pi - theta rounds to 2 pi itself for theta below ~4e-16 (a
// hinge folded flat, e.g. a polygon edge of a cell with Lc ~ 1e-8 R).
double below_two_pi(double angle) {
  return angle < kTwoPi ? angle : std::nextafter(kTwoPi, 0.0);
}

// MERLIN2's formula (docs/model.md, 'Hinges'), kept exactly so that forces match its runs to
// rounding: theta = sgn acos(m.n / |m||n|), sgn = sign(n . r_ac), taken as +1 when
// |n . r_ac| <= 1e-8, then mapped to [0, 2 pi). (m x n is parallel to the axis with the same
// sign as n . r_ac.) Near 0 and pi the arccosine is ill-conditioned: acos(-1 + d) =
// pi - sqrt(2 d), so an ulp of the cosine is ~1e-8 rad of angle there.
double merlin_angle(const Vector3& m, const Vector3& n, const Vector3& r_ac) {
  const double cosine = std::clamp(m.dot(n) / (m.norm() * n.norm()), -1.0, 1.0);
  const double theta = std::acos(cosine);
  const double side = n.dot(r_ac);
  if (!(side < -1e-8)) return theta;
  return below_two_pi(kTwoPi - theta);
}

// The same angle from atan2(|m||n| sin, |m||n| cos): (m x n) . e / |e| and m . n are both
// accurate to rounding relative to |m||n|, so the angle is too, at 0 and pi as elsewhere.
// The sign of the sine is that of n . r_ac (the side), without MERLIN2's threshold.
double exact_angle(const Vector3& m, const Vector3& n, const Vector3& e) {
  const double sine = m.cross(n).dot(e) / e.norm();
  const double theta = std::atan2(sine, m.dot(n));
  return theta < 0.0 ? below_two_pi(theta + kTwoPi) : theta + 0.0;  // + 0.0: not -0.0
}

double angle_of(const Vector3& m, const Vector3& n, const Vector3& e, const Vector3& r_ac,
                DihedralForm form) {
  return form == DihedralForm::Merlin2 ? merlin_angle(m, n, r_ac) : exact_angle(m, n, e);
}

}  // namespace

DihedralForm dihedral_form(long long code, const char* what) {
  if (code == 0 || code == 1) return static_cast<DihedralForm>(code);
  throw std::invalid_argument(std::string(what) + " = " + std::to_string(code) +
                              " is invalid: must be 0 (the exact angle, atan2) or 1 "
                              "(MERLIN2's arccosine)");
}

double dihedral_angle(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d,
                      DihedralForm form) {
  const Vector3 e = b - a;
  const Vector3 r_ac = c - a;
  return angle_of(r_ac.cross(e), e.cross(b - d), e, r_ac, form);
}

Vector12 dihedral_angle_gradient(const Vector3& a, const Vector3& b, const Vector3& c,
                                 const Vector3& d) {
  return dihedral_angle_derivatives(a, b, c, d, false).gradient;
}

Matrix12 dihedral_angle_hessian(const Vector3& a, const Vector3& b, const Vector3& c,
                                const Vector3& d) {
  return dihedral_angle_derivatives(a, b, c, d, true).hessian;
}

DihedralDerivatives dihedral_angle_derivatives(const Vector3& a, const Vector3& b,
                                               const Vector3& c, const Vector3& d,
                                               bool with_hessian, DihedralForm form) {
  DihedralDerivatives out;
  const Vector3 e = b - a;       // axis
  const Vector3 r_ac = c - a;    // to wing 1
  const Vector3 r_db = b - d;    // from wing 2
  const Vector3 m = r_ac.cross(e);
  const Vector3 n = e.cross(r_db);
  const double L2 = e.squaredNorm();
  const double L = std::sqrt(L2);
  const double m2 = m.squaredNorm();
  const double n2 = n.squaredNorm();
  out.angle = angle_of(m, n, e, r_ac, form);

  // Wing derivatives: each wing moves the angle along its triangle's normal, inversely
  // to its distance from the axis (|m| / L); the axis nodes take the rest so that the
  // gradient is invariant to translation and rotation.
  const double A = r_ac.dot(e) / L2;  // projection of wing 1 on the axis, in units of L
  const double B = r_db.dot(e) / L2;  // same for wing 2, measured from b
  const Vector3 gc = (L / m2) * m;
  const Vector3 gd = -(L / n2) * n;
  const Vector3 ga = (A - 1.0) * gc - B * gd;
  const Vector3 gb = (B - 1.0) * gd - A * gc;
  out.gradient << ga, gb, gc, gd;
  if (!with_hessian) return out;

  // Second derivatives, block by block (rows: derivative of the gradient of that node).
  // Wing-wing blocks: with u = m/|m| and w = u x e/L, d(gc)/dc = L^2/|m|^2 (u w^T + w u^T);
  // likewise for d with the opposite sign. The two wings do not interact (H_cd = 0).
  const Vector3 e_hat = e / L;
  const Vector3 u = m / std::sqrt(m2);
  const Vector3 w = u.cross(e_hat);
  const Vector3 v = n / std::sqrt(n2);
  const Vector3 z = v.cross(e_hat);
  const Matrix3 Hcc = (L2 / m2) * (u * w.transpose() + w * u.transpose());
  const Matrix3 Hdd = -(L2 / n2) * (v * z.transpose() + z * v.transpose());
  // Axis-wing blocks from g_a = (A-1) g_c - B g_d, g_b = (B-1) g_d - A g_c and
  // dA/dc = e/L^2, dB/dd = -e/L^2.
  const Matrix3 gc_e = gc * e.transpose() / L2;
  const Matrix3 gd_e = gd * e.transpose() / L2;
  const Matrix3 Hac = (A - 1.0) * Hcc + gc_e;
  const Matrix3 Hbc = -A * Hcc - gc_e;
  const Matrix3 Had = -B * Hdd + gd_e;
  const Matrix3 Hbd = (B - 1.0) * Hdd - gd_e;
  // Axis-axis: H_bb by the product rule with dA/db = (r_ac - 2 A e)/L^2 and
  // dB/db = (r_db + (1 - 2 B) e)/L^2; the others from translation invariance (every block
  // row sums to zero) and symmetry.
  const Matrix3 Hbb = (B - 1.0) * (B - 1.0) * Hdd + A * A * Hcc +
                      (-(B - 1.0) * e * gd.transpose() +
                       gd * (r_db + (1.0 - 2.0 * B) * e).transpose() + A * e * gc.transpose() -
                       gc * (r_ac - 2.0 * A * e).transpose()) /
                          L2;
  const Matrix3 Hba = -(Hbb + Hbc + Hbd);
  const Matrix3 Haa = -(Hba.transpose() + Hac + Had);

  Matrix12& H = out.hessian;
  H.block<3, 3>(0, 0) = Haa;
  H.block<3, 3>(0, 3) = Hba.transpose();
  H.block<3, 3>(0, 6) = Hac;
  H.block<3, 3>(0, 9) = Had;
  H.block<3, 3>(3, 0) = Hba;
  H.block<3, 3>(3, 3) = Hbb;
  H.block<3, 3>(3, 6) = Hbc;
  H.block<3, 3>(3, 9) = Hbd;
  H.block<3, 3>(6, 0) = Hac.transpose();
  H.block<3, 3>(6, 3) = Hbc.transpose();
  H.block<3, 3>(6, 6) = Hcc;
  H.block<3, 3>(6, 9).setZero();
  H.block<3, 3>(9, 0) = Had.transpose();
  H.block<3, 3>(9, 3) = Hbd.transpose();
  H.block<3, 3>(9, 6).setZero();
  H.block<3, 3>(9, 9) = Hdd;
  return out;
}

}  // namespace kresling::elements
