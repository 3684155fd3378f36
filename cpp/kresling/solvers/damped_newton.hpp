#pragma once
/// \file damped_newton.hpp
/// Newton with every correction scaled by a damping factor below 1, as MERLIN2 iterates
/// after ten rejected increments in a row (merlin2_steps.hpp).

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

/// Iterate from `u` (all DOFs, updated in place) with corrections damping * du, at most
/// options.max_iterations times; converged once an undamped correction du is <=
/// options.tolerance. No external force (MERLIN2 damps displacement control only). Each
/// damped correction is shortened further to what the model's barriers allow
/// (barrier_step_fraction), as Newton's are.
NewtonOutcome damped_newton(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                            const NewtonOptions& options, double damping);

}  // namespace kresling::solvers
