// The broad phase's candidates kept across evaluations (contact_candidate_cache.hpp).

#include "kresling/elements/contact_candidate_cache.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kresling/elements/contact_distance.hpp"

namespace kresling::elements {

namespace {

double largest_move(const Eigen::Ref<const NodeMatrix>& d) {
  return d.rows() ? d.rowwise().norm().maxCoeff() : 0.0;
}

// The smallest distance among the pairs of `list` at positions x (inf for none), by the
// distance kernels the collision check measures with.
double nearest_of(const ContactCandidates& list, const Eigen::Ref<const NodeMatrix>& x,
                  const Eigen::Ref<const TriangleMatrix>& triangles,
                  const Eigen::Ref<const EdgeMatrix>& edges) {
  auto at = [&x](Index i) -> Vector3 { return x.row(i).transpose(); };
  double nearest2 = std::numeric_limits<double>::infinity();
  for (const auto& [p, t] : list.point_triangle) {
    nearest2 = std::min(nearest2, point_triangle_distance(at(p), at(triangles(t, 0)),
                                                          at(triangles(t, 1)),
                                                          at(triangles(t, 2)), false)
                                      .value);
  }
  for (const auto& [a, b] : list.edge_edge) {
    nearest2 = std::min(nearest2, edge_edge_distance(at(edges(a, 0)), at(edges(a, 1)),
                                                     at(edges(b, 0)), at(edges(b, 1)), false)
                                      .value);
  }
  return std::sqrt(nearest2);
}

}  // namespace

std::shared_ptr<const ContactCandidates> ContactCandidateCache::candidates(
    const Eigen::Ref<const NodeMatrix>& x, const Eigen::Ref<const TriangleMatrix>& triangles,
    const Eigen::Ref<const EdgeMatrix>& edges, const NodeMatrix* step) const {
  const double reach = step ? 2.0 * largest_move(*step) : 0.0;
  std::lock_guard<std::mutex> lock(mutex_);
  const bool same_mesh = list_ && found_at_.rows() == x.rows();
  double moved = same_mesh ? largest_move(x - found_at_) : 0.0;
  if (!same_mesh || 2.0 * moved > skin_ || (step && 2.0 * moved + reach > skin_)) {
    // Found anew here: then only the step's reach must fit in the skin.
    if (step && reach > skin_) return nullptr;
    list_ = std::make_shared<const ContactCandidates>(
        contact_candidates(x, triangles, edges, distance_ + skin_));
    found_at_ = x;
    nearest_ = -1.0;
    moved = 0.0;
  }
  return list_;
}

double ContactCandidateCache::clearance(const Eigen::Ref<const NodeMatrix>& x,
                                        const Eigen::Ref<const TriangleMatrix>& triangles,
                                        const Eigen::Ref<const EdgeMatrix>& edges) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!list_ || found_at_.rows() != x.rows() || x.rows() == 0) return 0.0;
  if (nearest_ < 0.0) nearest_ = nearest_of(*list_, found_at_, triangles, edges);
  const double bound = std::min(nearest_, distance_ + skin_) - 2.0 * largest_move(x - found_at_);
  // Below this the distances' own rounding (of the order of 1e-16 of the coordinates) is
  // no longer negligible beside the bound.
  const double rounding = 1e-9 * std::max(x.cwiseAbs().maxCoeff(), distance_ + skin_);
  return bound > rounding ? bound : 0.0;
}

}  // namespace kresling::elements
