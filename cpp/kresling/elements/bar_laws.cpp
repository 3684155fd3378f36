#include "kresling/elements/bar_laws.hpp"

#include <stdexcept>
#include <string>

namespace kresling::elements {

StressResponse linear_bar_law(double modulus, double strain) {
  return {modulus * strain, modulus, 0.5 * modulus * strain * strain};
}

StressResponse ogden_bar_law(double modulus, double s) {
  const double c = 0.25 * modulus;
  const double s2 = s * s;
  const double s3 = s2 * s;
  StressResponse r;
  r.stress = c * (s3 - 1.0 / s);
  r.modulus = c * (3.0 * s + 1.0 / s3);
  // (s^5 - 1)/5 - (s - 1) = (s - 1)^2 (s^3 + 2 s^2 + 3 s + 4) / 5: no cancellation near s = 1.
  const double d = s - 1.0;
  r.energy_density = c * d * d * (s3 + 2.0 * s2 + 3.0 * s + 4.0) / 5.0;
  return r;
}

StressResponse BarLaw::evaluate(double strain, double stretch) const {
  if (kind == BarLawKind::Linear) return linear_bar_law(modulus, strain);
  return ogden_bar_law(modulus, stretch);
}

BarLawKind bar_law_kind(long long code, const char* name) {
  if (code != static_cast<long long>(BarLawKind::Linear) &&
      code != static_cast<long long>(BarLawKind::Ogden)) {
    throw std::invalid_argument(std::string(name) + " = " + std::to_string(code) +
                                " is not a bar law code (see kresling.laws.BAR_LAWS)");
  }
  return static_cast<BarLawKind>(code);
}

}  // namespace kresling::elements
