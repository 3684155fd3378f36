#include "kresling/kinematics/constant_curvature.hpp"

#include <cmath>

#include "kresling/core/check.hpp"
#include "kresling/kinematics/series.hpp"

namespace kresling::kinematics {

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kSqrt3 = std::sqrt(3.0);

std::string triple(const Eigen::Vector3d& v) {
  return "(" + format_number(v[0]) + ", " + format_number(v[1]) + ", " + format_number(v[2]) +
         ")";
}

}  // namespace

void validate(const TendonLayout& layout) {
  require_positive("d", layout.radius);
  if (layout.segments < 1) throw_invalid("N", layout.segments, "an integer >= 1");
}

double tendon_angle(int i) { return 2.0 * kPi * i / 3.0; }

TendonDecomposition decompose_tendons(const Eigen::Vector3d& l, const TendonLayout& layout,
                                      const std::string& suffix) {
  validate(layout);
  for (int i = 0; i < 3; ++i) {
    // Checked inline so that the message (a string) is only built on failure: the inverse
    // kinematics calls this in its inner loop.
    if (!(std::isfinite(l[i]) && l[i] >= 0.0)) {
      require_positive("l" + std::to_string(i + 1) + suffix, l[i], /*allow_zero=*/true);
    }
  }
  if (l.sum() <= 0.0) {
    throw_invalid("l1 + l2 + l3" + suffix, l.sum(), "> 0 (at least one tendon of positive length)");
  }
  TendonDecomposition out;
  out.mean = l.sum() / 3.0;
  out.a = 0.5 * (l[1] + l[2] - 2.0 * l[0]);
  out.b = 0.5 * kSqrt3 * (l[1] - l[2]);
  // Q = l1^2 + l2^2 + l3^2 - l1 l2 - l2 l3 - l1 l3 = a^2 + b^2: a sum of squares of
  // differences, so it does not cancel near the straight case.
  const double scale = 3.0 * layout.segments * layout.radius;
  // (a^2 + b^2) / scale^2 as a sum of squared ratios: the plain form overflows to inf / inf
  // = NaN (and passed the check below) for lengths and radius near 1e154.
  const double ya = out.a / scale, yb = out.b / scale;
  out.y = ya * ya + yb * yb;
  if (!(out.y <= 1.0)) {
    throw_invalid("sqrt(Q) / (3 N d) for tendon lengths (l1, l2, l3)" + suffix + " = " + triple(l),
                  std::sqrt(out.y),
                  "<= 1: no constant-curvature arc with d = " + format_number(layout.radius) +
                      " mm, N = " + std::to_string(layout.segments) +
                      " realises these lengths (they differ too much)");
  }
  return out;
}

Eigen::Vector3d arc_from_tendons(const Eigen::Vector3d& lengths, const TendonLayout& layout,
                                 const std::string& suffix) {
  const TendonDecomposition t = decompose_tendons(lengths, layout, suffix);
  // Eqn 27: s = (sum l) N d / sqrt(Q) asin(sqrt(Q) / (3 N d)) = mean * asin(x) / x, x^2 = y.
  const double s = t.mean * asin_ratio_of_square(t.y);
  // Eqn 28: kappa = 2 sqrt(Q) / (d sum l); with the sum itself, not 3 mean: for subnormal
  // lengths (5e-324) the mean underflows to 0 and kappa came out inf.
  const double kappa = (2.0 * std::hypot(t.a, t.b) / lengths.sum()) / layout.radius;
  if (!std::isfinite(kappa) || !std::isfinite(s)) {
    throw_invalid("d", layout.radius,
                  "large enough for the arc of tendon lengths " + triple(lengths) + suffix +
                      " to be a finite number: its curvature 2 sqrt(Q) / (d (l1 + l2 + l3)) "
                      "overflows");
  }
  // Eqn 29 with atan2: tan(phi) = (sqrt(3)/3)(l3 + l2 - 2 l1) / (l2 - l3) = a / b.
  const double phi = std::atan2(t.a, t.b);
  return {s, kappa, phi};
}

Eigen::Vector3d tendons_from_arc(const Eigen::Vector3d& arc, const TendonLayout& layout,
                                 const std::string& suffix) {
  validate(layout);
  const double s = arc[0], kappa = arc[1], phi = arc[2];
  require_positive("s" + suffix, s, /*allow_zero=*/true);
  require_positive("kappa" + suffix, kappa, /*allow_zero=*/true);
  require_finite("phi" + suffix, phi);
  const int N = layout.segments;
  const double half_segment_angle = s * kappa / (2.0 * N);
  if (half_segment_angle > 0.5 * kPi) {
    throw_invalid("s kappa" + suffix, s * kappa,
                  "<= N pi = " + format_number(N * kPi) +
                      " (a larger bend is not on the branch eqn 27 inverts)");
  }
  // Chord of one tendon segment over the backbone's radius, times N:
  // 2 N sin(s kappa / 2N) / kappa = s sin(u) / u with u = s kappa / 2N; safe at kappa = 0.
  const double chord = s * sinc_of_square(half_segment_angle * half_segment_angle);
  Eigen::Vector3d l;
  for (int i = 0; i < 3; ++i) {
    const double offset = kappa * layout.radius * std::sin(phi - tendon_angle(i));
    if (offset > 1.0) {
      throw_invalid("kappa" + suffix, kappa,
                    "small enough that every tendon stays outside the centre of curvature: "
                    "kappa d sin(phi - sigma_" + std::to_string(i + 1) + ") = " +
                        format_number(offset) + " exceeds 1 at d = " +
                        format_number(layout.radius) + " mm, phi = " + format_number(phi));
    }
    l[i] = chord * (1.0 - offset);
  }
  return l;
}

}  // namespace kresling::kinematics
