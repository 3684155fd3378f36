#pragma once
/// \file bar_laws.hpp
/// Constitutive laws of bars in terms of the Green-Lagrange strain E = (l^2 - L^2) / (2 L^2).
/// A law gives the second Piola-Kirchhoff stress S(E), its derivative dS/dE and the energy
/// density W(E) (dW/dE = S); a bar of area A and rest length L stores A L W.

namespace kresling::elements {

/// Value of a bar law at one strain.
struct StressResponse {
  double stress = 0.0;          ///< S [force / area]
  double modulus = 0.0;         ///< dS/dE
  double energy_density = 0.0;  ///< W [energy / volume]
};

enum class BarLawKind : int {
  Linear = 0,  ///< S = C0 E (Saint Venant-Kirchhoff)
  Ogden = 1,   ///< MERLIN2's Ogden law with exponents (5, 1)
};

/// A bar law and its modulus C0 (EA per unit area; the thesis uses C0 = 1e5 kf).
/// The law of `code` (a BarLawKind's value); throws std::invalid_argument naming `name`
/// for any other number.
BarLawKind bar_law_kind(long long code, const char* name);

struct BarLaw {
  BarLawKind kind = BarLawKind::Ogden;
  double modulus = 0.0;

  /// Response at Green-Lagrange strain E and stretch s = l / L = sqrt(2 E + 1) > 0 (both
  /// given, so that each law uses the one it is accurate in).
  StressResponse evaluate(double strain, double stretch) const;
};

/// Linear law: S = C0 E, dS/dE = C0, W = C0 E^2 / 2.
StressResponse linear_bar_law(double modulus, double strain);

/// Ogden law, exponents (5, 1), in the stretch s:
/// S = C0/4 (s^3 - 1/s), dS/dE = C0/4 (3 s + s^-3), W = C0/4 ((s^5 - 1)/5 - (s - 1)).
/// Its small-strain modulus is C0, like the linear law's.
StressResponse ogden_bar_law(double modulus, double stretch);

}  // namespace kresling::elements
