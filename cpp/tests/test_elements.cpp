// Element kernels against finite differences, closed forms and rigid motions.
//
// Tolerances: central differences with step h have truncation error ~h^2 |f'''| and
// rounding error ~eps |f| / h; with h = 1e-6 on O(1) geometry both are below 1e-8 of the
// derivative's scale, so 1e-6 relative (on the norm) leaves two orders of headroom while
// still catching any wrong term (those are O(1) relative).

#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "finite_differences.hpp"
#include "kresling/elements/bar.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"
#include "kresling/elements/spring_laws.hpp"

using namespace kresling;
using namespace kresling::elements;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStep = 1e-6;
constexpr double kRelTol = 1e-6;

Vector3 random_point(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

// A hinge with wings well away from its axis (the angle is undefined on the axis line).
std::array<Vector3, 4> random_hinge(std::mt19937& rng, double scale) {
  for (;;) {
    std::array<Vector3, 4> x = {random_point(rng, scale), random_point(rng, scale),
                                random_point(rng, scale), random_point(rng, scale)};
    const Vector3 e = (x[1] - x[0]).normalized();
    const double hc = (x[2] - x[0]).cross(e).norm(), hd = (x[3] - x[1]).cross(e).norm();
    if ((x[1] - x[0]).norm() > 0.3 * scale && hc > 0.2 * scale && hd > 0.2 * scale) return x;
  }
}

Vector12 stack(const std::array<Vector3, 4>& x) {
  Vector12 v;
  v << x[0], x[1], x[2], x[3];
  return v;
}

std::array<Vector3, 4> unstack(const Vector12& v) {
  return {v.segment<3>(0), v.segment<3>(3), v.segment<3>(6), v.segment<3>(9)};
}

double angle_of(const Vector12& v) {
  const auto x = unstack(v);
  return dihedral_angle(x[0], x[1], x[2], x[3]);
}

Vector12 gradient_of(const Vector12& v) {
  const auto x = unstack(v);
  return dihedral_angle_gradient(x[0], x[1], x[2], x[3]);
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  const Vector3 axis = random_point(rng).normalized();
  return Eigen::AngleAxisd(std::uniform_real_distribution<double>(0, 2 * kPi)(rng), axis)
      .toRotationMatrix();
}

}  // namespace

TEST(Dihedral, AngleSweepsTheWholeTurn) {
  // Axis along z, wing c on +x: the angle equals the azimuth of wing d, from 0 to 2 pi.
  // The exact form (atan2) is accurate to rounding everywhere, at 1e-7 rad from flat (pi)
  // and from folded flat (0, 2 pi) as well: 1e-15 rad there (a few ulps of pi), 1e-12
  // relative elsewhere. MERLIN2's arccosine is as accurate away from 0 and pi; within 1e-4
  // of them its error is bounded by eps / sin(theta) ~ 1e-16 / 1e-7 plus the rounding of
  // the cosine itself, sqrt(2 eps) ~ 2e-8: the tolerance there is 3e-8.
  const Vector3 a(0, 0, 0), b(0, 0, 1), c(1, 0, 0.3);
  for (double phi : {1e-7, 1e-3, 0.1, 1.0, kPi / 2, kPi - 1e-3, kPi - 1e-7, kPi, kPi + 1e-7,
                     kPi + 1e-3, 4.0, 6.0, 2 * kPi - 1e-3, 2 * kPi - 1e-7}) {
    const Vector3 d(std::cos(phi), std::sin(phi), 0.7);
    const double distance = std::min({phi, std::abs(phi - kPi), 2 * kPi - phi});
    EXPECT_NEAR(dihedral_angle(a, b, c, d), phi, distance < 1e-4 ? 1e-15 : 1e-12 * phi)
        << "phi = " << phi;
    EXPECT_NEAR(dihedral_angle(a, b, c, d, DihedralForm::Merlin2), phi,
                distance < 1e-4 ? 3e-8 : 1e-12)
        << "phi = " << phi;
  }
}

TEST(Dihedral, ExactNearFlatAtEveryScale) {
  // A flat hinge lifted by 1e-9 of its size at a wing: the angle is pi - 1e-9 to rounding
  // at 1 um, 1 mm and 1 m (the arccosine would give pi, or pi - ~1.5e-8, by rounding).
  for (double scale : {1e-3, 1.0, 1e3}) {
    const Vector3 a(0, 0, 0), b(0, scale, 0), c(scale, 0.3 * scale, 0);
    const double lift = 1e-9;
    const Vector3 d(-scale * std::cos(lift), 0.6 * scale, scale * std::sin(lift));
    // pi -+ 1e-9 (the side depends on the axis's direction): |theta - pi| to a few ulps of pi.
    EXPECT_NEAR(std::abs(dihedral_angle(a, b, c, d) - kPi), lift, 1e-15) << "scale " << scale;
  }
}

TEST(Dihedral, SideRuleFollowsMerlin) {
  // MERLIN2's form: within |n . r_ac| <= 1e-8 the angle is taken on the near side of pi
  // (docs/model.md, 'Hinges'). The exact form has no threshold: the side is the sine's sign.
  const Vector3 a(0, 0, 0), b(0, 0, 1), c(1, 0, 0.3);
  const double tiny = 1e-10;  // |n . r_ac| = sin(tiny) * |r_db_perp| * |r_ac_perp| ~ 1e-10
  const Vector3 d(std::cos(kPi + tiny), std::sin(kPi + tiny), 0.7);
  EXPECT_LE(dihedral_angle(a, b, c, d, DihedralForm::Merlin2), kPi);
  EXPECT_NEAR(dihedral_angle(a, b, c, d), kPi + tiny, 1e-15);
}

TEST(Dihedral, FormsAgreeAwayFromZeroAndPi) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 500; ++trial) {
    const auto x = random_hinge(rng, 1.0);
    const double exact = dihedral_angle(x[0], x[1], x[2], x[3]);
    const double merlin = dihedral_angle(x[0], x[1], x[2], x[3], DihedralForm::Merlin2);
    const double distance = std::min({exact, std::abs(exact - kPi), 2 * kPi - exact});
    // The arccosine's error is ~ eps / sin(theta) (relative to the angle's size, 1e-12).
    EXPECT_NEAR(exact, merlin, 1e-12 + 1e-15 / std::max(distance, 1e-12)) << "trial " << trial;
    EXPECT_GE(exact, 0.0);
    EXPECT_LT(exact, 2 * kPi);
  }
  EXPECT_THROW(dihedral_form(2, "form"), std::invalid_argument);
}

TEST(Dihedral, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(7);
  for (double scale : {1e-2, 1.0, 30.0}) {
    for (int trial = 0; trial < 200; ++trial) {
      const Vector12 x = stack(random_hinge(rng, scale));
      const Vector12 g = gradient_of(x);
      const Matrix12 H = dihedral_angle_hessian(unstack(x)[0], unstack(x)[1], unstack(x)[2],
                                                unstack(x)[3]);
      Vector12 g_fd;
      Matrix12 H_fd;
      const double h = kStep * scale;
      for (int k = 0; k < 12; ++k) {
        Vector12 xp = x, xm = x;
        xp[k] += h;
        xm[k] -= h;
        double dtheta = angle_of(xp) - angle_of(xm);
        // Stay on one branch across the 0 / 2 pi seam.
        if (dtheta > kPi) dtheta -= 2 * kPi;
        if (dtheta < -kPi) dtheta += 2 * kPi;
        g_fd[k] = dtheta / (2 * h);
        H_fd.col(k) = (gradient_of(xp) - gradient_of(xm)) / (2 * h);
      }
      EXPECT_LE((g - g_fd).norm(), kRelTol * g.norm()) << "scale " << scale;
      EXPECT_LE((H - H_fd).norm(), kRelTol * H.norm()) << "scale " << scale;
      EXPECT_LE((H - H.transpose()).norm(), 1e-12 * H.norm());
    }
  }
}

TEST(Dihedral, InvariantUnderRigidMotions) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    auto x = random_hinge(rng, 1.0);
    const Matrix3 Q = random_rotation(rng);
    const Vector3 t = random_point(rng, 5.0);
    std::array<Vector3, 4> y;
    for (int i = 0; i < 4; ++i) y[i] = Q * x[i] + t;
    const auto dx = dihedral_angle_derivatives(x[0], x[1], x[2], x[3]);
    const auto dy = dihedral_angle_derivatives(y[0], y[1], y[2], y[3]);
    EXPECT_NEAR(dx.angle, dy.angle, 1e-11);
    for (int i = 0; i < 4; ++i) {
      EXPECT_LE((Q * dx.gradient.segment<3>(3 * i) - dy.gradient.segment<3>(3 * i)).norm(),
                1e-10 * dx.gradient.norm());
    }
    // Translation: the four gradient blocks sum to zero, and so do the Hessian's block rows.
    Vector3 sum = Vector3::Zero();
    for (int i = 0; i < 4; ++i) sum += dx.gradient.segment<3>(3 * i);
    EXPECT_LE(sum.norm(), 1e-12 * dx.gradient.norm());
    Eigen::Matrix<double, 12, 3> row_sum = Eigen::Matrix<double, 12, 3>::Zero();
    for (int i = 0; i < 4; ++i) row_sum += dx.hessian.block<12, 3>(0, 3 * i);
    EXPECT_LE(row_sum.norm(), 1e-11 * dx.hessian.norm());
    // Rotation about the axis moves the angle by nothing: g . (omega x x) = 0.
    const Vector3 omega = random_point(rng);
    double rate = 0;
    for (int i = 0; i < 4; ++i) rate += dx.gradient.segment<3>(3 * i).dot(omega.cross(x[i]));
    EXPECT_NEAR(rate, 0.0, 1e-11 * dx.gradient.norm());
  }
}

TEST(Bar, StrainAndDerivatives) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 100; ++trial) {
    const Vector3 x1 = random_point(rng), x2 = random_point(rng);
    const double L = 0.5 + (x2 - x1).norm();
    const double l = (x2 - x1).norm();
    EXPECT_NEAR(bar_strain(x1, x2, L), (l * l - L * L) / (2 * L * L), 1e-15);
    const Vector6 g = bar_strain_gradient(x1, x2, L);
    for (int k = 0; k < 3; ++k) {
      Vector3 p = x2, q = x2;
      p[k] += kStep;
      q[k] -= kStep;
      EXPECT_NEAR(g[3 + k], (bar_strain(x1, p, L) - bar_strain(x1, q, L)) / (2 * kStep), 1e-8);
    }
  }
}

TEST(Bar, ForceAndStiffnessMatchFiniteDifferencesForBothLaws) {
  std::mt19937 rng(5);
  for (BarLawKind kind : {BarLawKind::Linear, BarLawKind::Ogden}) {
    const BarLaw law{kind, 4700.0};
    for (int trial = 0; trial < 100; ++trial) {
      Vector6 x;
      x << random_point(rng, 10.0), random_point(rng, 10.0);
      const double L = (x.tail<3>() - x.head<3>()).norm() * (0.8 + 0.4 * (trial % 5) / 4.0);
      const double area = 0.01 + trial * 0.01;
      auto at = [&](const Vector6& y) {
        return bar_response(y.head<3>(), y.tail<3>(), area, L, law);
      };
      const BarResponse r = at(x);
      const double h = kStep * 10.0;
      const auto [f_fd, K_fd] = test::energy_differences(at, x, h);
      // Near rest the force vanishes; the floor is the rounding of the energy differences,
      // relative to the force a perturbation h produces (|K| h).
      EXPECT_LE((r.force - f_fd).norm(), kRelTol * (r.force.norm() + r.stiffness.norm() * h));
      EXPECT_LE((r.stiffness - K_fd).norm(), kRelTol * r.stiffness.norm());
      EXPECT_LE((r.stiffness - r.stiffness.transpose()).norm(), 1e-12 * r.stiffness.norm());
    }
  }
}

TEST(Bar, NoForceAtRestAndObjective) {
  const BarLaw law{BarLawKind::Ogden, 4700.0};
  const Vector3 x1(1, 2, 3), x2(4, -2, 3);
  const BarResponse rest = bar_response(x1, x2, 1.0, 5.0, law);
  EXPECT_EQ(rest.energy, 0.0);
  EXPECT_LE(rest.force.norm(), 1e-12);
  // Small-strain modulus: axial stiffness EA/L at rest. The mode (-t, t) stretches the bar
  // by 2, so its quadratic form is 4 EA/L.
  const Vector3 axis = (x2 - x1) / 5.0;
  Vector6 mode;
  mode << -axis, axis;
  EXPECT_NEAR(mode.dot(rest.stiffness * mode), 4 * 4700.0 / 5.0, 1e-9);
  std::mt19937 rng(9);
  const Matrix3 Q = random_rotation(rng);
  const BarResponse r1 = bar_response(x1, 1.1 * x2, 1.0, 5.0, law);
  const BarResponse r2 = bar_response(Q * x1, Q * (1.1 * x2), 1.0, 5.0, law);
  EXPECT_NEAR(r1.energy, r2.energy, 1e-9 * r1.energy);
  EXPECT_LE((Q * r1.force.head<3>() - r2.force.head<3>()).norm(), 1e-9 * r1.force.norm());
}

TEST(Bar, OgdenLawClosedForms) {
  // W(s) integrates S dE: check dW/ds = S ds/dE^-1 = S s by differences, and W(1) = 0.
  for (double s : {0.3, 0.9, 1.0, 1.2, 2.5}) {
    const auto r = ogden_bar_law(100.0, s);
    const double h = 1e-6;
    const double dWds = (ogden_bar_law(100.0, s + h).energy_density -
                         ogden_bar_law(100.0, s - h).energy_density) / (2 * h);
    EXPECT_NEAR(dWds, r.stress * s, 1e-6 * std::max(1.0, std::abs(r.stress)));
    const double dSds =
        (ogden_bar_law(100.0, s + h).stress - ogden_bar_law(100.0, s - h).stress) / (2 * h);
    EXPECT_NEAR(dSds, r.modulus * s, 1e-6 * r.modulus);
  }
  EXPECT_EQ(ogden_bar_law(100.0, 1.0).energy_density, 0.0);
}

TEST(SpringLaws, EnhancedLinearIsSmoothAndConsistent) {
  const double t1 = 5.0 * kPi / 180, t2 = 355.0 * kPi / 180, t0 = 1.3, kp = 0.047;
  const SpringLaw law{SpringLawKind::EnhancedLinear, t1, t2};
  for (double t : {0.01, 0.05, t1 - 1e-9, t1 + 1e-9, 1.0, 3.0, t2 - 1e-9, t2 + 1e-9, 6.2}) {
    const auto r = law.evaluate(t, t0, kp);
    const double h = 1e-7;
    const auto p = law.evaluate(t + h, t0, kp), m = law.evaluate(t - h, t0, kp);
    EXPECT_NEAR((p.energy - m.energy) / (2 * h), r.moment, 1e-6 * std::max(1.0, std::abs(r.moment)))
        << t;
    EXPECT_NEAR((p.moment - m.moment) / (2 * h), r.stiffness, 1e-5 * r.stiffness) << t;
  }
  // Continuity at the limits; divergence as the hinge closes.
  EXPECT_NEAR(law.evaluate(t1 - 1e-12, t0, kp).moment, law.evaluate(t1 + 1e-12, t0, kp).moment,
              1e-12);
  EXPECT_GT(law.evaluate(1e-4, t0, kp).stiffness, 1e3 * kp);
  EXPECT_EQ(law.evaluate(2.0, 2.0, kp).energy, 0.0);
}

TEST(SpringLaws, SuperLinearBend) {
  const SpringLaw law{SpringLawKind::SuperLinearBend, 0, 0};
  const double kp = 2.0;
  for (double t : {2.0, 3.5, 4.0}) {
    const auto r = law.evaluate(t, 3.0, kp);
    const double d = t - 3.0;
    EXPECT_NEAR(r.moment, kp * std::copysign(std::pow(std::abs(d), 4.0 / 3.0), d), 1e-14);
    const double h = 1e-7;
    EXPECT_NEAR((law.evaluate(t + h, 3.0, kp).energy - law.evaluate(t - h, 3.0, kp).energy) /
                    (2 * h),
                r.moment, 1e-6);
  }
  EXPECT_EQ(law.evaluate(3.0, 3.0, kp).stiffness, 1e-3 * kp);  // the documented floor
}

TEST(Hinge, ForceAndStiffnessMatchFiniteDifferences) {
  std::mt19937 rng(13);
  const SpringLaw law{SpringLawKind::EnhancedLinear, 5 * kPi / 180, 355 * kPi / 180};
  for (int trial = 0; trial < 100; ++trial) {
    const Vector12 x = stack(random_hinge(rng, 20.0));
    auto at = [&](const Vector12& y) {
      const auto p = unstack(y);
      return hinge_response(p[0], p[1], p[2], p[3], 0.047, 2.0, 30.0, law);
    };
    const HingeResponse r = at(x);
    const auto [f_fd, K_fd] = test::energy_differences(at, x, kStep * 20.0);
    EXPECT_LE((r.force - f_fd).norm(), kRelTol * r.force.norm() + 1e-12);
    EXPECT_LE((r.stiffness - K_fd).norm(), kRelTol * r.stiffness.norm());
  }
}

TEST(Hinge, NoForceAtRestAngle) {
  const Vector3 a(0, 0, 0), b(0, 0, 2), c(1, 0, 0.3), d(std::cos(2.0), std::sin(2.0), 1.0);
  const SpringLaw law{SpringLawKind::Linear, 0, 0};
  const HingeResponse r = hinge_response(a, b, c, d, 0.047, 2.0, 2.0, law);
  EXPECT_NEAR(r.angle, 2.0, 1e-14);
  EXPECT_LE(r.force.norm(), 1e-14);
  EXPECT_LE(r.energy, 1e-28);
}
