#pragma once
/// \file polygon_diagonals.hpp
/// Which segments cut a panel into triangles: diagonals that lie inside it, and centres a
/// fan of triangles can be built around. For convex panels every diagonal and MERLIN2's
/// centre qualify; these tests let non-convex panels and panels with straight (180 deg)
/// corners be split too.
///
///   p5 -------- p4
///    |          |          An L-shaped panel: p2-p5 lies inside it and is a
///    |    p2 -- p3         diagonal; p1-p3 passes outside it (around the reflex
///    |    |                corner p2) and is not. A straight corner k (p_(k-1),
///   p0 -- p1               p_k, p_(k+1) on a line) makes p_(k-1)-p_(k+1) run
///                          along the sides: not a diagonal either.
///
/// The tests work in the panel's plane (Newell's normal through the corners' mean); corners
/// off it are projected onto it. Lengths are compared relative to the panel's size, so that
/// a segment within 1e-9 of it of a corner or a side counts as touching it; a cut or a
/// spoke must also leave every triangle it makes with angles above 1e-4 rad (a nearly
/// straight corner is not cut off, a centre nearly on a side's line is not used).

#include <cstddef>
#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::model {

/// A panel's corners in its own plane: 2D coordinates, counter-clockwise.
class PlanarPolygon {
 public:
  /// `corners` in order around the panel (at least 3, not all on one line).
  explicit PlanarPolygon(const std::vector<Vector3>& corners);

  /// Whether no two sides cross or touch but neighbours at their shared corner (a simple
  /// polygon; straight corners allowed).
  bool is_simple() const;

  /// Whether the segment from corner i to corner j (not neighbours) lies inside the panel,
  /// touching its boundary only at its ends: then it cuts the panel into two panels of
  /// positive area.
  bool is_interior_diagonal(std::size_t i, std::size_t j) const;

  /// Whether `centre` sees every side from inside: every triangle (centre, p_k, p_(k+1))
  /// turns the panel's way with an area, once around (the panel is star-shaped from it).
  bool is_star_centre(const Vector3& centre) const;

 private:
  // Twice the signed area of (a, b, c): > 0 when c is left of a -> b.
  double turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) const;
  bool on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) const;
  bool crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                const Eigen::Vector2d& d) const;
  bool in_cone(std::size_t i, const Eigen::Vector2d& towards) const;
  Eigen::Vector2d project(const Vector3& x) const;

  std::vector<Eigen::Vector2d> points_;
  Vector3 origin_, u_, v_;
  double size_ = 0.0;            // the largest distance of a corner from their mean
  double area_tolerance_ = 0.0;  // twice an area, below which three points are on a line
};

}  // namespace kresling::model
