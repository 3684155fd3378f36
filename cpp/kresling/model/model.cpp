#include "kresling/model/model.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "kresling/core/check.hpp"

namespace kresling::model {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// An element as messages name it; the name is only formatted when a check fails (the
// checks run for every element of every model a sweep builds).
struct ElementRef {
  const char* kind;
  std::size_t index;
  const Index* nodes;
  int count;

  std::string name() const {
    std::string s = std::string(kind) + " " + std::to_string(index) + " (nodes";
    for (int k = 0; k < count; ++k) s += (k ? ", " : " ") + std::to_string(nodes[k]);
    return s + ")";
  }
};

void check_nodes(const ElementRef& e, Index num_nodes) {
  for (int k = 0; k < e.count; ++k) {
    if (e.nodes[k] < 0 || e.nodes[k] >= num_nodes) {
      throw std::invalid_argument(e.name() + ": node " + std::to_string(e.nodes[k]) +
                                  " is out of range [0, " + std::to_string(num_nodes) + ")");
    }
    for (int j = 0; j < k; ++j) {
      if (e.nodes[j] == e.nodes[k]) throw std::invalid_argument(e.name() + ": a node appears twice");
    }
  }
}

// require_positive / require_finite with the element's name built only on failure.
void positive(const ElementRef& e, const char* what, double value, bool allow_zero = false) {
  if (std::isfinite(value) && (allow_zero ? value >= 0.0 : value > 0.0)) return;
  require_positive(e.name() + ": " + what, value, allow_zero);
}

double extent(const NodeMatrix& X) {
  return std::max((X.colwise().maxCoeff() - X.colwise().minCoeff()).norm(), 1e-300);
}

void check_bar(const Bar& bar, std::size_t i, const NodeMatrix& X, double scale) {
  const ElementRef e{"bar", i, bar.nodes.data(), 2};
  check_nodes(e, X.rows());
  positive(e, "area", bar.area);
  positive(e, "rest length", bar.rest_length);
  positive(e, "modulus", bar.law.modulus);
  const double l = (X.row(bar.nodes[1]) - X.row(bar.nodes[0])).norm();
  if (!(l > 1e-12 * scale)) {
    throw std::invalid_argument(e.name() + ": zero length (its two nodes coincide)");
  }
}

void check_hinge_geometry(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                          std::size_t index, double scale) {
  const ElementRef e{"hinge", index, nodes.data(), 4};
  check_nodes(e, X.rows());
  const Vector3 a = X.row(nodes[0]), b = X.row(nodes[1]);
  const Vector3 axis = b - a;
  const double axis_length = axis.norm();
  if (!(axis_length > 1e-12 * scale)) throw std::invalid_argument(e.name() + ": zero-length axis");
  for (int w = 2; w < 4; ++w) {
    const Vector3 x = X.row(nodes[w]);
    const double distance = (x - a).cross(axis).norm() / axis_length;
    if (!(distance > 1e-9 * scale)) {
      throw std::invalid_argument(e.name() + ": wing node " + std::to_string(nodes[w]) +
                                  " lies on the axis line (collinear hinge triangle)");
    }
  }
}

void check_hinge(const Hinge& h, std::size_t i, const NodeMatrix& X, double scale) {
  const ElementRef e{"hinge", i, h.nodes.data(), 4};
  check_hinge_geometry(X, h.nodes, i, scale);
  positive(e, "stiffness", h.stiffness, /*allow_zero=*/true);
  positive(e, "length", h.length);
  if (!(std::isfinite(h.rest_angle) && h.rest_angle >= 0.0 && h.rest_angle < kTwoPi)) {
    require_finite(e.name() + ": rest angle", h.rest_angle);
    throw_invalid(e.name() + ": rest angle", h.rest_angle, "in [0, 2 pi)");
  }
  if (h.law.kind == elements::SpringLawKind::EnhancedLinear) {
    if (!(h.law.theta1 > 0.0 && h.law.theta1 < h.law.theta2 && h.law.theta2 < kTwoPi)) {
      throw std::invalid_argument(e.name() + ": spring limits (" + format_number(h.law.theta1) +
                                  ", " + format_number(h.law.theta2) +
                                  ") are invalid: must satisfy 0 < theta1 < theta2 < 2 pi");
    }
  }
}

void check_cable(const Cable& c, std::size_t i, const NodeMatrix& X, double scale) {
  const ElementRef e{"cable", i, c.nodes.data(), static_cast<int>(c.nodes.size())};
  if (c.nodes.size() < 2 || c.nodes.size() > kMaxCableNodes) {
    throw std::invalid_argument("cable " + std::to_string(i) + ": has " +
                                std::to_string(c.nodes.size()) + " nodes, must have 2 to " +
                                std::to_string(kMaxCableNodes));
  }
  check_nodes(e, X.rows());
  positive(e, "stiffness", c.stiffness);
  positive(e, "rest length", c.rest_length);
  for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) {
    if (!((X.row(c.nodes[k + 1]) - X.row(c.nodes[k])).norm() > 1e-12 * scale)) {
      throw std::invalid_argument(e.name() + ": nodes " + std::to_string(c.nodes[k]) + " and " +
                                  std::to_string(c.nodes[k + 1]) +
                                  " coincide (a segment needs a direction)");
    }
  }
}

}  // namespace

void check_hinge_geometry(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                          std::size_t index) {
  check_hinge_geometry(X, nodes, index, extent(X));
}

void check_hinge_geometry_at_scale(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                                   std::size_t index, double scale) {
  check_hinge_geometry(X, nodes, index, scale);
}

double node_extent(const NodeMatrix& X) { return extent(X); }

Model::Model(NodeMatrix nodes, std::vector<Bar> bars, std::vector<Hinge> hinges,
             std::vector<std::uint8_t> fixed, std::vector<Cable> cables)
    : nodes_(std::move(nodes)),
      bars_(std::move(bars)),
      hinges_(std::move(hinges)),
      fixed_(std::move(fixed)),
      cables_(std::move(cables)) {
  if (nodes_.rows() == 0) throw std::invalid_argument("nodes: the model has no nodes");
  for (Index i = 0; i < nodes_.rows(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(nodes_(i, k))) {
        throw std::invalid_argument("node " + std::to_string(i) + ": coordinate " +
                                    std::to_string(k) + " = " + format_number(nodes_(i, k)) +
                                    " is not finite");
      }
    }
  }
  if (static_cast<Index>(fixed_.size()) != num_dofs()) {
    throw std::invalid_argument("fixed: has " + std::to_string(fixed_.size()) +
                                " entries, must have one per DOF (" +
                                std::to_string(num_dofs()) + ")");
  }
  // Length scale for the degeneracy checks: the model's extent.
  const double scale = extent(nodes_);
  for (std::size_t i = 0; i < bars_.size(); ++i) check_bar(bars_[i], i, nodes_, scale);
  for (std::size_t i = 0; i < hinges_.size(); ++i) check_hinge(hinges_[i], i, nodes_, scale);
  for (std::size_t i = 0; i < cables_.size(); ++i) check_cable(cables_[i], i, nodes_, scale);
}

Model Model::with_cable_rest_lengths(const std::vector<double>& rest_lengths) const {
  if (rest_lengths.size() != cables_.size()) {
    throw std::invalid_argument("rest_lengths: has " + std::to_string(rest_lengths.size()) +
                                " entries, the model has " + std::to_string(cables_.size()) +
                                " cables");
  }
  Model copy = *this;
  for (std::size_t i = 0; i < rest_lengths.size(); ++i) {
    require_positive("rest_lengths[" + std::to_string(i) + "]", rest_lengths[i]);
    copy.cables_[i].rest_length = rest_lengths[i];
  }
  return copy;
}

NodeMatrix Model::deformed(const VectorX& u) const {
  if (u.size() != num_dofs()) {
    throw std::invalid_argument("u: has " + std::to_string(u.size()) + " entries, must have " +
                                std::to_string(num_dofs()));
  }
  return nodes_ + Eigen::Map<const NodeMatrix>(u.data(), nodes_.rows(), 3);
}

}  // namespace kresling::model
