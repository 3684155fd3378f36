#include "kresling/geometry/design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kresling/core/check.hpp"

namespace kresling::geometry {

namespace {

constexpr double kPi = 3.14159265358979323846;

// L(alpha)^2 of eqn 8, written with the cosine difference as a product of sines so that it
// stays accurate near alpha0 (where the plain difference cancels).
double height_squared(const DesignParameters& p, const DerivedQuantities& d, double alpha) {
  const double a = alpha + 2.0 * d.phi;
  const double a0 = d.alpha0 + 2.0 * d.phi;
  const double cos_difference = -2.0 * std::sin(0.5 * (a + a0)) * std::sin(0.5 * (a - a0));
  return p.Lc * p.Lc + 2.0 * p.R * p.R * cos_difference;
}

// Dihedral along the bottom edge b0-b1 between the base polygon (towards its centre) and the
// triangle [b0, b1, t1]; both polygons are centred on the z axis.
double facet_angle(double R, double phi, double alpha, double L) {
  const Eigen::Vector3d b0(R, 0.0, 0.0);
  const Eigen::Vector3d b1(R * std::cos(2 * phi), R * std::sin(2 * phi), 0.0);
  const Eigen::Vector3d t1(R * std::cos(2 * phi + alpha), R * std::sin(2 * phi + alpha), L);
  const Eigen::Vector3d edge = (b1 - b0).normalized();
  const Eigen::Vector3d inward = -(b0 + b1).normalized();  // in the polygon's plane
  Eigen::Vector3d wing = t1 - b0;
  wing -= wing.dot(edge) * edge;  // component perpendicular to the hinge axis
  return std::atan2(wing.z(), wing.dot(inward));
}

}  // namespace

void validate(const DesignParameters& p, const std::string& suffix) {
  if (p.n < 3) throw_invalid("n" + suffix, p.n, "an integer >= 3");
  require_positive("R" + suffix, p.R);
  require_open_interval("lam" + suffix, p.lam, 0.5, 1.0);
  require_positive("Lc" + suffix, p.Lc, /*allow_zero=*/true);
  if (p.chirality != 1 && p.chirality != -1) {
    throw_invalid("chirality" + suffix, p.chirality, "+1 or -1");
  }
}

DerivedQuantities derive(const DesignParameters& p) {
  DerivedQuantities d;
  const double n = p.n, R = p.R, lam = p.lam, Lc = p.Lc;
  d.phi = kPi / n;
  d.gamma = kPi * (n - 2.0) / (2.0 * n);
  d.P = 2.0 * R * std::sin(kPi / n);
  d.V = 2.0 * R * std::cos(d.gamma * (1.0 - lam));
  d.M = std::sqrt(d.V * d.V + d.P * d.P - 2.0 * d.V * d.P * std::cos(lam * d.gamma));
  d.Vg = std::hypot(d.V, Lc);
  d.Mg = std::hypot(d.M, Lc);
  // Clamped: rounding can push the cosine a few ulps past +-1 in degenerate facets.
  d.theta_g = std::acos(std::clamp((d.P * d.P + d.Vg * d.Vg - d.Mg * d.Mg) / (2.0 * d.P * d.Vg),
                                   -1.0, 1.0));
  d.alpha0 = 2.0 * lam * d.gamma;
  // pi - alpha0 - 2 phi, written as 2 gamma (1 - lam) (pi - 2 phi = 2 gamma): the plain
  // difference cancels to exactly 0 as lam -> 1 (Design(28, 1 - 2^-52, 0, 1)), where this
  // is positive for every lam < 1 (1 - lam is exact for lam >= 0.5) and accurate.
  d.alpha_e = 2.0 * d.gamma * (1.0 - lam);
  // Le^2 = Lc^2 - 2 R^2 (cos a0 + cos(a0 + 2 phi)) = Lc^2 - 4 R^2 cos(a0 + phi) cos(phi)
  //      = Lc^2 + 4 R^2 sin(gamma (2 lam - 1)) cos(phi),
  // since a0 + phi - pi/2 = gamma (2 lam - 1). The last form is a sum of non-negative terms
  // (Le > Lc whenever lam > 0.5) and stays accurate as lam -> 0.5 with Lc = 0, where the
  // first form cancels to a rounding error of either sign.
  d.Le = std::sqrt(Lc * Lc +
                   4.0 * R * R * std::sin(d.gamma * (2.0 * lam - 1.0)) * std::cos(d.phi));
  d.psi_con = facet_angle(R, d.phi, d.alpha0, Lc);
  d.psi_ext = facet_angle(R, d.phi, d.alpha_e, d.Le);
  return d;
}

std::array<double, kDerivedNames.size()> derived_as_array(const DerivedQuantities& d) {
  return {d.phi, d.gamma,  d.P,       d.V,  d.M,       d.Vg,     d.Mg,
          d.theta_g, d.alpha0, d.alpha_e, d.Le, d.psi_con, d.psi_ext};
}

Design::Design(int n, double R, double lam, double Lc, int chirality)
    : Design(DesignParameters{n, R, lam, Lc, chirality}) {}

Design::Design(const DesignParameters& p) : p_(p) {
  validate(p_);
  d_ = derive(p_);
}

double Design::twist(State state) const {
  return state == State::Extended ? d_.alpha_e : d_.alpha0;
}

double Design::height(State state) const {
  return state == State::Extended ? d_.Le : p_.Lc;
}

double Design::height_at(double alpha) const {
  require_finite("alpha", alpha);
  double L2 = height_squared(p_, d_, alpha);
  // A flat state (L = 0) evaluates to a rounding error of either sign: accept it as 0.
  const double rounding = 64.0 * std::numeric_limits<double>::epsilon() *
                          (p_.R * p_.R + p_.Lc * p_.Lc);
  if (L2 < 0.0 && L2 >= -rounding) L2 = 0.0;
  if (L2 < 0.0) {
    throw_invalid("alpha", alpha,
                  "a twist the valley creases can reach (L(alpha)^2 = " + format_number(L2) +
                      " < 0 there)");
  }
  return std::sqrt(L2);
}

double Design::mountain_length_at(double alpha) const {
  const double L = height_at(alpha);
  // 2 R^2 (1 - cos alpha) = (2 R sin(alpha/2))^2, without cancellation at small alpha.
  return std::hypot(2.0 * p_.R * std::sin(0.5 * alpha), L);
}

double Design::facet_angle_at(double alpha) const {
  return facet_angle(p_.R, d_.phi, alpha, height_at(alpha));
}

}  // namespace kresling::geometry
