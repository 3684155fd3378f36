#include "kresling/geometry/design_table.hpp"

#include <string>

namespace kresling::geometry {

void derive_table(const int* n, const double* R, const double* lam, const double* Lc,
                  std::size_t count, double* out) {
  for (std::size_t i = 0; i < count; ++i) {
    validate(DesignParameters{n[i], R[i], lam[i], Lc[i], 1}, "[" + std::to_string(i) + "]");
  }
  constexpr std::size_t width = kDerivedNames.size();
  for (std::size_t i = 0; i < count; ++i) {
    const auto row = derived_as_array(derive(DesignParameters{n[i], R[i], lam[i], Lc[i], 1}));
    for (std::size_t k = 0; k < width; ++k) out[i * width + k] = row[k];
  }
}

}  // namespace kresling::geometry
