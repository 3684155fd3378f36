#include "kresling/solvers/time_function.hpp"

#include <cmath>
#include <stdexcept>

#include "kresling/core/check.hpp"

namespace kresling::solvers {

namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

std::function<double(double)> table(const VectorX& times, const VectorX& factors) {
  if (times.size() != factors.size()) {
    throw std::invalid_argument("time table: needs one factor per time");
  }
  for (Index i = 0; i < times.size(); ++i) {
    require_finite("time table: time", times[i]);
    require_finite("time table: factor", factors[i]);
    if (i > 0 && !(times[i] > times[i - 1])) {
      throw std::invalid_argument("time table: the times must increase");
    }
  }
  if (!times.size()) return {};
  return [times, factors](double t) {
    if (t <= times[0]) return factors[0];
    for (Index i = 1; i < times.size(); ++i) {
      if (t <= times[i]) {
        const double s = (t - times[i - 1]) / (times[i] - times[i - 1]);
        return factors[i - 1] + s * (factors[i] - factors[i - 1]);
      }
    }
    return factors[times.size() - 1];
  };
}

}  // namespace

std::function<double(double)> time_factor(const TimeFunction& f) {
  require_finite("amplitude", f.amplitude);
  require_positive("sweep_time", f.sweep_time, /*allow_zero=*/true);
  if (f.sweep_time > 0.0) {
    require_positive("chirp start frequency_hz", f.frequency_hz);
    require_positive("chirp end frequency_hz", f.end_frequency_hz);
    const double a = f.amplitude, f0 = f.frequency_hz, f1 = f.end_frequency_hz,
                 sweep = f.sweep_time;
    const double rate = (f1 - f0) / sweep;  // [Hz/s]
    const double phase_at_end = kTwoPi * (f0 + 0.5 * rate * sweep) * sweep;
    return [a, f0, f1, sweep, rate, phase_at_end](double t) {
      const double phase = t <= sweep ? kTwoPi * (f0 + 0.5 * rate * t) * t
                                      : phase_at_end + kTwoPi * f1 * (t - sweep);
      return a * std::sin(phase);
    };
  }
  require_positive("frequency_hz", f.frequency_hz, /*allow_zero=*/true);
  if (f.frequency_hz > 0.0) {
    const double w = kTwoPi * f.frequency_hz, a = f.amplitude;
    return [w, a](double t) { return a * std::sin(w * t); };
  }
  return table(f.times, f.factors);
}

}  // namespace kresling::solvers
