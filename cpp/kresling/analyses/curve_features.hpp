#pragma once
/// \file curve_features.hpp
/// Features of a sampled curve y(x) (a force-displacement path): its first local maximum,
/// refined by the parabola through the sample and its neighbours, the first sign change of
/// y, and cubic Hermite interpolation of a function whose derivative is also sampled (the
/// strain energy, whose derivative along a displacement-controlled path is the force).
/// Pure functions; x must increase.

#include <cstddef>
#include <limits>
#include <vector>

namespace kresling::analyses {

/// A local maximum of sampled data.
struct LocalMaximum {
  bool found = false;
  std::size_t index = 0;  ///< the sample at the maximum
  double x = std::numeric_limits<double>::quiet_NaN();  ///< vertex of the fitted parabola
  double y = std::numeric_limits<double>::quiet_NaN();  ///< its value
};

/// The first interior sample i >= max(from, 1) with y[i] > y[i-1] and y[i] >= y[i+1]; x and
/// y are those of the vertex of the parabola through samples i-1, i, i+1 (uneven spacing
/// allowed), which lies between x[i-1] and x[i+1]. found = false if there is none (y
/// monotonic, or the maximum is at an end). Throws std::invalid_argument if the sizes differ.
LocalMaximum first_local_maximum(const std::vector<double>& x, const std::vector<double>& y,
                                 std::size_t from = 0);

/// Where y changes sign.
struct Crossing {
  bool found = false;
  std::size_t index = 0;  ///< the first sample past the crossing
  double fraction = 0.0;  ///< position between samples index-1 (0) and index (1)
  double x = std::numeric_limits<double>::quiet_NaN();  ///< linear interpolation
};

/// The first i > from with y[i-1] > 0 >= y[i] (`downward`) or y[i-1] < 0 <= y[i] (upward),
/// located by linear interpolation. Throws std::invalid_argument if the sizes differ.
Crossing first_crossing(const std::vector<double>& x, const std::vector<double>& y,
                        std::size_t from, bool downward);

/// The cubic Hermite interpolant on [x0, x1] with values e0, e1 and slopes f0, f1, at x.
double hermite(double x0, double x1, double e0, double e1, double f0, double f1, double x);

}  // namespace kresling::analyses
