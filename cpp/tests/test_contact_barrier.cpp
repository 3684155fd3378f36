// IPC's log barrier and the pair contact energies against closed forms and finite
// differences (tolerances: contact_test_helpers.hpp), the PSD projection, and the initial
// barrier stiffness.

#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "contact_test_helpers.hpp"
#include "kresling/contact/contact_barrier.hpp"
#include "kresling/contact/contact_barrier_stiffness.hpp"
#include "kresling/contact/contact_mollifier.hpp"

using namespace kresling;
using namespace kresling::contact;
using namespace kresling::contact_test;

namespace {

// A random 12-coordinate pair whose squared distance (by `distance2`) lies in
// (0.05, 0.9) d_hat^2, where the barrier is active and its derivatives are moderate.
template <typename Distance2>
Vector12 random_active_pair(std::mt19937& rng, double d_hat, Distance2&& distance2) {
  for (;;) {
    const Vector12 x = stack(random_point(rng), random_point(rng), random_point(rng),
                             random_point(rng));
    const double s = distance2(x) / (d_hat * d_hat);
    if (s > 0.05 && s < 0.9) return x;
  }
}

}  // namespace

TEST(ContactBarrier, LogBarrierClosedFormAndDerivatives) {
  const double s_hat = 0.25;
  // b(s_hat / e) = s_hat^2 (1 - 1/e)^2, since ln(1/e) = -1.
  const double e = std::exp(1.0);
  EXPECT_NEAR(log_barrier(s_hat / e, s_hat).value, s_hat * s_hat * std::pow(1 - 1 / e, 2),
              1e-16);
  for (double s : {s_hat, 2 * s_hat}) {
    const auto b = log_barrier(s, s_hat);
    EXPECT_EQ(b.value, 0.0);
    EXPECT_EQ(b.first, 0.0);
    EXPECT_EQ(b.second, 0.0);
  }
  // b, b', b'' all vanish at s_hat (C2 where a pair leaves the range): with delta = 1 - s /
  // s_hat, b ~ s_hat^2 delta^3, b' ~ -3 s_hat delta^2, b'' ~ 6 delta; bounds at twice that.
  const double delta = 1e-6;
  const auto near = log_barrier(s_hat * (1 - delta), s_hat);
  EXPECT_LT(std::abs(near.value), 2 * s_hat * s_hat * std::pow(delta, 3));
  EXPECT_LT(std::abs(near.first), 6 * s_hat * delta * delta);
  EXPECT_LT(std::abs(near.second), 12 * delta);
  EXPECT_TRUE(std::isinf(log_barrier(0.0, s_hat).value));
  // Derivatives in s by central differences (h = 1e-7 s_hat; relative 1e-6 as for the
  // kernels: the barrier is smooth on (0, s_hat)).
  for (double ratio : {0.01, 0.1, 0.3, 0.6, 0.95}) {
    const double s = ratio * s_hat, h = 1e-7 * s_hat;
    const auto b = log_barrier(s, s_hat);
    const auto bp = log_barrier(s + h, s_hat), bm = log_barrier(s - h, s_hat);
    EXPECT_GT(b.value, 0.0);
    EXPECT_LT(b.first, 0.0);
    EXPECT_GT(b.second, 0.0);
    EXPECT_NEAR(b.first, (bp.value - bm.value) / (2 * h), 1e-6 * std::abs(b.first)) << ratio;
    EXPECT_NEAR(b.second, (bp.first - bm.first) / (2 * h), 1e-6 * std::abs(b.second)) << ratio;
  }
}

TEST(ContactBarrier, PairEnergiesMatchFiniteDifferences) {
  std::mt19937 rng(31);
  const double d_hat = 0.3, kappa = 7.0;
  int mollified = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vector12 x_pt = random_active_pair(rng, d_hat, point_triangle_distance2);
    const auto pt = [&](const Vector12& y) {
      const auto v = unstack(y);
      return point_triangle_barrier(v[0], v[1], v[2], v[3], d_hat, kappa);
    };
    const auto e_pt = pt(x_pt), fd_pt = finite_differences<12>(pt, x_pt, kStep);
    EXPECT_LE(relative_error(e_pt.gradient, fd_pt.gradient), kRelTol) << trial;
    EXPECT_LE(relative_error(e_pt.hessian, fd_pt.hessian), kRelTol) << trial;
    // The value is kappa b(s) of the distance kernel.
    const double s_pt = point_triangle_distance2(x_pt);
    EXPECT_NEAR(e_pt.value, kappa * log_barrier(s_pt, d_hat * d_hat).value,
                1e-14 * e_pt.value);

    // Edge-edge with a threshold large enough that about half the pairs are mollified.
    const Vector12 x_ee = random_active_pair(rng, d_hat, edge_edge_distance2);
    const auto v = unstack(x_ee);
    const double eps_x = alternating_mollifier_threshold(v, trial);
    mollified += cross_squared_norm(v[1] - v[0], v[3] - v[2]).value < eps_x;
    const auto ee = [&](const Vector12& y) {
      const auto w = unstack(y);
      return edge_edge_barrier(w[0], w[1], w[2], w[3], eps_x, d_hat, kappa);
    };
    expect_derivatives_match<12>(ee, x_ee, trial);
  }
  EXPECT_EQ(mollified, 100);
}

TEST(ContactBarrier, PointPlaneBarrierMatchesFiniteDifferences) {
  std::mt19937 rng(32);
  const Vector3 origin(0.1, -0.2, 0.3), normal = Vector3(1, 2, 2);  // |n| = 3
  const double d_hat = 0.5, kappa = 2.0;
  for (int trial = 0; trial < 100; ++trial) {
    const double gap = (trial % 2 ? 1 : -1) * (0.05 + 0.4 * (trial % 10) / 10.0);
    const Vector3 p = origin + random_point(rng).cross(normal) + gap * normal / 3.0;
    const auto f = [&](const Vector3& y) {
      return point_plane_barrier(y, origin, normal, d_hat, kappa);
    };
    const auto e = f(p);
    EXPECT_NEAR(e.value, kappa * log_barrier(gap * gap, d_hat * d_hat).value, 1e-12 * e.value);
    const auto fd = finite_differences<3>(f, p, kStep);
    EXPECT_LE(relative_error(e.gradient, fd.gradient), kRelTol);
    EXPECT_LE(relative_error(e.hessian, fd.hessian), kRelTol);
    // The force pushes the point away from the plane, on whichever side it is.
    EXPECT_GT(-e.gradient.dot(normal) * gap, 0.0);
  }
}

TEST(ContactBarrier, NothingBeyondTheRangeAndInfiniteAtContact) {
  const Vector3 t0(0, 0, 0), t1(1, 0, 0), t2(0, 1, 0);
  const auto far = point_triangle_barrier(Vector3(0.2, 0.2, 0.5), t0, t1, t2, 0.5, 3.0);
  EXPECT_EQ(far.value, 0.0);
  EXPECT_EQ(far.gradient.norm(), 0.0);
  EXPECT_EQ(far.hessian.norm(), 0.0);
  const auto touching = point_triangle_barrier(Vector3(0.2, 0.2, 0.0), t0, t1, t2, 0.5, 3.0);
  EXPECT_TRUE(std::isinf(touching.value));
  EXPECT_TRUE(touching.gradient.allFinite());
}

TEST(ContactBarrier, ProjectionIsTheNearestPositiveSemiDefiniteMatrix) {
  std::mt19937 rng(33);
  const double d_hat = 0.3;
  int indefinite = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const Vector12 x = random_active_pair(rng, d_hat, point_triangle_distance2);
    const auto v = unstack(x);
    const auto exact = point_triangle_barrier(v[0], v[1], v[2], v[3], d_hat, 1.0);
    const auto projected = point_triangle_barrier(v[0], v[1], v[2], v[3], d_hat, 1.0,
                                                  BarrierHessian::Projected);
    EXPECT_EQ(projected.value, exact.value);
    EXPECT_EQ(projected.gradient, exact.gradient);
    const Matrix12& H = exact.hessian;
    const Matrix12& P = projected.hessian;
    const double scale = H.norm();
    const Eigen::SelfAdjointEigenSolver<Matrix12> eig_h(H), eig_p(P), eig_d(P - H);
    indefinite += eig_h.eigenvalues().minCoeff() < -1e-9 * scale;
    // P is PSD, P - H is PSD (only negative curvature was removed) and P (P - H) = 0 (what
    // was removed is orthogonal to what was kept): together, P is H's nearest PSD matrix.
    EXPECT_GE(eig_p.eigenvalues().minCoeff(), -1e-12 * scale);
    EXPECT_GE(eig_d.eigenvalues().minCoeff(), -1e-12 * scale);
    EXPECT_LE((P * (P - H)).norm(), 1e-12 * scale * scale);
    EXPECT_LE((project_to_psd<12>(P) - P).norm(), 1e-12 * scale);  // idempotent
  }
  EXPECT_GT(indefinite, 10);  // the exact Hessians were not all PSD already
}

TEST(ContactBarrier, InitialStiffnessFollowsIpcsRule) {
  const double diagonal = 100.0, d_hat = 0.5, mass = 2.0;
  const double s0 = std::pow(1e-8 * diagonal, 2), s_hat = d_hat * d_hat;
  const double b2 = std::pow(s_hat / s0, 2) + 2 * s_hat / s0 - 2 * std::log(s0 / s_hat) - 3;
  const double kappa_min = 1e11 * mass / (4 * s0 * b2);
  VectorX grad_b(4), grad_e(4);
  grad_b << 1, -2, 0, 2;  // |grad B|^2 = 9
  // E's gradient along B's: kappa = -(grad B . grad E) / |grad B|^2.
  const double wanted = 37 * kappa_min;
  grad_e = -wanted * grad_b;
  grad_e[2] = 5.0;  // orthogonal to grad B: no effect
  auto k = initial_barrier_stiffness(diagonal, d_hat, mass, grad_e, grad_b);
  EXPECT_NEAR(k.min_stiffness, kappa_min, 1e-12 * kappa_min);
  EXPECT_NEAR(k.max_stiffness, 100 * kappa_min, 1e-10 * kappa_min);
  EXPECT_NEAR(k.stiffness, wanted, 1e-12 * wanted);
  // Clamped to its bounds; 1 without any barrier gradient (kappa_min = 0.8 < 1 here).
  EXPECT_EQ(initial_barrier_stiffness(diagonal, d_hat, mass, -grad_e, grad_b).stiffness,
            k.min_stiffness);
  EXPECT_EQ(initial_barrier_stiffness(diagonal, d_hat, mass, 1e3 * grad_e, grad_b).stiffness,
            k.max_stiffness);
  ASSERT_LT(k.min_stiffness, 1.0);
  EXPECT_EQ(initial_barrier_stiffness(diagonal, d_hat, mass, grad_e, VectorX::Zero(4)).stiffness,
            1.0);
  EXPECT_THROW(initial_barrier_stiffness(0.0, d_hat, mass, grad_e, grad_b), std::invalid_argument);
  EXPECT_THROW(initial_barrier_stiffness(diagonal, -1, mass, grad_e, grad_b),
               std::invalid_argument);
  EXPECT_THROW(initial_barrier_stiffness(diagonal, d_hat, mass, grad_e, VectorX::Zero(3)),
               std::invalid_argument);
  EXPECT_THROW(check_barrier_parameters(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(check_barrier_parameters(1.0, -1.0), std::invalid_argument);
}
