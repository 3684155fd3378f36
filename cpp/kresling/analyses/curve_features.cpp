#include "kresling/analyses/curve_features.hpp"

#include <stdexcept>
#include <string>

namespace kresling::analyses {

namespace {

void check_sizes(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) {
    throw std::invalid_argument("x, y: have " + std::to_string(x.size()) + " and " +
                                std::to_string(y.size()) + " entries; must be equally long");
  }
}

}  // namespace

LocalMaximum first_local_maximum(const std::vector<double>& x, const std::vector<double>& y,
                                 std::size_t from) {
  check_sizes(x, y);
  LocalMaximum out;
  for (std::size_t i = from < 1 ? 1 : from; i + 1 < y.size(); ++i) {
    if (!(y[i] > y[i - 1] && y[i] >= y[i + 1])) continue;
    // Newton form p(x) = y0 + d01 (x - x0) + a (x - x0)(x - x1); a < 0 at a maximum.
    const double x0 = x[i - 1], x1 = x[i], x2 = x[i + 1];
    const double d01 = (y[i] - y[i - 1]) / (x1 - x0), d12 = (y[i + 1] - y[i]) / (x2 - x1);
    const double a = (d12 - d01) / (x2 - x0);
    const double xv = 0.5 * (x0 + x1) - d01 / (2.0 * a);
    out.found = true;
    out.index = i;
    out.x = xv;
    out.y = y[i - 1] + d01 * (xv - x0) + a * (xv - x0) * (xv - x1);
    return out;
  }
  return out;
}

Crossing first_crossing(const std::vector<double>& x, const std::vector<double>& y,
                        std::size_t from, bool downward) {
  check_sizes(x, y);
  Crossing out;
  for (std::size_t i = from + 1; i < y.size(); ++i) {
    const bool crosses = downward ? (y[i - 1] > 0.0 && y[i] <= 0.0)
                                  : (y[i - 1] < 0.0 && y[i] >= 0.0);
    if (!crosses) continue;
    out.found = true;
    out.index = i;
    out.fraction = y[i - 1] / (y[i - 1] - y[i]);
    out.x = x[i - 1] + out.fraction * (x[i] - x[i - 1]);
    return out;
  }
  return out;
}

double hermite(double x0, double x1, double e0, double e1, double f0, double f1, double x) {
  const double h = x1 - x0, t = (x - x0) / h, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * e0 + (t3 - 2 * t2 + t) * h * f0 + (-2 * t3 + 3 * t2) * e1 +
         (t3 - t2) * h * f1;
}

}  // namespace kresling::analyses
