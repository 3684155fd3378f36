#pragma once
/// \file energy_minimum.hpp
/// Descend to a stable equilibrium (a local minimum of the potential energy: the strain
/// energy less the work of a constant external load, none by default) of a small model:
/// where a structure released at `u` comes to rest.
///
/// Newton's method finds any equilibrium, saddles included; this finds minima. Each
/// iteration takes the "saddle-free" Newton step -|K|^-1 g, with |K| = V |Lambda| V^T the
/// free tangent with its eigenvalues replaced by their magnitudes (floored at
/// `min_curvature`), so every step descends; a backtracking line search on the energy
/// (Armijo) accepts it. At a saddle (g = 0 but a negative eigenvalue) it steps `escape_step`
/// along the eigenvector of the most negative eigenvalue. Converged when the step is at most
/// `tolerance` and the free tangent is positive definite. Dense eigen-decompositions: for
/// models of up to a few hundred free DOFs (a snap-through cell has 3 (n + 1)).

#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct EnergyMinimumOptions {
  double tolerance = 1e-8;      ///< on the 2-norm of the last step [mm]
  int max_iterations = 200;
  double escape_step = 0.05;    ///< length of the step out of a saddle [mm]
  double min_curvature = 1e-8;  ///< floor of |eigenvalue| in the step [N/mm]
  /// Longest step [mm]: longer ones are shortened to it, so that the descent follows the
  /// energy landscape instead of leaping into another basin where the local model is poor.
  double max_step = 0.5;
};

struct EnergyMinimum {
  bool converged = false;
  int iterations = 0;
  double energy = 0.0;               ///< potential energy at the end [N mm]
  int negative_eigenvalues = -1;     ///< of the free tangent at the end
  double smallest_eigenvalue = 0.0;  ///< of the free tangent at the end [N/mm]
  std::string failure;               ///< why not converged
};

/// Throws std::invalid_argument unless a descent's tolerance, longest step and escape step
/// [mm] are > 0 and its budget of iterations >= 1 (every descent's options).
void check_descent(double tolerance, double max_step, double escape_step, int max_iterations);

/// Descend from `u` (all DOFs, updated in place) on the assembler's rows (its other DOFs
/// stay where they are). The assembler should store the full matrix with no diagonal shift
/// (a shift would hide a zero-stiffness mode from the inertia). `external` (optional, one
/// entry per DOF) is a constant load whose work f . u is taken off the strain energy.
EnergyMinimum minimize_energy(assembly::Assembler& assembler, VectorX& u,
                              const EnergyMinimumOptions& options = {},
                              const VectorX* external = nullptr);

/// The same descent for models of any size, on sparse factorisations: each step is
/// -(K + mu I)^-1 g with the smallest shift mu (0, else doubled from 1e-6 of the tangent's
/// largest diagonal entry) whose Cholesky exists, so every step descends; the same
/// backtracking line search and longest step. Converged when the step is at most
/// `tolerance` with no shift (the tangent itself positive definite: a stable equilibrium).
/// It has no eigenvectors to leave an exact saddle by (`escape_step` unused): a descent
/// that stops at one fails. `solver` is the caller's (its pattern the assembler's);
/// negative_eigenvalues is 0 at a converged end, else -1; smallest_eigenvalue is not
/// computed (0).
EnergyMinimum minimize_energy_sparse(assembly::Assembler& assembler, TangentSolver& solver,
                                     VectorX& u, const EnergyMinimumOptions& options = {},
                                     const VectorX* external = nullptr);

}  // namespace kresling::solvers
