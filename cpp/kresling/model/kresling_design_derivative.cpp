#include "kresling/model/kresling_design_derivative.hpp"

#include <cmath>
#include <stdexcept>

#include "kresling/geometry/design_derivative.hpp"

namespace kresling::model {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

VectorX positions_derivative(const KreslingSpecimen& s, const geometry::Design& design,
                             const std::vector<int>& states, const std::vector<int>& chirality,
                             geometry::DesignVariable variable) {
  const int n = s.n;
  const double R = design.parameters().R;
  const double dR = variable == geometry::DesignVariable::R ? 1.0 : 0.0;
  VectorX dX = VectorX::Zero(s.model.num_dofs());
  double dz = 0.0, dtheta = 0.0;
  for (int k = 0; k <= s.cells; ++k) {
    if (k > 0) {
      const auto state = static_cast<geometry::State>(states[k - 1]);
      const geometry::StateDerivative d = geometry::state_derivative(design, state, variable);
      dz += d.height;
      dtheta += chirality[k - 1] * d.twist;
    }
    for (int j = 0; j < n; ++j) {
      const double a = s.level_angle[k] + kTwoPi * j / n;
      const Index i = 3 * s.node(k, j);
      dX[i] = dR * std::cos(a) - R * std::sin(a) * dtheta;
      dX[i + 1] = dR * std::sin(a) + R * std::cos(a) * dtheta;
      dX[i + 2] = dz;
    }
    dX[3 * s.node(k, n) + 2] = dz;
  }
  return dX;
}

}  // namespace

SpecimenDesignDerivative specimen_design_derivative(const KreslingSpecimen& s,
                                                    const geometry::Design& design,
                                                    const std::vector<int>& states,
                                                    const std::vector<int>& chirality,
                                                    const SpecimenParameters& p,
                                                    const std::string& variable) {
  if (static_cast<int>(states.size()) != s.cells || static_cast<int>(chirality.size()) != s.cells) {
    throw std::invalid_argument("states and chirality: need one entry per cell of the specimen (" +
                                std::to_string(s.cells) + ")");
  }
  if (design.parameters().n != s.n) {
    throw std::invalid_argument("design.n = " + std::to_string(design.parameters().n) +
                                " is not the specimen's n = " + std::to_string(s.n));
  }
  const auto bars = static_cast<Index>(s.bar_family.size());
  const auto hinges = static_cast<Index>(s.hinge_family.size());
  SpecimenDesignDerivative d{VectorX::Zero(s.model.num_dofs()), VectorX::Zero(bars),
                             VectorX::Zero(bars), VectorX::Zero(hinges)};
  if (variable == "kf") {
    // Every hinge's stiffness and every bar's modulus is a factor times kf.
    d.bar_modulus.setConstant(p.modulus_factor);
    for (Index h = 0; h < hinges; ++h) d.hinge_stiffness[h] = hinge_factor(s.hinge_family[h], p);
  } else if (variable == "modulus_factor") {
    // Every bar's modulus is modulus_factor kf.
    d.bar_modulus.setConstant(p.kf);
  } else if (variable == "thickness") {
    // Membrane stiffness ~ t (every bar's area), the facets' bending ~ t^3 (the spokes).
    for (Index b = 0; b < bars; ++b) {
      const double area = s.bar_family[b] == EdgeFamily::Mountain ? p.mountain_area : p.material_area;
      d.bar_area[b] = area / kFacetThickness;
    }
    for (Index h = 0; h < hinges; ++h) {
      if (s.hinge_family[h] == EdgeFamily::PolygonSpoke) {
        d.hinge_stiffness[h] = 3.0 * hinge_factor(s.hinge_family[h], p) * p.kf / kFacetThickness;
      }
    }
  } else if (variable == "lam" || variable == "Lc" || variable == "R") {
    d.positions = positions_derivative(s, design, states, chirality,
                                       geometry::design_variable(variable));
  } else {
    throw std::invalid_argument("design variable '" + variable +
                                "' is invalid: must be one of lam, Lc, R, thickness, kf, "
                                "modulus_factor");
  }
  return d;
}

}  // namespace kresling::model
