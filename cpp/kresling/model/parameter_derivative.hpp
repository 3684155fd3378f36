#pragma once
/// \file parameter_derivative.hpp
/// What a family gives for sensitivities: the derivative of its internal force and stored
/// energy with respect to one real column of its table (its elements' parameters: a bar's
/// modulus, area or rest length, a hinge's stiffness, rest angle or length, ...), at a
/// state X + u.
///
/// A column of `width` values per element has entries j = width e + k (row-major, as
/// table() stores them). The force derivative is a sparse 3N x m matrix G with
/// G(i, j) = d f_i / d theta_j, kept as triplets (every element adds its local vector, as
/// assembly adds forces); the energy derivative is dense, dE/dtheta_j. Both are partial
/// derivatives at fixed positions: the sensitivity of an equilibrium follows from them and
/// the tangent (solvers/sensitivity.hpp).

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/SparseCore>

#include "kresling/core/types.hpp"

namespace kresling::model {

/// Whether a rest value `value` holds the reference geometry's `geometric` value: equal to
/// within rounding of the computation that made it (relative 1e-9, at least 1e-12 absolute),
/// so that a model built stress-free in its reference positions is recognised as such.
inline bool holds_reference_geometry(double value, double geometric) {
  const double scale = std::max(std::abs(value), std::abs(geometric));
  return std::abs(value - geometric) <= 1e-9 * scale + 1e-12;
}

struct ParameterDerivative {
  using Triplet = Eigen::Triplet<double, int>;
  /// (DOF, entry, d f_DOF / d theta_entry); repeated pairs are summed.
  std::vector<Triplet> force;
  /// dE/dtheta per entry of the column [energy per unit of the parameter].
  VectorX energy;

  /// Clear and size for a column of `entries` values.
  void reset(Index entries) {
    force.clear();
    energy = VectorX::Zero(entries);
  }
  /// Add an element's local force derivative `local` (its DOFs `dofs`, in order) for
  /// entry `entry`, and its energy derivative.
  template <typename Local, typename Dofs>
  void add(Index entry, const Local& local, const Dofs& dofs, double energy_derivative) {
    for (std::size_t a = 0; a < dofs.size(); ++a) {
      const double v = local[static_cast<Index>(a)];
      if (v != 0.0) force.emplace_back(static_cast<int>(dofs[a]), static_cast<int>(entry), v);
    }
    energy[entry] += energy_derivative;
  }
};

}  // namespace kresling::model
