#pragma once
/// \file contact_ccd.hpp
/// Continuous collision detection along a linear step: the largest fraction of a step from
/// positions x0 to x1 that a Newton step (static, fold or dynamic) may take so that no point
/// passes through a triangle, no edge through an edge and no point through a rigid plane.
///
///     t = 0        p0 o                    t = 1           o p1
///                      \                                  /
///       t00 --------- t10    ...    t01 ------------ t11
///
/// Point-triangle and edge-edge pairs use additive CCD (ACCD, Li et al. 2021, "Codimensional
/// incremental potential contact", Sec. 4): after subtracting the mean displacement (which
/// changes no distance), the two primitives cannot approach faster than l_p, the sum of the
/// largest displacement on each side, so advancing by t_l = eta (d - xi) / l_p from a state
/// at distance d cannot bring them closer than xi + (1 - eta)(d - xi). Repeating from the
/// new state until the distance falls below (1 - eta)(d0 - xi) gives a time of impact that is
/// conservative by construction, up to the rounding of the distance itself. Point-plane
/// pairs move linearly in their signed distance, which is solved exactly.

#include "kresling/core/types.hpp"

namespace kresling::contact {

/// How a collision check runs.
struct CcdOptions {
  double min_distance = 0.0;            ///< xi >= 0: the separation a step must keep [length]
  double t_max = 1.0;                   ///< the fraction of the step to check, in (0, 1]
  double conservative_rescaling = 0.9;  ///< eta in (0, 1): the share of the gap one advance takes
  long max_iterations = 1000000;        ///< advances before giving up with the time reached
};

/// Result of a collision check. Without impact, the pair stays farther apart than
/// min_distance over [0, t_max] and `toi` = t_max. With impact, it does so over [0, toi],
/// toi in [0, t_max) (0 when the pair starts at min_distance or closer). An impact says that
/// this pair limits the step, not that it collides: ACCD also stops where the gap falls
/// below (1 - eta) of its starting value, and the next step starts from that smaller gap.
struct TimeOfImpact {
  bool impact = false;
  double toi = 1.0;
  long iterations = 0;  ///< ACCD's advances (0 for point-plane)
};

/// A point (p) and a triangle (t0, t1, t2) moving linearly from the first four positions to
/// the last four.
TimeOfImpact point_triangle_ccd(const Vector3& p_start, const Vector3& t0_start,
                                const Vector3& t1_start, const Vector3& t2_start,
                                const Vector3& p_end, const Vector3& t0_end,
                                const Vector3& t1_end, const Vector3& t2_end,
                                const CcdOptions& options = {});

/// Two edges (ea0, ea1) and (eb0, eb1) moving linearly.
TimeOfImpact edge_edge_ccd(const Vector3& ea0_start, const Vector3& ea1_start,
                           const Vector3& eb0_start, const Vector3& eb1_start,
                           const Vector3& ea0_end, const Vector3& ea1_end,
                           const Vector3& eb0_end, const Vector3& eb1_end,
                           const CcdOptions& options = {});

/// A point moving linearly against a rigid plane (origin, normal of non-zero length): it must
/// stay on the side where it starts, farther than min_distance. The time is eta times the
/// exact time at which the distance reaches min_distance, so the step keeps the same margin
/// as ACCD's.
TimeOfImpact point_plane_ccd(const Vector3& p_start, const Vector3& p_end,
                             const Vector3& origin, const Vector3& normal,
                             const CcdOptions& options = {});

/// Throw std::invalid_argument naming the field unless the options are in their ranges.
void check_ccd_options(const CcdOptions& options);

}  // namespace kresling::contact
