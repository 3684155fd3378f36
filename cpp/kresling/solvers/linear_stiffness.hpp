#pragma once
/// \file linear_stiffness.hpp
/// The linearised (infinitesimal) bar-and-hinge model of Schenk and Guest: the tangent at a
/// state, which at a stress-free state is C^T diag(EA/L) C + J^T diag(k L0) J (Appendix A).

#include <vector>

#include <Eigen/Dense>

#include "kresling/assembly/assembler.hpp"
#include "kresling/model/model.hpp"

namespace kresling::solvers {

/// Full tangent stiffness (every DOF, supports ignored) at displacement u.
assembly::SparseMatrix tangent_matrix(const model::Model& model, const VectorX& u,
                                      double shift = 0.0);

/// Stiffness condensed onto `dofs` with the model's supports held and every other DOF free:
/// S = K_pp - K_pf K_ff^-1 K_fp, so that S u_p is the force needed to impose u_p.
/// Throws std::invalid_argument if a DOF is out of range, repeated or supported; returns a
/// matrix of NaN with `singular = true` if K_ff is singular (a mechanism).
Eigen::MatrixXd condensed_stiffness(const model::Model& model, const VectorX& u,
                                    const std::vector<Index>& dofs, bool* singular = nullptr);

}  // namespace kresling::solvers
