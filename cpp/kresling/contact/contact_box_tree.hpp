#pragma once
/// \file contact_box_tree.hpp
/// A bounding-volume hierarchy of axis-aligned boxes for the contact broad phase: built in
/// O(n log n) by median splits, queried for the boxes that overlap a given box in
/// O(log n + k) for boxes of similar size.
///
///                 [ root box ]
///                /            |
///        [ left half ]    [ right half ]      split at the median centroid along the
///          /     |           /     |           longest axis of the centroids' spread
///       leaf    leaf      leaf    leaf        (at most 4 boxes a leaf)

#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::contact {

/// An axis-aligned box [lo, hi] (lo <= hi componentwise).
struct AxisBox {
  Vector3 lo = Vector3::Zero();
  Vector3 hi = Vector3::Zero();
};

/// True when the two closed boxes share a point.
inline bool boxes_overlap(const AxisBox& a, const AxisBox& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
         b.lo.y() <= a.hi.y() && a.lo.z() <= b.hi.z() && b.lo.z() <= a.hi.z();
}

/// A static hierarchy over a list of boxes (indices 0 .. n-1 in the order given).
class BoxTree {
 public:
  explicit BoxTree(std::vector<AxisBox> boxes);

  /// Call visit(i) for every box i that overlaps `query` (each once, in no set order).
  template <typename Visit>
  void for_each_overlap(const AxisBox& query, Visit&& visit) const;

  Index size() const { return static_cast<Index>(boxes_.size()); }

 private:
  struct Node {
    AxisBox box;
    Index begin = 0, end = 0;   ///< the boxes order_[begin, end) below this node
    Index left = -1, right = -1;  ///< children (-1 for a leaf)
  };
  Index build(Index begin, Index end, const std::vector<Vector3>& centres);

  std::vector<AxisBox> boxes_;  ///< in tree order once built (leaves' boxes contiguous)
  std::vector<Index> order_;    ///< the given index of each box in tree order
  std::vector<Node> nodes_;
};

template <typename Visit>
void BoxTree::for_each_overlap(const AxisBox& query, Visit&& visit) const {
  if (nodes_.empty()) return;
  // Depth-first with an explicit stack: the depth is about log2(n / 4), far below 64.
  Index stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    if (!boxes_overlap(node.box, query)) continue;
    if (node.left < 0) {
      for (Index k = node.begin; k < node.end; ++k) {
        if (boxes_overlap(boxes_[static_cast<std::size_t>(k)], query)) {
          visit(order_[static_cast<std::size_t>(k)]);
        }
      }
      continue;
    }
    stack[top++] = node.left;
    stack[top++] = node.right;
  }
}

}  // namespace kresling::contact
