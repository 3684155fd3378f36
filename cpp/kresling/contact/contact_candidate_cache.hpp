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
/// The same argument bounds every pair's distance from below: a pair in the list is no
/// closer than its own distance where the list was found, one outside it no closer than
/// distance + skin there, each less twice the largest node move since. The list keeps each
/// pair's distance, so that an evaluation passes over the pairs that cannot be within its
/// distance at a comparison each, and a collision check can tell from the step's size
/// alone that no pair comes near (KeptView::clearance).
///
/// Thread-safe: one cache may serve several evaluations at once (a family shared by
/// computations on several threads); each gets the list as it stands.

#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "kresling/contact/contact_broad_phase.hpp"

namespace kresling::contact {

/// A list as the cache keeps it: the candidates found within `reach` (distance + skin) at
/// some positions, and each pair's distance there, in the list's order.
struct KeptCandidates {
  ContactCandidates pairs;
  std::vector<double> point_triangle_distance;  ///< one per pairs.point_triangle
  std::vector<double> edge_edge_distance;       ///< one per pairs.edge_edge
  double reach = 0.0;     ///< no pair outside the list is closer than this where it was found
  double nearest = 0.0;   ///< the smallest of the distances (inf: no pair)
  /// 1e-9 of the coordinates' size: a distance is trusted to within this (its rounding is
  /// of the order of 1e-16 of the coordinates).
  double rounding = 0.0;
};

/// A kept list served at positions x: the list (null when it cannot cover a step asked
/// for) and the largest node move from where it was found to x. No pair's distance at x
/// is below its distance in the list less 2 moved, nor, for a pair outside the list,
/// below reach less 2 moved.
struct KeptView {
  std::shared_ptr<const KeptCandidates> list;
  double moved = 0.0;

  /// A lower bound on the distance at x of every pair that is not excluded (in the list or
  /// not): min(nearest, reach) - 2 moved, less the rounding; 0 when that is not positive.
  double clearance() const;
  /// Whether a pair whose distance in the list is `found` may be closer than `distance`
  /// at x (false only when it surely is not, rounding included).
  bool may_be_within(double found, double distance) const {
    return found - 2.0 * moved < distance + list->rounding;
  }
};

class ContactCandidateCache {
 public:
  /// Candidates within `distance` of triangles and their edges, found within distance +
  /// skin (skin > 0).
  ContactCandidateCache(double distance, double skin, JoinedNodes joined = {})
      : distance_(distance), skin_(skin), joined_(std::move(joined)) {}

  /// A list holding every pair closer than the distance at positions x (and, when `step`
  /// is given, every pair that may meet along x -> x + step), with the nodes' move since it
  /// was found; a null list when the list, found anew at x if need be, cannot cover the
  /// step (then a swept broad phase must).
  KeptView candidates(const Eigen::Ref<const NodeMatrix>& x,
                      const Eigen::Ref<const TriangleMatrix>& triangles,
                      const Eigen::Ref<const EdgeMatrix>& edges,
                      const NodeMatrix* step = nullptr) const;

 private:
  double distance_, skin_;
  JoinedNodes joined_;  // nodes that count as one (contact_broad_phase.hpp)
  mutable std::mutex mutex_;
  mutable NodeMatrix found_at_;  // the positions the list was found at
  mutable std::shared_ptr<const KeptCandidates> list_;
};

}  // namespace kresling::contact
