#pragma once
/// \file contact_candidate_cache.hpp
/// The broad phase's candidates kept across evaluations (a Verlet list): found once within
/// a distance d + skin, they hold every pair closer than d for as long as no node has moved
/// more than skin / 2 from where they were found, since then no pair's distance has fallen
/// by more than skin. Newton's iterates near each other thus share one broad phase; the
/// list is found anew when a node has moved further. A step from x to x + dx is covered as
/// long as, in addition, 2 max |dx| stays within the skin's remainder (a pair that meets
/// along the step starts at most 2 max |dx| apart).
///
/// Thread-safe: one cache may serve several evaluations at once (a family shared by
/// computations on several threads); each gets the list as it stands.

#include <memory>
#include <mutex>

#include "kresling/elements/contact_broad_phase.hpp"

namespace kresling::elements {

class ContactCandidateCache {
 public:
  /// Candidates within `distance` of triangles and their edges, found within distance +
  /// skin (skin > 0).
  ContactCandidateCache(double distance, double skin) : distance_(distance), skin_(skin) {}

  /// A list holding every pair closer than the distance at positions x (and, when `step`
  /// is given, every pair that may meet along x -> x + step); null when the list, found
  /// anew at x if need be, cannot cover the step (then a swept broad phase must).
  std::shared_ptr<const ContactCandidates> candidates(
      const Eigen::Ref<const NodeMatrix>& x, const Eigen::Ref<const TriangleMatrix>& triangles,
      const Eigen::Ref<const EdgeMatrix>& edges, const NodeMatrix* step = nullptr) const;

 private:
  double distance_, skin_;
  mutable std::mutex mutex_;
  mutable NodeMatrix found_at_;  // the positions the list was found at
  mutable std::shared_ptr<const ContactCandidates> list_;
};

}  // namespace kresling::elements
