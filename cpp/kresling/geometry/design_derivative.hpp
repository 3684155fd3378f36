#pragma once
/// \file design_derivative.hpp
/// How a cell's stable states move with its design: the derivatives of the height and the
/// twist of each state with respect to lambda, Lc and R (docs/thesis_equations.md,
/// 'Geometry'), the first link of the chain rule from a design to its bending stiffness.
///
/// With gamma = pi (n - 2) / (2 n) and phi = pi / n (fixed by n):
///
///     contracted:  height Lc,   twist alpha0  = 2 lam gamma
///     extended:    height Le,   twist alpha_e = 2 gamma (1 - lam),
///                  Le^2 = Lc^2 + 4 R^2 sin(gamma (2 lam - 1)) cos(phi)
///
/// so that dLe/dLc = Lc / Le, dLe/dR = 4 R sin(gamma (2 lam - 1)) cos(phi) / Le and
/// dLe/dlam = 4 R^2 gamma cos(gamma (2 lam - 1)) cos(phi) / Le (Le > 0 for every valid
/// design: lam > 1/2 makes the sine positive).

#include <string>

#include "kresling/geometry/design.hpp"

namespace kresling::geometry {

/// The design variables a cell's geometry depends on continuously.
enum class DesignVariable { Lam, Lc, R };

/// "lam", "Lc" or "R" as a DesignVariable; throws std::invalid_argument naming the others.
DesignVariable design_variable(const std::string& name);

struct StateDerivative {
  double height = 0.0;  ///< d height / dv [mm per unit of v]
  double twist = 0.0;   ///< d twist / dv [rad per unit of v] (unsigned, as Design::twist)
};

/// The derivative of `design`'s height and twist in `state` with respect to `variable`.
StateDerivative state_derivative(const Design& design, State state, DesignVariable variable);

}  // namespace kresling::geometry
