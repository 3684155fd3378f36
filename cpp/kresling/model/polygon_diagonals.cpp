#include "kresling/model/polygon_diagonals.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace kresling::model {

namespace {

// Segments within this fraction of the panel's size of a corner or a side touch it.
constexpr double kTouching = 1e-9;
// A cut or a spoke closer than this angle [rad] to a side would make a triangle with a
// corner that sharp (a nearly straight corner cut off, a centre nearly on a side's line):
// its angles' derivatives grow as 1 / sin of it.
constexpr double kMarginAngle = 1e-4;

}  // namespace

PlanarPolygon::PlanarPolygon(const std::vector<Vector3>& corners) {
  const std::size_t m = corners.size();
  if (m < 3) throw std::invalid_argument("a panel needs at least 3 corners");
  origin_ = Vector3::Zero();
  for (const Vector3& x : corners) origin_ += x;
  origin_ /= static_cast<double>(m);
  // Newell's normal: the panel's vector area, so the corners run counter-clockwise about it.
  Vector3 normal = Vector3::Zero();
  double size = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const Vector3 a = corners[k] - origin_, b = corners[(k + 1) % m] - origin_;
    normal += a.cross(b);
    size = std::max(size, a.norm());
  }
  if (!(normal.norm() > kTouching * size * size)) {
    // No net area (a bowtie's two loops cancel): any plane the corners span will show its
    // sides crossing (is_simple).
    for (std::size_t k = 1; k < m; ++k) {
      const Vector3 n = (corners[k] - corners[0]).cross(corners[(k + 1) % m] - corners[0]);
      if (n.norm() > normal.norm()) normal = n;
    }
  }
  if (!(normal.norm() > kTouching * size * size)) {
    throw std::invalid_argument("the panel has no area (its corners lie on a line)");
  }
  normal.normalize();
  u_ = normal.unitOrthogonal();
  v_ = normal.cross(u_);
  size_ = size;
  area_tolerance_ = kTouching * size * size;
  points_.reserve(m);
  for (const Vector3& x : corners) points_.push_back(project(x));
}

Eigen::Vector2d PlanarPolygon::project(const Vector3& x) const {
  const Vector3 d = x - origin_;
  return {d.dot(u_), d.dot(v_)};
}

double PlanarPolygon::turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const Eigen::Vector2d& c) const {
  const Eigen::Vector2d ab = b - a, ac = c - a;
  return ab.x() * ac.y() - ab.y() * ac.x();
}

// p on the closed segment a-b, within the tolerance of its line.
bool PlanarPolygon::on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                               const Eigen::Vector2d& p) const {
  const double length = (b - a).norm();
  if (std::abs(turn(a, b, p)) > kTouching * size_ * length) return false;  // off its line
  const double t = (p - a).dot(b - a);
  return t >= 0.0 && t <= length * length;
}

// Whether the direction from corner i towards `towards` points into the panel's interior
// angle at i, at least kMarginAngle from either side: angles measured counter-clockwise
// from the side to the next corner, where the interior angle ends at the previous corner
// (any angle in (0, 2 pi): convex, straight or reflex alike).
bool PlanarPolygon::in_cone(std::size_t i, const Eigen::Vector2d& towards) const {
  const std::size_t m = points_.size();
  const Eigen::Vector2d& here = points_[i];
  const Eigen::Vector2d next = points_[(i + 1) % m] - here;
  auto angle_from_next = [&](const Eigen::Vector2d& d) {
    const double a = std::atan2(next.x() * d.y() - next.y() * d.x(), next.dot(d));
    return a < 0.0 ? a + 2.0 * M_PI : a;
  };
  const double interior = angle_from_next(points_[(i + m - 1) % m] - here);
  const double direction = angle_from_next(towards - here);
  return direction > kMarginAngle && direction < interior - kMarginAngle;
}

bool PlanarPolygon::is_interior_diagonal(std::size_t i, std::size_t j) const {
  const std::size_t m = points_.size();
  if (i == j || (i + 1) % m == j || (j + 1) % m == i) return false;
  const Eigen::Vector2d& a = points_[i];
  const Eigen::Vector2d& b = points_[j];
  if (!in_cone(i, b) || !in_cone(j, a)) return false;
  for (std::size_t k = 0; k < m; ++k) {
    if (k == i || k == j) continue;
    if (on_segment(a, b, points_[k])) return false;  // the cut would pass through a corner
    const std::size_t l = (k + 1) % m;
    if (l == i || l == j) continue;
    if (crossing(a, b, points_[k], points_[l])) return false;  // a side crosses the cut
  }
  return true;
}

// Whether segments a-b and c-d cross at a point inside both (touching at an end is the
// callers' to test with on_segment).
bool PlanarPolygon::crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                             const Eigen::Vector2d& c, const Eigen::Vector2d& d) const {
  const double eps = area_tolerance_;
  const double s1 = turn(a, b, c), s2 = turn(a, b, d), s3 = turn(c, d, a), s4 = turn(c, d, b);
  return ((s1 > eps && s2 < -eps) || (s1 < -eps && s2 > eps)) &&
         ((s3 > eps && s4 < -eps) || (s3 < -eps && s4 > eps));
}

bool PlanarPolygon::is_simple() const {
  const std::size_t m = points_.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Eigen::Vector2d& a = points_[k];
    const Eigen::Vector2d& b = points_[(k + 1) % m];
    // A corner on a side other than its own two (a corner repeated, or pinched).
    for (std::size_t j = 0; j < m; ++j) {
      if (j != k && j != (k + 1) % m && on_segment(a, b, points_[j])) return false;
    }
    for (std::size_t l = k + 2; l < m; ++l) {
      if ((l + 1) % m == k) continue;  // the side before k shares corner k
      if (crossing(a, b, points_[l], points_[(l + 1) % m])) return false;
    }
  }
  return true;
}

bool PlanarPolygon::is_star_centre(const Vector3& centre) const {
  const Eigen::Vector2d c = project(centre);
  const std::size_t m = points_.size();
  double swept = 0.0;  // the angle the corners turn through about the centre
  for (std::size_t k = 0; k < m; ++k) {
    const Eigen::Vector2d a = points_[k] - c, b = points_[(k + 1) % m] - c;
    const double subtended = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    // Each fan triangle has all three angles above the margin: at the centre, and at its
    // corners (the spoke inside each corner's angle).
    if (!(subtended > kMarginAngle) || !in_cone(k, c)) return false;
    swept += subtended;
  }
  return swept < 3.0 * M_PI;  // once around (2 pi), not a star polygon's 4 pi or more
}

}  // namespace kresling::model
