#include "kresling/model/polygon_centre_walk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

namespace kresling::model {

namespace {

using Vector2 = Eigen::Vector2d;

// One diagonal's line in the plane: residual n . x - c (a signed distance), weight w.
struct Line {
  Vector2 n;
  double c;
  double w;
};

// The polygon's diagonal lines in plane coordinates (e1, e2) about `origin`.
std::vector<Line> diagonal_lines(const std::vector<Vector2>& p) {
  const std::size_t m = p.size();
  std::vector<Line> lines;
  lines.reserve(m * (m - 3) / 2);
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t i = 0; i + 2 <= j; ++i) {
      if (i == 0 && j == m - 1) continue;
      const Vector2 d = p[j] - p[i];
      const double length = d.norm();
      if (!(length > 0.0)) continue;  // coincident corners: their term is zero everywhere
      const Vector2 n(-d.y() / length, d.x() / length);
      lines.push_back({n, n.dot(p[i]), 1.0 / length});
    }
  }
  return lines;
}

double objective(const std::vector<Line>& lines, const Vector2& x) {
  double sum = 0.0;
  for (const Line& l : lines) sum += l.w * std::abs(l.n.dot(x) - l.c);
  return sum;
}

// The directional derivative of the objective at x along u (`active`: lines through x).
double slope(const std::vector<Line>& lines, const std::vector<double>& r,
             const std::vector<char>& active, const Vector2& u) {
  double s = 0.0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const double a = lines[k].n.dot(u);
    s += lines[k].w * (active[k] ? std::abs(a) : a * std::copysign(1.0, r[k]));
  }
  return s;
}

// The lowest point of the objective on the ray x + t u, t >= 0, given its slope s0 < 0 at
// t = 0+: the first crossing where the slope, rising by 2 w |a| at each, reaches 0.
double ray_minimum(const std::vector<Line>& lines, const std::vector<double>& r,
                   const std::vector<char>& active, const Vector2& u, double s0) {
  std::vector<std::pair<double, double>> crossings;  // (t, slope gained)
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const double a = lines[k].n.dot(u);
    if (!active[k] && r[k] * a < 0.0) crossings.emplace_back(-r[k] / a, 2.0 * lines[k].w * std::abs(a));
  }
  std::sort(crossings.begin(), crossings.end());
  double s = s0;
  for (const auto& [t, gain] : crossings) {
    s += gain;
    if (s >= 0.0) return t;
  }
  return crossings.empty() ? 0.0 : crossings.back().first;  // unreachable: f grows far out
}

// The directions that can descend from x: along and across the active lines, or down the
// gradient if none is active.
std::vector<Vector2> directions(const std::vector<Line>& lines, const std::vector<double>& r,
                                const std::vector<char>& active) {
  std::vector<Vector2> out;
  Vector2 gradient = Vector2::Zero();
  Vector2 first_normal = Vector2::Zero();
  bool parallel = true;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (!active[k]) {
      gradient += lines[k].w * std::copysign(1.0, r[k]) * lines[k].n;
      continue;
    }
    const Vector2& n = lines[k].n;
    if (first_normal.isZero()) first_normal = n;
    if (std::abs(first_normal.x() * n.y() - first_normal.y() * n.x()) > 1e-12) parallel = false;
    out.emplace_back(-n.y(), n.x());
    out.emplace_back(n.y(), -n.x());
  }
  if (out.empty()) {
    if (gradient.norm() > 0.0) out.push_back(-gradient.normalized());
  } else if (parallel) {  // every sector is a half-plane: its ray across the lines too
    out.push_back(first_normal);
    out.push_back(-first_normal);
  }
  return out;
}

}  // namespace

Vector3 planar_polygon_centre_walk(const std::vector<Vector3>& corners) {
  const std::size_t m = corners.size();
  if (m < 4) throw std::invalid_argument("polygon centre: needs at least 4 corners");
  Vector3 mean = Vector3::Zero();
  for (const auto& p : corners) mean += p;
  mean /= static_cast<double>(m);
  Vector3 normal = Vector3::Zero();
  for (std::size_t k = 0; k < m; ++k) normal += corners[k].cross(corners[(k + 1) % m]);
  if (!(normal.norm() > 0.0)) throw std::invalid_argument("polygon centre: zero area");
  normal.normalize();
  // The plane's axes: e1 along the corner farthest from the mean, e2 = normal x e1.
  double size = 0.0;
  Vector3 e1 = Vector3::Zero();
  for (const auto& p : corners) {
    const Vector3 v = (p - mean) - (p - mean).dot(normal) * normal;
    if (v.norm() > size) size = v.norm(), e1 = v;
  }
  e1.normalize();
  const Vector3 e2 = normal.cross(e1);
  std::vector<Vector2> p(m);
  for (std::size_t k = 0; k < m; ++k) p[k] = {(corners[k] - mean).dot(e1), (corners[k] - mean).dot(e2)};
  const std::vector<Line> lines = diagonal_lines(p);
  // MERLIN2's starting points: the shortest diagonal's midpoint and the corner mean (0).
  Vector2 x = Vector2::Zero(), midpoint = x;
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t i = 0; i + 2 <= j; ++i) {
      if (i == 0 && j == m - 1) continue;
      const double length = (p[j] - p[i]).squaredNorm();
      if (length < shortest) shortest = length, midpoint = 0.5 * (p[i] + p[j]);
    }
  }
  if (objective(lines, midpoint) < objective(lines, x)) x = midpoint;

  const double on_line = 1e-12 * size;  // a line through x, to rounding
  std::vector<double> r(lines.size());
  std::vector<char> active(lines.size());
  for (std::size_t move = 0; move < 4 * lines.size() + 16; ++move) {
    double scale = 0.0;  // of the slopes, for "does not descend" to rounding
    for (std::size_t k = 0; k < lines.size(); ++k) {
      r[k] = lines[k].n.dot(x) - lines[k].c;
      active[k] = std::abs(r[k]) <= on_line;
      scale += lines[k].w;
    }
    double best = -1e-12 * scale;
    Vector2 down = Vector2::Zero();
    for (const Vector2& u : directions(lines, r, active)) {
      const double s = slope(lines, r, active, u);
      if (s < best) best = s, down = u;
    }
    if (down.isZero()) break;  // no direction descends: the minimum
    const double t = ray_minimum(lines, r, active, down, best);
    if (!(t > 0.0)) break;
    x += t * down;
  }
  return mean + x.x() * e1 + x.y() * e2;
}

}  // namespace kresling::model
