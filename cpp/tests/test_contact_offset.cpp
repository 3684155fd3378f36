// The barrier between offset surfaces (panels of a thickness, contact/contact_offset.hpp):
// the squared gap (d - t)^2 and the pair energies on it against closed forms and central
// differences (tolerances: contact_test_helpers.hpp; the gaps used, 0.05 to 0.9 of d_hat
// beyond offsets of 0.1 to 2 d_hat, keep the barrier's derivatives moderate as there), and
// the offset's edges: none at t = 0, not admissible at d <= t, nothing beyond t + d_hat.

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "contact_test_helpers.hpp"
#include "kresling/contact/contact_barrier.hpp"
#include "kresling/contact/contact_mollifier.hpp"
#include "kresling/contact/contact_offset.hpp"

using namespace kresling;
using namespace kresling::contact;
using namespace kresling::contact_test;

namespace {

// A random pair (by `distance2`) and an offset t such that the gap d - t lies in
// (0.05, 0.9) d_hat: the offset barrier acts there, with moderate derivatives.
template <typename Distance2>
std::pair<Vector12, double> random_offset_pair(std::mt19937& rng, double d_hat,
                                               Distance2&& distance2) {
  std::uniform_real_distribution<double> share(0.05, 0.9);
  for (;;) {
    const Vector12 x = stack(random_point(rng), random_point(rng), random_point(rng),
                             random_point(rng));
    const double t = std::sqrt(distance2(x)) - share(rng) * d_hat;
    if (t > 0.1 * d_hat && t < 2.0 * d_hat) return {x, t};
  }
}

}  // namespace

TEST(ContactOffset, SquaredGapIsTheChainRuleOfTheSquaredDistance) {
  // s_o = (sqrt(s) - t)^2 of the point-triangle distance: its value by the closed form,
  // its gradient and Hessian by central differences of s_o itself (not of the formula).
  std::mt19937 rng(41);
  for (int trial = 0; trial < 200; ++trial) {
    const Vector12 x = stack(random_point(rng), random_point(rng), random_point(rng),
                             random_point(rng));
    const double d = std::sqrt(point_triangle_distance2(x));
    const double t = std::uniform_real_distribution<double>(0.05, 0.9)(rng) * d;
    const auto f = [&](const Vector12& y) {
      const auto v = unstack(y);
      return offset_squared_distance<12>(point_triangle_distance(v[0], v[1], v[2], v[3]), t);
    };
    EXPECT_NEAR(f(x).value, (d - t) * (d - t), 1e-14 * d * d) << trial;
    expect_derivatives_match<12>(f, x, trial);
  }
}

TEST(ContactOffset, OffsetPairEnergiesMatchFiniteDifferences) {
  std::mt19937 rng(42);
  const double d_hat = 0.3, kappa = 7.0;
  int mollified = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const auto [x_pt, t_pt] = random_offset_pair(rng, d_hat, point_triangle_distance2);
    const auto pt = [&, t = t_pt](const Vector12& y) {
      const auto v = unstack(y);
      return point_triangle_barrier(v[0], v[1], v[2], v[3], d_hat, kappa,
                                    BarrierHessian::Exact, t);
    };
    expect_derivatives_match<12>(pt, x_pt, trial);
    // The value is kappa b((d - t)^2): the log barrier of the gap beyond the offset.
    const double gap = std::sqrt(point_triangle_distance2(x_pt)) - t_pt;
    EXPECT_NEAR(pt(x_pt).value, kappa * log_barrier(gap * gap, d_hat * d_hat).value,
                1e-12 * pt(x_pt).value);

    // Edge-edge, about half the pairs mollified (the mollifier multiplies the offset
    // barrier as it does the plain one).
    const auto [x_ee, t_ee] = random_offset_pair(rng, d_hat, edge_edge_distance2);
    const auto v = unstack(x_ee);
    const double eps_x = alternating_mollifier_threshold(v, trial);
    mollified += cross_squared_norm(v[1] - v[0], v[3] - v[2]).value < eps_x;
    const auto ee = [&, t = t_ee](const Vector12& y) {
      const auto w = unstack(y);
      return edge_edge_barrier(w[0], w[1], w[2], w[3], eps_x, d_hat, kappa,
                               BarrierHessian::Exact, t);
    };
    expect_derivatives_match<12>(ee, x_ee, trial);
  }
  EXPECT_EQ(mollified, 100);
}

TEST(ContactOffset, PointPlaneBarrierActsOnTheDistanceLessTheOffset) {
  std::mt19937 rng(43);
  const Vector3 origin(0.1, -0.2, 0.3), normal = Vector3(1, 2, 2);  // |n| = 3
  const double d_hat = 0.5, kappa = 2.0, offset = 0.35;
  for (int trial = 0; trial < 100; ++trial) {
    const double gap = 0.05 + 0.4 * (trial % 10) / 10.0;  // beyond the offset
    const double side = trial % 2 ? 1.0 : -1.0;
    const Vector3 p =
        origin + random_point(rng).cross(normal) + side * (offset + gap) * normal / 3.0;
    const auto f = [&](const Vector3& y) {
      return point_plane_barrier(y, origin, normal, d_hat, kappa, BarrierHessian::Exact,
                                 offset);
    };
    const auto e = f(p);
    EXPECT_NEAR(e.value, kappa * log_barrier(gap * gap, d_hat * d_hat).value, 1e-10 * e.value);
    expect_derivatives_match<3>(f, p, trial);
    EXPECT_GT(-e.gradient.dot(normal) * side, 0.0);  // pushes the point off the plane
  }
}

TEST(ContactOffset, NoOffsetIsTheDistanceItselfToTheBit) {
  std::mt19937 rng(44);
  for (int trial = 0; trial < 50; ++trial) {
    const auto v = unstack(stack(random_point(rng), random_point(rng), random_point(rng),
                                 random_point(rng)));
    const auto s = point_triangle_distance(v[0], v[1], v[2], v[3]);
    const auto o = offset_squared_distance<12>(s, 0.0);
    EXPECT_EQ(o.value, s.value);
    EXPECT_EQ(o.gradient, s.gradient);
    EXPECT_EQ(o.hessian, s.hessian);
    const double d_hat = 2.0 * std::sqrt(s.value);  // active
    const auto plain = edge_edge_barrier(v[0], v[1], v[2], v[3], 1e-3, d_hat, 3.0);
    const auto zero = edge_edge_barrier(v[0], v[1], v[2], v[3], 1e-3, d_hat, 3.0,
                                        BarrierHessian::Exact, 0.0);
    EXPECT_EQ(plain.value, zero.value);
    EXPECT_EQ(plain.gradient, zero.gradient);
    EXPECT_EQ(plain.hessian, zero.hessian);
  }
}

TEST(ContactOffset, RangeStartsAtTheOffsetAndEndsDHatBeyondIt) {
  // A point 1 mm over a triangle's face, offsets around it (d_hat 0.5).
  const Vector3 t0(0, 0, 0), t1(4, 0, 0), t2(0, 4, 0), p(1, 1, 1);
  const double d_hat = 0.5;
  auto energy = [&](double offset) {
    return point_triangle_barrier(p, t0, t1, t2, d_hat, 3.0, BarrierHessian::Exact, offset);
  };
  // Beyond t + d_hat (t = 0.5, 0.4): nothing.
  for (double offset : {0.5, 0.4}) {
    const auto e = energy(offset);
    EXPECT_EQ(e.value, 0.0);
    EXPECT_EQ(e.gradient.norm(), 0.0);
    EXPECT_EQ(e.hessian.norm(), 0.0);
  }
  EXPECT_GT(energy(0.6).value, 0.0);  // within: the barrier acts
  EXPECT_GT(energy(0.999).value, energy(0.9).value);  // and grows as the faces approach
  // Faces touching (t = d) or overlapping (t > d): not admissible, for every kind of pair.
  for (double offset : {1.0, 1.5}) {
    EXPECT_TRUE(std::isinf(energy(offset).value));
    EXPECT_TRUE(energy(offset).gradient.allFinite());
    EXPECT_TRUE(std::isinf(
        point_plane_barrier(p, t0, Vector3::UnitZ(), d_hat, 3.0, BarrierHessian::Exact, offset)
            .value));
    EXPECT_TRUE(std::isinf(edge_edge_barrier(p, p - Vector3(0, 2, 0), t0, t1, 1e-3, d_hat, 3.0,
                                             BarrierHessian::Exact, offset)
                               .value));
  }
}
