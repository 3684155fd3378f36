#pragma once
/// \file time_function.hpp
/// A factor in time, shared by a motion's loads (time_integration.hpp's TimeLoad) and its
/// creases' rest angles (RestAngleSchedule): a table, a harmonic or a linear chirp.

#include <functional>

#include "kresling/core/types.hpp"

namespace kresling::solvers {

/// What a factor in time is:
/// - a table (`times` [s] increasing, `factors`): piecewise linear, held beyond its ends;
///   an empty table (and no frequency) is the factor 1;
/// - a harmonic (`frequency_hz` > 0, `sweep_time` 0): amplitude sin(2 pi f t);
/// - a linear chirp (`sweep_time` > 0): amplitude sin(phi(t)), its frequency going linearly
///   from `frequency_hz` at t = 0 to `end_frequency_hz` at t = sweep_time,
///       phi(t) = 2 pi (f0 t + (f1 - f0) t^2 / (2 T))     for t <= T,
///   and a harmonic of f1 beyond, its phase continuous: phi(T) + 2 pi f1 (t - T).
struct TimeFunction {
  VectorX times, factors;
  double amplitude = 0.0;
  double frequency_hz = 0.0;      ///< the harmonic's, the chirp's at t = 0 [Hz]
  double end_frequency_hz = 0.0;  ///< the chirp's at t = sweep_time [Hz]
  double sweep_time = 0.0;        ///< the chirp's sweep [s]; 0: no chirp
};

/// The factor as a function of t [s] (empty for the factor 1). Throws
/// std::invalid_argument for a table whose times do not increase or whose sizes differ, a
/// harmonic or chirp whose frequencies are not > 0, or a non-finite value.
std::function<double(double)> time_factor(const TimeFunction& f);

}  // namespace kresling::solvers
