#pragma once
/// \file rigid_body.hpp
/// Check that supports (and imposed DOFs) block every rigid-body motion of the model. The
/// tangent is shifted by 1e-8 I (MERLIN2's regularisation), so an unconstrained structure
/// would otherwise "solve" with enormous displacements instead of failing.

#include <cstdint>
#include <vector>

#include "kresling/model/model.hpp"

namespace kresling::solvers {

/// Throw std::invalid_argument when the DOFs marked in `held` (one entry per DOF) leave a
/// zero-stiffness motion that is visible without solving: a rigid-body motion of the whole
/// model (named: translations along and rotations about x, y, z), or a node with a free DOF
/// that no bar is attached to. DOFs an element family ties to the ground
/// (ElementFamily::mark_grounded_dofs) count as held.
void require_rigid_body_constrained(const model::Model& model,
                                    const std::vector<std::uint8_t>& held);

}  // namespace kresling::solvers
