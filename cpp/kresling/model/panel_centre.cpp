#include "kresling/model/panel_centre.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "kresling/model/octave_arithmetic.hpp"
#include "kresling/model/polygon_centre_walk.hpp"

namespace kresling::model {

namespace {

// Non-adjacent corner pairs (i < j), the diagonals the centre objective runs over.
std::vector<std::pair<std::size_t, std::size_t>> diagonals(std::size_t m) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t i = 0; i + 2 <= j; ++i) {
      if (i == 0 && j == m - 1) continue;
      pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

// The point on line a + s (b - a) closest to line c + t (d - c), or false if parallel.
bool closest_on_line(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d,
                     Vector3& out) {
  const Vector3 m = b - a, n = d - c, w = c - a;
  // Least squares on [m, -n] (s, t) = w, through its 2 x 2 normal equations.
  const double mm = m.dot(m), nn = n.dot(n), mn = m.dot(n);
  const double det = mm * nn - mn * mn;
  if (!(det > 1e-14 * mm * nn)) return false;
  const double s = (w.dot(m) * nn - w.dot(n) * mn) / det;
  out = a + s * m;
  return true;
}

}  // namespace

Vector3 quad_centre(const Vector3& p0, const Vector3& p1, const Vector3& p2, const Vector3& p3) {
  // Lengths, directions and the solve are computed as MERLIN2 does under Octave, so that
  // the centre agrees with its to the last bit (its bend hinges' rest angles feel an ulp).
  const double l1 = octave_norm(p0 - p2), l2 = octave_norm(p3 - p1);
  if (!(l1 > 0.0 && l2 > 0.0)) {
    throw std::invalid_argument("quad has a diagonal of zero length");
  }
  const Vector3 m = (p2 - p0) / l1, n = (p3 - p1) / l2;
  // Solve [m, -n] (c1, c2) = p1 - p0 in the least-squares sense.
  Eigen::Matrix<double, 3, 2> A;
  A.col(0) = m;
  A.col(1) = -n;
  if (!(std::abs((A.transpose() * A).determinant()) > 1e-14)) {
    throw std::invalid_argument("quad has parallel diagonals");
  }
  Eigen::Vector2d c;
  if (!octave_least_squares(A, p1 - p0, c)) {
    throw std::invalid_argument("quad's diagonals could not be intersected");
  }
  // On the shorter diagonal: the quad then bends along it if it is warped.
  return l1 < l2 ? Vector3(p0 + c[0] * m) : Vector3(p1 + c[1] * n);
}

double polygon_centre_objective(const std::vector<Vector3>& corners, const Vector3& x) {
  double sum = 0.0;
  for (const auto& [i, j] : diagonals(corners.size())) {
    const Vector3 d = corners[j] - corners[i];
    sum += (corners[j] - x).cross(corners[i] - x).norm() / d.squaredNorm();
  }
  return sum;
}

Vector3 polygon_optimal_centre(const std::vector<Vector3>& corners) {
  const std::size_t m = corners.size();
  if (m < 4) throw std::invalid_argument("polygon centre: needs at least 4 corners");
  const auto pairs = diagonals(m);
  // Starting points MERLIN2 uses: the shortest diagonal's midpoint and the corner mean.
  std::size_t shortest = 0;
  for (std::size_t k = 1; k < pairs.size(); ++k) {
    const auto& [i, j] = pairs[k];
    const auto& [a, b] = pairs[shortest];
    if ((corners[j] - corners[i]).squaredNorm() < (corners[b] - corners[a]).squaredNorm()) {
      shortest = k;
    }
  }
  Vector3 mean = Vector3::Zero();
  for (const auto& p : corners) mean += p;
  mean /= static_cast<double>(m);
  std::vector<Vector3> candidates = {
      0.5 * (corners[pairs[shortest].first] + corners[pairs[shortest].second]), mean};
  // Every crossing of two diagonal lines (exact minimiser for a planar polygon); beyond
  // kCrossingCorners corners, where they are too many, the walk to the lowest of them.
  const bool small = m <= kCrossingCorners;
  if (!small) candidates.push_back(planar_polygon_centre_walk(corners));
  for (std::size_t p = 0; small && p < pairs.size(); ++p) {
    for (std::size_t q = p + 1; q < pairs.size(); ++q) {
      Vector3 x;
      if (closest_on_line(corners[pairs[p].first], corners[pairs[p].second],
                          corners[pairs[q].first], corners[pairs[q].second], x)) {
        candidates.push_back(x);
      }
    }
  }
  Vector3 best = candidates[0];
  double best_value = polygon_centre_objective(corners, best);
  for (const Vector3& x : candidates) {
    const double value = polygon_centre_objective(corners, x);
    if (value < best_value) best = x, best_value = value;
  }

  // A warped polygon: the objective is still convex but no longer piecewise linear. Refine
  // by iteratively reweighted least squares (each term |c + (p_i - p_j) x X| / |p_j - p_i|^2
  // is the norm of an affine function of X; every step lowers the objective), from the best
  // crossing and from MERLIN2's two starting points, and keep the lowest.
  double size = 0.0;
  for (const auto& p : corners) size = std::max(size, (p - mean).norm());
  // A planar polygon's best crossing is exact: keep it (refining could only move it by
  // rounding). Newell's normal gives the plane.
  Vector3 normal = Vector3::Zero();
  for (std::size_t k = 0; k < m; ++k) normal += corners[k].cross(corners[(k + 1) % m]);
  double warp = 0.0;
  if (normal.norm() > 0.0) {
    normal.normalize();
    for (const auto& p : corners) warp = std::max(warp, std::abs((p - mean).dot(normal)));
  }
  if (warp <= 1e-12 * size) return best;
  const double floor = 1e-13 * size * size;  // keeps the weights finite on a kink
  auto refine = [&](Vector3 x) {
    for (int iteration = 0; iteration < 5000; ++iteration) {
      Matrix3 H = Matrix3::Zero();
      Vector3 g = Vector3::Zero();
      for (const auto& [i, j] : pairs) {
        const Vector3 d = corners[i] - corners[j];
        const Vector3 c = corners[j].cross(corners[i]);
        const double w = 1.0 / (std::max((c + d.cross(x)).norm(), floor) * d.squaredNorm());
        Matrix3 B;  // B y = d x y
        B << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
        H += w * B.transpose() * B;
        g += w * B.transpose() * c;
      }
      const Vector3 next = H.ldlt().solve(-g);
      if (!next.allFinite()) break;
      const double step = (next - x).norm();
      x = next;
      if (step <= 1e-15 * size) break;
    }
    return x;
  };
  // A large polygon is refined from the best crossing only (each refinement costs up to
  // 5000 passes over its diagonals).
  const std::vector<Vector3> starts =
      small ? std::vector<Vector3>{best, candidates[0], candidates[1]} : std::vector<Vector3>{best};
  for (const Vector3& start : starts) {
    const Vector3 x = refine(start);
    const double value = polygon_centre_objective(corners, x);
    if (value < best_value) best = x, best_value = value;
  }
  return best;
}

}  // namespace kresling::model
