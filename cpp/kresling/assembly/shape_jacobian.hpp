#pragma once
/// \file shape_jacobian.hpp
/// The derivative of a model's internal force and energy with respect to its reference node
/// positions X, at a fixed displacement u: the right-hand side of a shape sensitivity
/// (moving a crease pattern's vertices, or a Kresling cell's radius and heights).
///
/// The positions are x = X + u, so moving X at fixed u moves x with it: that part is the
/// tangent K(u). A model built stress-free in X stays stress-free in the moved X: every rest
/// value that holds the reference geometry (ElementFamily::reference_geometry_derivative: a
/// bar's rest length, a hinge's rest angle and length, a face's corner angles) follows it,
/// which adds G_c R_c per such column c (G_c its parameter Jacobian, R_c = d theta_c / dX):
///
///     d f_int / dX = K(u) + sum_c G_c R_c,        dE/dX = f_int(u) + sum_c R_c^T dE/dtheta_c.
///
/// Rest values set to anything else (a fold's target angle, a cable's pulled length) stay.

#include <string>

#include "kresling/assembly/workspace.hpp"
#include "kresling/core/types.hpp"
#include "kresling/model/model.hpp"

namespace kresling::assembly {

struct ShapeJacobian {
  /// d f_int / dX at fixed u, 3N x 3N [force per length].
  SparseMatrix force;
  /// dE / dX at fixed u, 3N [energy per length].
  VectorX energy;
};

/// R_c = d theta_c / dX of the column `column` of the family `family` (m x 3N): the rows of
/// the entries that hold the reference geometry; zero rows for the others. It depends on X
/// alone, so a path computes it once. Throws std::invalid_argument for a family or column
/// the model does not have.
SparseMatrix reference_geometry_jacobian(const model::Model& model, const std::string& family,
                                         const std::string& column);

/// The shape Jacobian of `model` at X + u (u: 3N entries; throws std::invalid_argument
/// otherwise).
ShapeJacobian shape_jacobian(const model::Model& model, const VectorX& u);

}  // namespace kresling::assembly
