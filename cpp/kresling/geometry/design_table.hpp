#pragma once
/// \file design_table.hpp
/// Derived quantities of many designs in one call (e.g. a 100 x 100 sweep grid).

#include <cstddef>

#include "kresling/geometry/design.hpp"

namespace kresling::geometry {

/// Evaluate `count` designs. Inputs are arrays of length `count`; `out` is row-major
/// (count, kDerivedNames.size()). All designs are validated before any is evaluated, and
/// the first invalid one throws std::invalid_argument naming its index, e.g. "lam[12]".
void derive_table(const int* n, const double* R, const double* lam, const double* Lc,
                  std::size_t count, double* out);

}  // namespace kresling::geometry
