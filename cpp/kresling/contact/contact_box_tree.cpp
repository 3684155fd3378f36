// A bounding-volume hierarchy of axis-aligned boxes (contact_box_tree.hpp).

#include "kresling/contact/contact_box_tree.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace kresling::contact {

namespace {

constexpr Index kLeafSize = 4;

Vector3 centre(const AxisBox& b) { return 0.5 * (b.lo + b.hi); }

}  // namespace

BoxTree::BoxTree(std::vector<AxisBox> boxes) : boxes_(std::move(boxes)) {
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), Index{0});
  if (boxes_.empty()) return;
  nodes_.reserve(boxes_.size());  // leaves hold at least 2 boxes, so fewer than n nodes
  std::vector<Vector3> centres(boxes_.size());
  for (std::size_t i = 0; i < boxes_.size(); ++i) centres[i] = centre(boxes_[i]);
  build(0, size(), centres);
  // Store the boxes in tree order, so that a leaf's boxes are read from one place.
  std::vector<AxisBox> sorted(boxes_.size());
  for (std::size_t k = 0; k < boxes_.size(); ++k) {
    sorted[k] = boxes_[static_cast<std::size_t>(order_[k])];
  }
  boxes_ = std::move(sorted);
}

Index BoxTree::build(Index begin, Index end, const std::vector<Vector3>& centres) {
  // Median splits halve the count at every level, so the depth is ceil(log2(n / 4)) and the
  // nth_element passes cost O(n) a level: O(n log n) in all.
  const Index id = static_cast<Index>(nodes_.size());
  nodes_.push_back(Node{});
  AxisBox box{Vector3::Constant(std::numeric_limits<double>::infinity()),
              Vector3::Constant(-std::numeric_limits<double>::infinity())};
  AxisBox spread = box;  // of the centres
  for (Index k = begin; k < end; ++k) {
    const auto i = static_cast<std::size_t>(order_[static_cast<std::size_t>(k)]);
    box.lo = box.lo.cwiseMin(boxes_[i].lo);
    box.hi = box.hi.cwiseMax(boxes_[i].hi);
    spread.lo = spread.lo.cwiseMin(centres[i]);
    spread.hi = spread.hi.cwiseMax(centres[i]);
  }
  Index left = -1, right = -1;
  if (end - begin > kLeafSize) {
    int axis = 0;
    (spread.hi - spread.lo).maxCoeff(&axis);
    const Index middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&centres, axis](Index a, Index b) {
                       return centres[static_cast<std::size_t>(a)][axis] <
                              centres[static_cast<std::size_t>(b)][axis];
                     });
    left = build(begin, middle, centres);
    right = build(middle, end, centres);
  }
  Node& node = nodes_[static_cast<std::size_t>(id)];
  node.box = box;
  node.begin = begin;
  node.end = end;
  node.left = left;
  node.right = right;
  return id;
}

}  // namespace kresling::contact
