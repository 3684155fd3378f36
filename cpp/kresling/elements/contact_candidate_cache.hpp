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
/// The same argument bounds every pair's distance from below (clearance): a pair in the list
/// is no closer than the nearest of the list where it was found, one outside it no closer
/// than distance + skin there, each less twice the largest node move since. A collision
/// check can then tell from the step's size alone that no pair comes near.
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

  /// A lower bound on the distance at x of every point-triangle and edge-edge pair of the
  /// mesh that is not excluded (any pair a broad phase may return), from the list as it
  /// stands: min(the nearest of its pairs where it was found, distance + skin) less twice
  /// the largest node move from there to x. Zero when there is no list yet or the bound is
  /// within the rounding of the distances (1e-9 of the coordinates' size). The list's
  /// nearest pair is measured once per list, at the first call.
  double clearance(const Eigen::Ref<const NodeMatrix>& x,
                   const Eigen::Ref<const TriangleMatrix>& triangles,
                   const Eigen::Ref<const EdgeMatrix>& edges) const;

 private:
  double distance_, skin_;
  mutable std::mutex mutex_;
  mutable NodeMatrix found_at_;  // the positions the list was found at
  mutable std::shared_ptr<const ContactCandidates> list_;
  mutable double nearest_ = -1.0;  // the list's nearest pair where found (< 0: not yet measured)
};

}  // namespace kresling::elements
