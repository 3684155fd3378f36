#include "kresling/core/check.hpp"

#include <iomanip>
#include <limits>

namespace kresling {

std::string format_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out << std::setprecision(std::numeric_limits<double>::max_digits10) << value;
  // Prefer the short form when it round-trips (0.9 rather than 0.90000000000000002).
  std::ostringstream shorter;
  shorter << std::setprecision(15) << value;
  if (std::stod(shorter.str()) == value) return shorter.str();
  return out.str();
}

void throw_invalid(const std::string& name, double value, const std::string& allowed) {
  throw std::invalid_argument(name + " = " + format_number(value) + " is invalid: must be " +
                              allowed);
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
