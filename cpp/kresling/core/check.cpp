#include "kresling/core/check.hpp"

#include <cstdlib>
#include <iomanip>
#include <limits>

namespace kresling {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  // Read back with std::strtod, not std::stod: stod throws std::out_of_range for a
  // subnormal (-1e-310), which turned a message about a bad value into an IndexError.
  auto reads_back = [value](const std::string& text) {
    return std::strtod(text.c_str(), nullptr) == value;
  };
  auto with_digits = [value](int digits) {
    std::ostringstream out;
    out << std::setprecision(digits) << value;
    return out.str();
  };
  if (std::fpclassify(value) == FP_SUBNORMAL) {
    // Few digits are exact there: the fewest that read back (-1e-310, not
    // -9.99999999999997e-311).
    for (int digits = 1; digits < std::numeric_limits<double>::max_digits10; ++digits) {
      if (reads_back(with_digits(digits))) return with_digits(digits);
    }
  }
  // Prefer the short form when it round-trips (0.9 rather than 0.90000000000000002).
  const std::string shorter = with_digits(15);
  if (reads_back(shorter)) return shorter;
  std::ostringstream out;
  out << std::setprecision(std::numeric_limits<double>::max_digits10) << value;
  return out.str();
}

std::string format_rounded(double value, int digits) {
  std::ostringstream out;
  out << std::setprecision(digits) << value;
  return out.str();
}

void throw_invalid(const std::string& name, double value, const std::string& allowed) {
  throw std::invalid_argument(name + " = " + format_number(value) + " is invalid: must be " +
                              allowed);
}

void require_integer_in(const std::string& name, long long value, long long lo, long long hi) {
  if (value < lo || value > hi) {
    throw std::invalid_argument(name + " = " + std::to_string(value) +
                                " is invalid: must be an integer in [" + std::to_string(lo) +
                                ", " + std::to_string(hi) + "]");
  }
}

void require_finite(const std::string& name, double value) {
  if (!std::isfinite(value)) throw_invalid(name, value, "a finite number");
}

void require_open_interval(const std::string& name, double value, double lo, double hi) {
  require_finite(name, value);
  if (!(value > lo && value < hi)) {
    throw_invalid(name, value,
                  "in the open interval (" + format_number(lo) + ", " + format_number(hi) + ")");
  }
}

void require_positive(const std::string& name, double value, bool allow_zero) {
  require_finite(name, value);
  if (allow_zero ? !(value >= 0.0) : !(value > 0.0)) {
    throw_invalid(name, value, allow_zero ? ">= 0" : "> 0");
  }
}

}  // namespace kresling
