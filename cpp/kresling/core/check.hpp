#pragma once
/// \file check.hpp
/// Input validation that fails with a message naming the parameter, the value given and
/// what is allowed. Bad input is always a std::invalid_argument (pybind11 turns it into a
/// Python ValueError); numerical outcomes are reported in results, never thrown.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace kresling {

/// Format a number the way messages show it: shortest round-trippable form.
std::string format_number(double value);

/// Format a number to `digits` significant digits, for a computed quantity in a message
/// whose last digits mean nothing (a path fraction reached by bisections: 0.671289, not
/// 0.67128906250000009).
std::string format_rounded(double value, int digits = 6);

/// Throw std::invalid_argument("<name> = <value> is invalid: must be <allowed>").
[[noreturn]] void throw_invalid(const std::string& name, double value, const std::string& allowed);

/// Throw unless lo <= value <= hi: "<name> = <value> is invalid: must be an integer in
/// [lo, hi]" (counts with a documented upper bound: steps, iterations, bisections).
void require_integer_in(const std::string& name, long long value, long long lo, long long hi);

/// Throw unless `value` is finite (not NaN, not +-inf).
void require_finite(const std::string& name, double value);

/// Throw unless lo < value < hi (both bounds excluded), after require_finite.
void require_open_interval(const std::string& name, double value, double lo, double hi);

/// Throw unless value > 0 (or >= 0 when allow_zero), after require_finite.
void require_positive(const std::string& name, double value, bool allow_zero = false);

}  // namespace kresling
