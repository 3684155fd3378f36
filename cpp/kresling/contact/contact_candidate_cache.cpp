// The broad phase's candidates kept across evaluations (contact_candidate_cache.hpp).

#include "kresling/contact/contact_candidate_cache.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kresling/contact/contact_closest_points.hpp"

namespace kresling::contact {

namespace {

double largest_move(const Eigen::Ref<const NodeMatrix>& d) {
  return d.rows() ? d.rowwise().norm().maxCoeff() : 0.0;
}

// The list found within `reach` at positions x, with each pair's distance there (from its
// closest points).
std::shared_ptr<const KeptCandidates> kept_at(const Eigen::Ref<const NodeMatrix>& x,
                                              const Eigen::Ref<const TriangleMatrix>& triangles,
                                              const Eigen::Ref<const EdgeMatrix>& edges,
                                              double reach, const JoinedNodes& joined) {
  auto kept = std::make_shared<KeptCandidates>();
  kept->pairs = contact_candidates(x, triangles, edges, reach, joined);
  kept->reach = reach;
  kept->nearest = std::numeric_limits<double>::infinity();
  kept->rounding = 1e-9 * std::max(x.rows() ? x.cwiseAbs().maxCoeff() : 0.0, reach);
  auto at = [&x](Index i) -> Vector3 { return x.row(i).transpose(); };
  kept->point_triangle_distance.reserve(kept->pairs.point_triangle.size());
  for (const auto& [p, t] : kept->pairs.point_triangle) {
    const Vector3 q = at(p);
    const double d = (q - closest_point_on_triangle(q, at(triangles(t, 0)), at(triangles(t, 1)),
                                                    at(triangles(t, 2))))
                         .norm();
    kept->point_triangle_distance.push_back(d);
    kept->nearest = std::min(kept->nearest, d);
  }
  kept->edge_edge_distance.reserve(kept->pairs.edge_edge.size());
  for (const auto& [a, b] : kept->pairs.edge_edge) {
    const auto [p, q] =
        closest_points_of_edges(at(edges(a, 0)), at(edges(a, 1)), at(edges(b, 0)), at(edges(b, 1)));
    const double d = (p - q).norm();
    kept->edge_edge_distance.push_back(d);
    kept->nearest = std::min(kept->nearest, d);
  }
  return kept;
}

}  // namespace

double KeptView::clearance() const {
  if (!list) return 0.0;
  const double bound = std::min(list->nearest, list->reach) - 2.0 * moved - list->rounding;
  return bound > list->rounding ? bound : 0.0;
}

KeptView ContactCandidateCache::candidates(const Eigen::Ref<const NodeMatrix>& x,
                                           const Eigen::Ref<const TriangleMatrix>& triangles,
                                           const Eigen::Ref<const EdgeMatrix>& edges,
                                           const NodeMatrix* step) const {
  const double reach = step ? 2.0 * largest_move(*step) : 0.0;
  std::lock_guard<std::mutex> lock(mutex_);
  const bool same_mesh = list_ && found_at_.rows() == x.rows();
  double moved = same_mesh ? largest_move(x - found_at_) : 0.0;
  if (!same_mesh || 2.0 * moved > skin_ || (step && 2.0 * moved + reach > skin_)) {
    // Found anew here: then only the step's reach must fit in the skin.
    if (step && reach > skin_) return {};
    list_ = kept_at(x, triangles, edges, distance_ + skin_, joined_);
    found_at_ = x;
    moved = 0.0;
  }
  return {list_, moved};
}

}  // namespace kresling::contact
