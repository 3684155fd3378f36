// Time functions (solvers/time_function.hpp): a table, a harmonic and a linear chirp against
// their closed forms, and their refusals.

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "kresling/solvers/time_function.hpp"

using namespace kresling;

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

TEST(TimeFunction, AnEmptyTableIsOneAndATableIsPiecewiseLinearAndHeld) {
  solvers::TimeFunction f;
  EXPECT_FALSE(static_cast<bool>(solvers::time_factor(f)));
  f.times = (VectorX(3) << 0.0, 1.0, 3.0).finished();
  f.factors = (VectorX(3) << 0.0, 2.0, -2.0).finished();
  const auto g = solvers::time_factor(f);
  EXPECT_DOUBLE_EQ(g(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(g(0.5), 1.0);
  EXPECT_DOUBLE_EQ(g(2.0), 0.0);
  EXPECT_DOUBLE_EQ(g(10.0), -2.0);
}

TEST(TimeFunction, AChirpsPhaseIsQuadraticThenLinearAtTheEndFrequency) {
  solvers::TimeFunction f;
  f.amplitude = 3.0;
  f.frequency_hz = 2.0;
  f.end_frequency_hz = 8.0;
  f.sweep_time = 1.5;
  const auto g = solvers::time_factor(f);
  // phi(t) = 2 pi (f0 t + (f1 - f0) t^2 / (2 T)): at T it has turned 2 pi (f0 + f1) T / 2.
  for (double t : {0.1, 0.7, 1.2, 1.5}) {
    const double phase = 2 * kPi * (2.0 * t + 6.0 / 1.5 * t * t / 2);
    EXPECT_NEAR(g(t), 3.0 * std::sin(phase), 1e-12) << t;
  }
  const double at_end = 2 * kPi * (2.0 + 8.0) / 2 * 1.5;
  for (double t : {1.6, 2.0, 7.3}) {
    EXPECT_NEAR(g(t), 3.0 * std::sin(at_end + 2 * kPi * 8.0 * (t - 1.5)), 1e-11) << t;
  }
}

TEST(TimeFunction, RefusesFrequenciesAndSweepsNotAboveZeroAndTimesThatDoNotIncrease) {
  solvers::TimeFunction chirp;
  chirp.amplitude = 1.0;
  chirp.frequency_hz = 1.0;
  chirp.end_frequency_hz = 0.0;
  chirp.sweep_time = 1.0;
  EXPECT_THROW(solvers::time_factor(chirp), std::invalid_argument);
  chirp.end_frequency_hz = 2.0;
  chirp.sweep_time = -1.0;
  EXPECT_THROW(solvers::time_factor(chirp), std::invalid_argument);
  solvers::TimeFunction harmonic;
  harmonic.frequency_hz = -1.0;
  EXPECT_THROW(solvers::time_factor(harmonic), std::invalid_argument);
  solvers::TimeFunction table;
  table.times = (VectorX(2) << 1.0, 1.0).finished();
  table.factors = VectorX::Zero(2);
  EXPECT_THROW(solvers::time_factor(table), std::invalid_argument);
  table.times = VectorX::Zero(1);
  EXPECT_THROW(solvers::time_factor(table), std::invalid_argument);
}
