// The broad phase's candidates kept across evaluations (contact_candidate_cache.hpp).

#include "kresling/elements/contact_candidate_cache.hpp"

namespace kresling::elements {

namespace {

double largest_move(const Eigen::Ref<const NodeMatrix>& d) {
  return d.rows() ? d.rowwise().norm().maxCoeff() : 0.0;
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
    moved = 0.0;
  }
  return list_;
}

}  // namespace kresling::elements
