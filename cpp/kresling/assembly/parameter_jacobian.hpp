#pragma once
/// \file parameter_jacobian.hpp
/// The derivative of a model's internal force and energy with respect to one parameter
/// column of one of its families (model/parameter_derivative.hpp), gathered into a sparse
/// matrix: the right-hand sides of every sensitivity (solvers/sensitivity.hpp).

#include <string>

#include "kresling/assembly/workspace.hpp"
#include "kresling/core/types.hpp"
#include "kresling/model/model.hpp"

namespace kresling::assembly {

struct ParameterJacobian {
  /// d f_int / d theta at fixed positions, 3N x m (m: the column's entries, row-major by
  /// element as the family's table stores them) [force per unit of the parameter].
  SparseMatrix force;
  /// dE/dtheta, m entries [energy per unit of the parameter].
  VectorX energy;
};

/// The Jacobian of the column `parameter` of the family `family` of `model` at X + u.
/// Throws std::invalid_argument naming what is missing when the model has no such family or
/// the family no such parameter (and listing what there is).
ParameterJacobian parameter_jacobian(const model::Model& model, const VectorX& u,
                                     const std::string& family, const std::string& parameter);

}  // namespace kresling::assembly
