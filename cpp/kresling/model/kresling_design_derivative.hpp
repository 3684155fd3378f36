#pragma once
/// \file kresling_design_derivative.hpp
/// The derivative of a Kresling specimen (kresling_specimen.hpp) with respect to one design
/// variable: how its reference node positions and its elements' parameters move. With the
/// shape and parameter Jacobians (assembly/shape_jacobian.hpp, parameter_jacobian.hpp) it
/// gives the derivative of any of the specimen's equilibria by the design.
///
/// The specimen is built stress-free in its states, so every rest length, hinge length and
/// rest angle follows the positions; only the positions need the chain rule:
///
///   level k:  z_k = sum_{i<k} height(state_i),   theta_k = sum_{i<k} c_i twist(state_i)
///   node j:   X = (R cos a, R sin a, z_k),  a = theta_k + 2 pi j / n;  centre (0, 0, z_k)
///
/// differentiated through geometry::state_derivative. The material variables:
///
///   kf         every hinge's stiffness is a factor times kf and every bar's modulus
///              modulus_factor kf: both linear in kf.
///   modulus_factor  the bars' modulus over kf (the thesis's 1e5): a material's own
///              ratio, fitted to records beside kf.
///   thickness  the facet sheet's thickness t, at the thesis's t0 = 0.25 mm: a sheet's
///              membrane stiffness grows like t and its plate bending like t^3, so every
///              bar's area scales with t and the polygon spokes' hinges (the facets' bending)
///              with t^3; the creases (kf) are the hinge sheet's and do not change.

#include <string>
#include <vector>

#include "kresling/geometry/design.hpp"
#include "kresling/model/kresling_specimen.hpp"

namespace kresling::model {

/// The thesis's facet sheet [mm] (a 0.25 mm PET layer), where the specimen's stiffness
/// ratios hold: the reference of the thickness derivative.
inline constexpr double kFacetThickness = 0.25;

struct SpecimenDesignDerivative {
  VectorX positions;        ///< dX/dv, 3N, node-major [mm per unit of v]
  VectorX bar_area;         ///< d area / dv per bar [mm^2 per unit]
  VectorX bar_modulus;      ///< d modulus / dv per bar
  VectorX hinge_stiffness;  ///< d stiffness / dv per hinge
};

/// The derivative of `specimen` (built from `design` with `states`, `chirality` and
/// `parameters`) by `variable`: "lam", "Lc", "R", "thickness", "kf" or
/// "modulus_factor". Throws
/// std::invalid_argument for any other name or lists that do not match the specimen.
SpecimenDesignDerivative specimen_design_derivative(const KreslingSpecimen& specimen,
                                                    const geometry::Design& design,
                                                    const std::vector<int>& states,
                                                    const std::vector<int>& chirality,
                                                    const SpecimenParameters& parameters,
                                                    const std::string& variable);

}  // namespace kresling::model
