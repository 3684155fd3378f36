// Contact distances against closed forms, dense sampling, finite differences and rigid
// motions (finite-difference tolerances: contact_test_helpers.hpp).

#include <gtest/gtest.h>

#include "contact_test_helpers.hpp"
#include "kresling/contact/contact_distance.hpp"
#include "kresling/contact/contact_mollifier.hpp"

using namespace kresling;
using namespace kresling::contact;
using namespace kresling::contact_test;

namespace {

using PT = PointTriangleDistanceType;
using EE = EdgeEdgeDistanceType;

const Vector3 kT0(0, 0, 0), kT1(1, 0, 0), kT2(0, 1, 0);

ScalarDerivatives<12> pt_of(const Vector12& v, PT type) {
  const auto x = unstack(v);
  return point_triangle_distance(x[0], x[1], x[2], x[3], type);
}

ScalarDerivatives<12> ee_of(const Vector12& v, EE type) {
  const auto x = unstack(v);
  return edge_edge_distance(x[0], x[1], x[2], x[3], type);
}

// A random pair whose closest features are of the given type (rejection sampling).
template <typename Type, typename Classify>
Vector12 random_pair_of_type(std::mt19937& rng, double scale, Type type, Classify&& classify) {
  for (;;) {
    const Vector12 v = stack(random_point(rng, 2 * scale), random_point(rng, scale),
                             random_point(rng, scale), random_point(rng, scale));
    const auto x = unstack(v);
    // Keep primitives well shaped so that the formulas are well conditioned.
    if ((x[2] - x[1]).cross(x[3] - x[1]).norm() < 0.2 * scale * scale) continue;
    if ((x[1] - x[0]).norm() < 0.2 * scale || (x[3] - x[2]).norm() < 0.2 * scale) continue;
    if (classify(x) == type) return v;
  }
}

void expect_derivatives_match(const ScalarDerivatives<12>& exact,
                              const ScalarDerivatives<12>& fd, const std::string& what) {
  EXPECT_LE(relative_error(exact.gradient, fd.gradient), kRelTol) << what;
  EXPECT_LE(relative_error(exact.hessian, fd.hessian), kRelTol) << what;
  EXPECT_LE((exact.hessian - exact.hessian.transpose()).norm(), 1e-12 * exact.hessian.norm())
      << what;
}

}  // namespace

TEST(ContactDistance, PointTriangleClosedForms) {
  struct Case {
    Vector3 p;
    PT type;
    double distance2;
  };
  const Case cases[] = {
      {{0.2, 0.3, 0.4}, PT::P_T, 0.16},
      {{0.2, 0.3, -0.4}, PT::P_T, 0.16},
      {{0.5, -0.7, 0.4}, PT::P_E0, 0.49 + 0.16},
      {{0.6, 0.6, 0.1}, PT::P_E1, 0.02 + 0.01},  // (0.2 / sqrt 2)^2 from x + y = 1
      {{-0.2, 0.5, 0.3}, PT::P_E2, 0.04 + 0.09},
      {{-0.3, -0.4, 0.5}, PT::P_T0, 0.09 + 0.16 + 0.25},
      {{1.5, -0.1, 0.2}, PT::P_T1, 0.25 + 0.01 + 0.04},
      {{-0.1, 1.4, 0.0}, PT::P_T2, 0.01 + 0.16},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(point_triangle_distance_type(c.p, kT0, kT1, kT2), c.type) << c.p.transpose();
    EXPECT_NEAR(point_triangle_distance(c.p, kT0, kT1, kT2).value, c.distance2, 1e-15)
        << c.p.transpose();
  }
}

TEST(ContactDistance, EdgeEdgeClosedForms) {
  const Vector3 a0(0, 0, 0), a1(1, 0, 0);
  const double h = 0.3;
  struct Case {
    Vector3 b0, b1;
    EE type;
    double distance2;
  };
  const Case cases[] = {
      {{0.5, -1, h}, {0.5, 1, h}, EE::EA_EB, h * h},
      {{1.5, -1, h}, {1.5, 1, h}, EE::EA1_EB, 0.25 + h * h},
      {{-0.5, 1, h}, {-0.5, -1, h}, EE::EA0_EB, 0.25 + h * h},
      {{2, 1, h}, {3, 2, h}, EE::EA1_EB0, 1 + 1 + h * h},
      {{-2, 1, h}, {-1, 1, h}, EE::EA0_EB1, 1 + 1 + h * h},
      {{0.5, 0.3, h}, {0.5, 2, h}, EE::EA_EB0, 0.09 + h * h},
      {{0.5, 2, h}, {0.5, 0.3, h}, EE::EA_EB1, 0.09 + h * h},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(edge_edge_distance_type(a0, a1, c.b0, c.b1), c.type) << c.b0.transpose();
    EXPECT_NEAR(edge_edge_distance(a0, a1, c.b0, c.b1).value, c.distance2, 1e-15)
        << c.b0.transpose();
  }
  // Parallel and nearly parallel overlapping edges at offset (0, 0.2, 0.1): the line-line
  // formula would divide 0 by 0; an end's distance is used, exact to rounding.
  for (double angle : {0.0, 1e-12, 1e-9, 1e-7}) {
    const Vector3 b0(0.5, 0.2, 0.1), b1 = b0 + Vector3(std::cos(angle), 0, std::sin(angle));
    const double d2 = edge_edge_distance(a0, a1, b0, b1).value;
    EXPECT_NEAR(d2, 0.05, 1e-6 * angle + 1e-15) << angle;
    EXPECT_NE(edge_edge_distance_type(a0, a1, b0, b1), EE::EA_EB) << angle;
  }
  // Zero-length edges reduce to point-edge and point-point.
  EXPECT_NEAR(edge_edge_distance(a0, a1, Vector3(0.5, 1, 0), Vector3(0.5, 1, 0)).value, 1.0,
              1e-15);
}

TEST(ContactDistance, SubKernelsClosedForms) {
  EXPECT_DOUBLE_EQ(point_point_distance(Vector3(1, 2, 3), Vector3(0, 0, 1)).value, 1 + 4 + 4);
  EXPECT_NEAR(point_line_distance(Vector3(3, 2, 1), Vector3(0, 0, 0), Vector3(2, 0, 0)).value,
              5.0, 1e-14);  // the line is x beyond the segment's end: still 4 + 1
  EXPECT_NEAR(point_edge_distance(Vector3(3, 2, 1), Vector3(0, 0, 0), Vector3(2, 0, 0)).value,
              6.0, 1e-14);  // the segment's end (2, 0, 0)
  EXPECT_EQ(point_edge_distance_type(Vector3(-1, 1, 0), Vector3(0, 0, 0), Vector3(2, 0, 0)),
            PointEdgeDistanceType::P_E0);
  const Vector3 origin(0, 0, 1), normal(0, 0, 2);  // any length
  EXPECT_DOUBLE_EQ(point_plane_signed_distance(Vector3(5, 1, 0.25), origin, normal), -0.75);
  const auto plane = point_rigid_plane_distance(Vector3(5, 1, 0.25), origin, normal);
  EXPECT_DOUBLE_EQ(plane.value, 0.5625);
  EXPECT_LE((plane.gradient - Vector3(0, 0, -1.5)).norm(), 1e-15);
  EXPECT_LE((plane.hessian - 2 * Vector3(0, 0, 1) * Vector3(0, 0, 1).transpose()).norm(), 1e-15);
}

TEST(ContactDistance, AutomaticDistanceIsTheMinimumOverDenseSamples) {
  // Independent of the classification: the distance is a minimum over the primitives'
  // points, so every sample is at least as far (up to rounding), and the nearest of a grid
  // of spacing delta (barycentric or along the edges) is within delta L of the true closest
  // point, so no further than (d + delta L)^2.
  std::mt19937 rng(21);
  const int n = 120;
  const double delta = 1.0 / n;
  for (int trial = 0; trial < 150; ++trial) {
    const Vector3 p = random_point(rng, 2), t0 = random_point(rng), t1 = random_point(rng),
                  t2 = random_point(rng);
    const double d2 = point_triangle_distance(p, t0, t1, t2).value;
    const double L = std::max({(t1 - t0).norm(), (t2 - t1).norm(), (t0 - t2).norm()});
    double best = 1e300;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const Vector3 q = t0 + (i * delta) * (t1 - t0) + (j * delta) * (t2 - t0);
        best = std::min(best, (p - q).squaredNorm());
      }
    }
    EXPECT_LE(d2, best + 1e-12) << trial;
    EXPECT_LE(best, std::pow(std::sqrt(d2) + delta * L, 2) + 1e-12) << trial;

    const Vector3 b0 = random_point(rng), b1 = random_point(rng);
    const double e2 = edge_edge_distance(p, t0, b0, b1).value;
    double best_e = 1e300;
    for (int i = 0; i <= 4 * n; ++i) {
      for (int j = 0; j <= 4 * n; ++j) {
        const Vector3 qa = p + (i * delta / 4) * (t0 - p), qb = b0 + (j * delta / 4) * (b1 - b0);
        best_e = std::min(best_e, (qa - qb).squaredNorm());
      }
    }
    const double Le = (t0 - p).norm() + (b1 - b0).norm();
    EXPECT_LE(e2, best_e + 1e-12) << trial;
    EXPECT_LE(best_e, std::pow(std::sqrt(e2) + delta / 4 * Le, 2) + 1e-12) << trial;
  }
}

TEST(ContactDistance, EveryPointTriangleTypeMatchesFiniteDifferences) {
  std::mt19937 rng(5);
  for (int code = 0; code <= static_cast<int>(PT::P_T); ++code) {
    const PT type = static_cast<PT>(code);
    for (double scale : {1e-2, 1.0, 30.0}) {
      for (int trial = 0; trial < 30; ++trial) {
        const Vector12 x = random_pair_of_type(rng, scale, type, [](const auto& y) {
          return point_triangle_distance_type(y[0], y[1], y[2], y[3]);
        });
        const auto f = [type](const Vector12& y) { return pt_of(y, type); };
        expect_derivatives_match(f(x), finite_differences<12>(f, x, kStep * scale),
                                 "type " + std::to_string(code));
      }
    }
  }
}

TEST(ContactDistance, EveryEdgeEdgeTypeMatchesFiniteDifferences) {
  std::mt19937 rng(6);
  for (int code = 0; code <= static_cast<int>(EE::EA_EB); ++code) {
    const EE type = static_cast<EE>(code);
    for (double scale : {1e-2, 1.0, 30.0}) {
      for (int trial = 0; trial < 30; ++trial) {
        const Vector12 x = random_pair_of_type(rng, scale, type, [](const auto& y) {
          return edge_edge_distance_type(y[0], y[1], y[2], y[3]);
        });
        const auto f = [type](const Vector12& y) { return ee_of(y, type); };
        expect_derivatives_match(f(x), finite_differences<12>(f, x, kStep * scale),
                                 "type " + std::to_string(code));
      }
    }
  }
}

TEST(ContactDistance, AutomaticGradientIsTheDerivativeOfTheDistance) {
  // Finite differences of the automatic distance's *value* (types chosen anew at each
  // sample): the chosen formula's gradient is the true function's, across all regions.
  std::mt19937 rng(8);
  for (int trial = 0; trial < 300; ++trial) {
    const Vector12 x = stack(random_point(rng, 2), random_point(rng), random_point(rng),
                             random_point(rng));
    const auto pt = [](const Vector12& y) {
      const auto v = unstack(y);
      return point_triangle_distance(v[0], v[1], v[2], v[3]);
    };
    const auto ee = [](const Vector12& y) {
      const auto v = unstack(y);
      return edge_edge_distance(v[0], v[1], v[2], v[3]);
    };
    EXPECT_LE(relative_error(pt(x).gradient, finite_differences<12>(pt, x, kStep).gradient),
              kRelTol);
    EXPECT_LE(relative_error(ee(x).gradient, finite_differences<12>(ee, x, kStep).gradient),
              kRelTol);
  }
}

TEST(ContactDistance, InvariantUnderRigidMotions) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<Vector3, 4> x = {random_point(rng, 2), random_point(rng),
                                      random_point(rng), random_point(rng)};
    const Matrix3 Q = random_rotation(rng);
    const Vector3 t = random_point(rng, 5.0);
    std::array<Vector3, 4> y;
    for (int i = 0; i < 4; ++i) y[i] = Q * x[i] + t;
    for (bool edges : {false, true}) {
      const auto dx = edges ? edge_edge_distance(x[0], x[1], x[2], x[3])
                            : point_triangle_distance(x[0], x[1], x[2], x[3]);
      const auto dy = edges ? edge_edge_distance(y[0], y[1], y[2], y[3])
                            : point_triangle_distance(y[0], y[1], y[2], y[3]);
      EXPECT_NEAR(dx.value, dy.value, 1e-12 * (1 + dx.value));
      Vector3 sum = Vector3::Zero();
      Eigen::Matrix<double, 12, 3> row_sum = Eigen::Matrix<double, 12, 3>::Zero();
      for (int i = 0; i < 4; ++i) {
        EXPECT_LE((Q * dx.gradient.segment<3>(3 * i) - dy.gradient.segment<3>(3 * i)).norm(),
                  1e-10 * dx.gradient.norm());
        sum += dx.gradient.segment<3>(3 * i);
        row_sum += dx.hessian.block<12, 3>(0, 3 * i);
      }
      // Translation changes nothing: gradient blocks and Hessian block rows sum to zero.
      EXPECT_LE(sum.norm(), 1e-12 * dx.gradient.norm());
      EXPECT_LE(row_sum.norm(), 1e-11 * dx.hessian.norm());
    }
  }
}

TEST(ContactDistance, MollifierMatchesFiniteDifferencesAndIsOneAboveItsThreshold) {
  std::mt19937 rng(10);
  int mollified = 0;
  for (int trial = 0; trial < 200; ++trial) {
    // Edges within a few degrees of parallel, so that x = |ua x ub|^2 falls below eps_x.
    const Vector3 a0 = random_point(rng), a1 = a0 + Vector3(1, 0, 0) + 0.03 * random_point(rng);
    const Vector3 b0 = random_point(rng), b1 = b0 + Vector3(1, 0, 0) + 0.03 * random_point(rng);
    const double eps_x = edge_edge_mollifier_threshold(a0, a1, b0, b1);
    const Vector12 x = stack(a0, a1, b0, b1);
    const auto f = [eps_x](const Vector12& y) {
      const auto v = unstack(y);
      return edge_edge_mollifier(v[0], v[1], v[2], v[3], eps_x);
    };
    const auto m = f(x);
    const double cross2 = cross_squared_norm(a1 - a0, b1 - b0).value;
    if (cross2 >= eps_x) {
      EXPECT_EQ(m.value, 1.0);
      EXPECT_EQ(m.gradient.norm(), 0.0);
      continue;
    }
    ++mollified;
    const double r = cross2 / eps_x;
    EXPECT_NEAR(m.value, (2 - r) * r, 1e-14);
    const auto fd = finite_differences<12>(f, x, kStep);
    EXPECT_LE(relative_error(m.gradient, fd.gradient), kRelTol);
    EXPECT_LE(relative_error(m.hessian, fd.hessian), kRelTol);
  }
  EXPECT_GT(mollified, 50);  // the test exercised the mollified branch
}
