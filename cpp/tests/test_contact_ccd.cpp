// Continuous collision detection: constructed crossings with known times, and random linear
// trajectories on which the reported time never passes a real crossing, found
// independently (sign changes of the coplanarity function, bisected, and dense sampling of
// the distance).

#include <functional>
#include <stdexcept>

#include <gtest/gtest.h>

#include "contact_test_helpers.hpp"
#include "kresling/contact/contact_ccd.hpp"
#include "kresling/contact/contact_distance.hpp"

using namespace kresling;
using namespace kresling::contact;
using namespace kresling::contact_test;

namespace {

const Vector3 kT0(0, 0, 0), kT1(1, 0, 0), kT2(0, 1, 0);

// Four nodes moving linearly from x0 to x1.
struct Trajectory {
  Vector12 x0, x1;
  Vector12 at(double t) const { return x0 + t * (x1 - x0); }
};

// Volume spanned by the four nodes: zero exactly when they are coplanar, which a point
// passing through a triangle, or an edge through an edge, must be at the crossing.
double coplanarity(const Vector12& y) {
  const auto v = unstack(y);
  return (v[1] - v[0]).dot((v[2] - v[0]).cross(v[3] - v[0]));
}

// The first time in [0, 1] at which the primitives touch (squared distance below 1e-18 at a
// root of the coplanarity function, bisected to 1e-14), or 2 if they never do.
double first_crossing(const Trajectory& path, const std::function<double(const Vector12&)>& d2) {
  const int n = 1000;
  double previous = coplanarity(path.at(0.0));
  for (int i = 1; i <= n; ++i) {
    double lo = (i - 1) / double(n), hi = i / double(n);
    const double current = coplanarity(path.at(hi));
    if ((previous <= 0) != (current <= 0)) {
      double f_lo = previous;
      while (hi - lo > 1e-14) {
        const double mid = 0.5 * (lo + hi);
        const double f_mid = coplanarity(path.at(mid));
        if ((f_lo <= 0) == (f_mid <= 0)) {
          lo = mid;
          f_lo = f_mid;
        } else {
          hi = mid;
        }
      }
      if (d2(path.at(hi)) < 1e-18) return lo;
    }
    previous = current;
  }
  return 2.0;
}

// The first sample time of 1000 at which the distance is at most xi (2 if none).
double first_sampled_contact(const Trajectory& path,
                             const std::function<double(const Vector12&)>& d2, double xi) {
  for (int i = 0; i <= 1000; ++i) {
    if (d2(path.at(i / 1000.0)) <= xi * xi) return i / 1000.0;
  }
  return 2.0;
}

TimeOfImpact pt_ccd(const Trajectory& p, const CcdOptions& o) {
  const auto a = unstack(p.x0), b = unstack(p.x1);
  return point_triangle_ccd(a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3], o);
}

TimeOfImpact ee_ccd(const Trajectory& p, const CcdOptions& o) {
  const auto a = unstack(p.x0), b = unstack(p.x1);
  return edge_edge_ccd(a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3], o);
}

}  // namespace

TEST(ContactCcd, FindsConstructedCrossings) {
  // A point dropping through a triangle's interior at t = 0.5, and with a minimum
  // separation of 0.1 (reached at t = 0.45). ACCD's first advance covers eta = 0.9 of the
  // gap and its stop rule keeps the state before the last advance: toi = 0.9 of the time
  // the separation is reached, for a head-on approach.
  const Vector3 p0(0.2, 0.2, 1), p1(0.2, 0.2, -1);
  for (double xi : {0.0, 0.1}) {
    CcdOptions o;
    o.min_distance = xi;
    const auto r = point_triangle_ccd(p0, kT0, kT1, kT2, p1, kT0, kT1, kT2, o);
    const double reach = (1 - xi) / 2;
    EXPECT_TRUE(r.impact);
    EXPECT_NEAR(r.toi, 0.9 * reach, 1e-12) << xi;
    // The same crossing seen from the triangle moving up through a fixed point: only the
    // relative motion counts.
    const Vector3 up(0, 0, 2);
    const auto q = point_triangle_ccd(p0, kT0, kT1, kT2, p0, kT0 + up, kT1 + up, kT2 + up, o);
    EXPECT_TRUE(q.impact);
    EXPECT_LT(q.toi, reach);
    EXPECT_GT(q.toi, 0.5 * reach);
  }
  // An edge sweeping down through another at t = 0.5.
  const Vector3 a0(0, 0, 0), a1(1, 0, 0), b0(0.5, -1, 1), b1(0.5, 1, 1), down(0, 0, -2);
  const auto e = edge_edge_ccd(a0, a1, b0, b1, a0, a1, b0 + down, b1 + down);
  EXPECT_TRUE(e.impact);
  EXPECT_LT(e.toi, 0.5);
  EXPECT_GT(e.toi, 0.25);
  // A point through a plane: eta times the exact time.
  CcdOptions o;
  o.min_distance = 0.2;
  const auto pl = point_plane_ccd(Vector3(3, 4, 1), Vector3(3, 4, -1), Vector3(0, 0, 0),
                                  Vector3(0, 0, 5), o);
  EXPECT_TRUE(pl.impact);
  EXPECT_NEAR(pl.toi, 0.9 * 0.4, 1e-15);
  // From below the plane: the point is kept below.
  const auto below = point_plane_ccd(Vector3(0, 0, -1), Vector3(0, 0, 1), Vector3(0, 0, 0),
                                     Vector3(0, 0, 1));
  EXPECT_TRUE(below.impact);
  EXPECT_NEAR(below.toi, 0.45, 1e-15);
}

TEST(ContactCcd, NoImpactWhenNothingCrosses) {
  const Vector3 p0(0.2, 0.2, 1), away(0.2, 0.2, 3);
  EXPECT_FALSE(point_triangle_ccd(p0, kT0, kT1, kT2, away, kT0, kT1, kT2).impact);
  // Sliding over the face at a constant height of 1e-3: many small advances (each 0.9 of
  // the gap over the closing-rate bound), then no impact.
  const auto slide = point_triangle_ccd(Vector3(0.1, 0.2, 1e-3), kT0, kT1, kT2,
                                        Vector3(0.7, 0.2, 1e-3), kT0, kT1, kT2);
  EXPECT_FALSE(slide.impact);
  EXPECT_EQ(slide.toi, 1.0);
  EXPECT_GT(slide.iterations, 100);
  EXPECT_LT(slide.iterations, 100000);
  // Approaching to a tenth of the starting gap without touching limits the step all the same
  // (ACCD's stop rule): the next step starts from the smaller gap.
  const auto skim = point_triangle_ccd(Vector3(-1, 0.2, 1e-3), kT0, kT1, kT2,
                                       Vector3(5, 0.2, 1e-3), kT0, kT1, kT2);
  EXPECT_TRUE(skim.impact);
  EXPECT_GT(skim.toi, 0.1);
  // Moving together: no relative motion.
  const Vector3 shift(10, -3, 7);
  const auto together =
      point_triangle_ccd(p0, kT0, kT1, kT2, p0 + shift, kT0 + shift, kT1 + shift, kT2 + shift);
  EXPECT_FALSE(together.impact);
  // A crossing after t_max is not reported; one at the start is, at 0.
  CcdOptions o;
  o.t_max = 0.4;
  const auto late = point_triangle_ccd(p0, kT0, kT1, kT2, Vector3(0.2, 0.2, -1), kT0, kT1, kT2, o);
  EXPECT_FALSE(late.impact);
  EXPECT_EQ(late.toi, 0.4);
  o = CcdOptions{};
  o.min_distance = 1.0;
  const auto start = point_triangle_ccd(p0, kT0, kT1, kT2, away, kT0, kT1, kT2, o);
  EXPECT_TRUE(start.impact);
  EXPECT_EQ(start.toi, 0.0);
}

TEST(ContactCcd, RandomTrajectoriesNeverPassACrossing) {
  std::mt19937 rng(41);
  int crossings = 0, near_misses = 0;
  for (double xi : {0.0, 1e-3, 0.05}) {
    CcdOptions o;
    o.min_distance = xi;
    for (int trial = 0; trial < 400; ++trial) {
      for (bool edges : {false, true}) {
        const std::function<double(const Vector12&)> d2 =
            edges ? edge_edge_distance2 : point_triangle_distance2;
        Trajectory path{stack(random_point(rng), random_point(rng), random_point(rng),
                              random_point(rng)),
                        stack(random_point(rng), random_point(rng), random_point(rng),
                              random_point(rng))};
        if (d2(path.x0) <= xi * xi) continue;
        const auto r = edges ? ee_ccd(path, o) : pt_ccd(path, o);
        const double cross = first_crossing(path, d2);
        const double contact = std::min(cross, first_sampled_contact(path, d2, xi));
        crossings += cross <= 1.0;
        near_misses += contact <= 1.0;
        if (contact <= 1.0) {
          EXPECT_TRUE(r.impact) << trial << (edges ? " edge-edge" : " point-triangle");
        }
        EXPECT_LE(r.toi, 1.0);
        if (contact <= 1.0) EXPECT_LT(r.toi, contact) << trial;
        // Every sample up to the reported time keeps the separation.
        for (int i = 0; i <= 200; ++i) {
          EXPECT_GT(d2(path.at(r.toi * i / 200.0)), xi * xi) << trial;
        }
      }
    }
  }
  // The test saw real crossings and contacts, not only misses.
  EXPECT_GT(crossings, 100);
  EXPECT_GT(near_misses, 200);
}

TEST(ContactCcd, OptionsAreChecked) {
  CcdOptions o;
  EXPECT_NO_THROW(check_ccd_options(o));
  o.min_distance = -1;
  EXPECT_THROW(check_ccd_options(o), std::invalid_argument);
  o = CcdOptions{};
  o.t_max = 0;
  EXPECT_THROW(check_ccd_options(o), std::invalid_argument);
  o = CcdOptions{};
  o.conservative_rescaling = 1.0;
  EXPECT_THROW(check_ccd_options(o), std::invalid_argument);
  o = CcdOptions{};
  o.max_iterations = 0;
  EXPECT_THROW(check_ccd_options(o), std::invalid_argument);
}
