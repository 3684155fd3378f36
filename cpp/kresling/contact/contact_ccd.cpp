// Continuous collision detection along a linear step (contact_ccd.hpp).

#include "kresling/contact/contact_ccd.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "kresling/core/check.hpp"
#include "kresling/contact/contact_distance.hpp"

namespace kresling::contact {

namespace {

// Additive CCD on four nodes x (12 coordinates) moving by dx, the first `side_a` of them on
// one primitive. `distance2` is the pair's squared distance.
template <typename Distance2>
TimeOfImpact additive_ccd(Vector12 x, Vector12 dx, int side_a, Distance2&& distance2,
                          const CcdOptions& options) {
  TimeOfImpact out;
  out.toi = options.t_max;
  const double xi = options.min_distance, eta = options.conservative_rescaling;
  // The mean displacement moves both primitives alike and changes no distance.
  Vector3 mean = Vector3::Zero();
  for (int i = 0; i < 4; ++i) mean += dx.segment<3>(3 * i) / 4.0;
  double max_a = 0.0, max_b = 0.0;
  for (int i = 0; i < 4; ++i) {
    dx.segment<3>(3 * i) -= mean;
    double& side = i < side_a ? max_a : max_b;
    side = std::max(side, dx.segment<3>(3 * i).norm());
  }
  const double l_p = max_a + max_b;  // bound on the rate at which the gap closes
  // d - xi written as (d^2 - xi^2) / (d + xi), which keeps its digits when d ~ xi.
  auto excess = [xi](double d2) { return (d2 - xi * xi) / (std::sqrt(d2) + xi); };
  double gap_now = excess(distance2(x));
  if (!(gap_now > 0)) return {true, 0.0, 0};
  if (l_p == 0) return out;
  const double stop = (1 - eta) * gap_now;
  double t = 0.0;
  for (;;) {
    if (out.iterations == options.max_iterations) return {true, t, out.iterations};
    const double t_l = eta * gap_now / l_p;
    x += t_l * dx;
    ++out.iterations;
    gap_now = excess(distance2(x));
    if (t > 0 && gap_now < stop) return {true, t, out.iterations};
    t += t_l;
    if (t >= options.t_max) return out;
  }
}

// ACCD for the pair of four nodes moving linearly from `start` to `end`, the first `side_a`
// on one primitive, with squared distance distance2(a, b, c, d).
template <typename Distance2>
TimeOfImpact four_node_ccd(const std::array<const Vector3*, 4>& start,
                           const std::array<const Vector3*, 4>& end, int side_a,
                           Distance2&& distance2, const CcdOptions& options) {
  Vector12 x, dx;
  for (int i = 0; i < 4; ++i) {
    x.segment<3>(3 * i) = *start[static_cast<std::size_t>(i)];
    dx.segment<3>(3 * i) = *end[static_cast<std::size_t>(i)] - *start[static_cast<std::size_t>(i)];
  }
  auto of_stack = [&distance2](const Vector12& y) {
    return distance2(y.segment<3>(0), y.segment<3>(3), y.segment<3>(6), y.segment<3>(9));
  };
  return additive_ccd(x, dx, side_a, of_stack, options);
}

}  // namespace

TimeOfImpact point_triangle_ccd(const Vector3& p_start, const Vector3& t0_start,
                                const Vector3& t1_start, const Vector3& t2_start,
                                const Vector3& p_end, const Vector3& t0_end,
                                const Vector3& t1_end, const Vector3& t2_end,
                                const CcdOptions& options) {
  auto distance2 = [](const Vector3& p, const Vector3& t0, const Vector3& t1, const Vector3& t2) {
    return point_triangle_distance(p, t0, t1, t2, false).value;
  };
  return four_node_ccd({&p_start, &t0_start, &t1_start, &t2_start},
                       {&p_end, &t0_end, &t1_end, &t2_end}, 1, distance2, options);
}

TimeOfImpact edge_edge_ccd(const Vector3& ea0_start, const Vector3& ea1_start,
                           const Vector3& eb0_start, const Vector3& eb1_start,
                           const Vector3& ea0_end, const Vector3& ea1_end,
                           const Vector3& eb0_end, const Vector3& eb1_end,
                           const CcdOptions& options) {
  auto distance2 = [](const Vector3& a0, const Vector3& a1, const Vector3& b0, const Vector3& b1) {
    return edge_edge_distance(a0, a1, b0, b1, false).value;
  };
  return four_node_ccd({&ea0_start, &ea1_start, &eb0_start, &eb1_start},
                       {&ea0_end, &ea1_end, &eb0_end, &eb1_end}, 2, distance2, options);
}

TimeOfImpact point_plane_ccd(const Vector3& p_start, const Vector3& p_end,
                             const Vector3& origin, const Vector3& normal,
                             const CcdOptions& options) {
  TimeOfImpact out;
  out.toi = options.t_max;
  const double s0 = point_plane_signed_distance(p_start, origin, normal);
  const double s1 = point_plane_signed_distance(p_end, origin, normal);
  // Distances on the starting side: a(t) = a0 + t (a1 - a0) must stay above xi.
  const double side = s0 >= 0 ? 1.0 : -1.0;
  const double a0 = side * s0, a1 = side * s1, xi = options.min_distance;
  if (!(a0 > xi)) return {true, 0.0, 0};
  if (a0 + options.t_max * (a1 - a0) > xi) return out;
  const double t_reach = (a0 - xi) / (a0 - a1);
  return {true, options.conservative_rescaling * t_reach, 0};
}

void check_ccd_options(const CcdOptions& options) {
  require_positive("min_distance", options.min_distance, true);
  if (!(options.t_max > 0 && options.t_max <= 1)) {
    throw_invalid("t_max", options.t_max, "in (0, 1]");
  }
  require_open_interval("conservative_rescaling", options.conservative_rescaling, 0.0, 1.0);
  require_integer_in("max_iterations", options.max_iterations, 1, 1000000000);
}

}  // namespace kresling::contact
