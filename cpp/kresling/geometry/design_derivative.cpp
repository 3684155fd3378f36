#include "kresling/geometry/design_derivative.hpp"

#include <cmath>
#include <stdexcept>

namespace kresling::geometry {

DesignVariable design_variable(const std::string& name) {
  if (name == "lam") return DesignVariable::Lam;
  if (name == "Lc") return DesignVariable::Lc;
  if (name == "R") return DesignVariable::R;
  throw std::invalid_argument("design variable '" + name +
                              "' is invalid: must be one of lam, Lc, R");
}

StateDerivative state_derivative(const Design& design, State state, DesignVariable variable) {
  const DesignParameters& p = design.parameters();
  const DerivedQuantities& d = design.derived();
  StateDerivative r;
  if (state == State::Contracted) {
    if (variable == DesignVariable::Lc) r.height = 1.0;
    if (variable == DesignVariable::Lam) r.twist = 2.0 * d.gamma;
    return r;
  }
  const double Le = d.Le;
  const double arc = d.gamma * (2.0 * p.lam - 1.0);
  switch (variable) {
    case DesignVariable::Lam:
      r.height = 4.0 * p.R * p.R * d.gamma * std::cos(arc) * std::cos(d.phi) / Le;
      r.twist = -2.0 * d.gamma;
      break;
    case DesignVariable::Lc:
      r.height = p.Lc / Le;
      break;
    case DesignVariable::R:
      r.height = 4.0 * p.R * std::sin(arc) * std::cos(d.phi) / Le;
      break;
  }
  return r;
}

}  // namespace kresling::geometry
