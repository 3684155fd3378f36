#pragma once
/// \file newton.hpp
/// Newton iterations for equilibrium on the free DOFs: f_int(u) = f_ext there, the other
/// DOFs held where they are.

#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;
  int negative_eigenvalues = -1;
  std::string failure;  ///< why not converged
};

/// Iterate from `u` (all DOFs, updated in place) until the correction's norm is at most
/// `options.tolerance`. `external` has one entry per DOF (only free rows are used).
/// After the first iteration, each iteration first computes its correction with the
/// tangent already factorised (a chord step); if it is below the tolerance and its product
/// with the previous correction is below tolerance^2 (so it is as accurate as a Newton
/// step), it is applied as the last one, saving a tangent assembly and factorisation;
/// otherwise a full Newton iteration follows. Iterations count applied corrections, as
/// MERLIN2 counts them.
/// `max_iterations` overrides options.max_iterations when > 0 (used to reject early).
NewtonOutcome newton_equilibrium(assembly::Assembler& assembler, TangentSolver& solver,
                                 VectorX& u, const VectorX& external,
                                 const NewtonOptions& options, int max_iterations = 0);

/// Gather the entries of a full-length vector at the assembler's rows.
VectorX gather_rows(const assembly::Assembler& assembler, const VectorX& full);
/// Add a row-indexed vector into the full-length vector at the assembler's rows.
void scatter_add_rows(const assembly::Assembler& assembler, const VectorX& reduced, VectorX& full);

/// Whether a recorded step holds only finite numbers (displacement, constraint forces,
/// energies). A solver accepts no step that does not: a state where an element's law is
/// singular (a hinge folded flat) fails its increment instead of ending a "completed" path
/// with NaN or 1e16 N forces.
bool finite_step(const PathStep& step);

/// Record a converged state as a path step: energies and the internal force re-evaluated
/// at `u` itself (not at the last iterate), the constrained DOFs' forces times `sign`.
PathStep record_step(assembly::Assembler& assembler, const VectorX& u, double load_factor,
                     const NewtonOutcome& outcome, const std::vector<Index>& constraint_dofs,
                     double sign);

}  // namespace kresling::solvers
