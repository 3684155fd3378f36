#pragma once
/// \file stable_relaxation.hpp
/// Relax a structure of any size to a stable equilibrium (a local minimum of its potential
/// energy) on sparse factorisations: where a sheet released at `u` comes to rest, found in
/// about as many factorisations as Newton needs where Newton converges.
///
/// Each iteration solves (K + mu I) p = -g on the assembler's rows, K the tangent and g the
/// out-of-balance force, with a shift mu >= 0 for which K + mu I has a Cholesky
/// factorisation (raised by 4, from 1e-6 of K's largest diagonal entry, until it has one):
/// p descends even
/// where K is indefinite, and leans on its negative-curvature directions. p is held to a
/// trust region's radius (from `max_step`; doubled after a good step it was held by, up to
/// 100 times that; cut to a quarter of the step after a poor one) and taken when the
/// energy falls by at least a tenth of what the quadratic model E + g.p + p.K.p / 2
/// predicts, after one chord step with the same factorisation from the step's end (which
/// takes back the stiff bars' stretch along a straight step where the mechanism turns). A
/// good step (three quarters of the predicted fall) divides mu by 4 (to 0 below 1e-9 of the
/// largest diagonal entry): where K is positive definite the steps are Newton's, converging
/// quadratically to the same equilibrium. Where the steps vanish but K is not positive
/// definite (a saddle, which a symmetric sheet can descend into exactly), a few inverse
/// iterations with the shifted factorisation give the direction of the most negative
/// curvature, and a step of `escape_step` along it (the sign of lower energy, halved until
/// lower) leaves the saddle. Converged when the unshifted step is at most
/// `tolerance` and K itself has a Cholesky factorisation (a stable equilibrium).

#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct RelaxationOptions {
  double tolerance = 1e-6;     ///< on the 2-norm of the last, unshifted step [mm]
  int max_iterations = 300;    ///< steps tried and shifts tried
  double max_step = 0.5;       ///< longest step [mm] (a trust region's largest radius)
  double escape_step = 0.05;   ///< length of the step out of a saddle [mm]
};

struct Relaxation {
  bool converged = false;
  int iterations = 0;      ///< steps tried and shifts tried
  int steps = 0;           ///< steps taken (each lowered the energy)
  double energy = 0.0;     ///< potential energy at the end [N mm]
  std::string failure;     ///< why not converged
};

/// Relax from `u` (all DOFs, updated in place) on the assembler's rows (its other DOFs stay
/// where they are). `solver`'s pattern must be the assembler's (its symbolic analysis is
/// reused). `external` (optional, one entry per DOF) is a constant load whose work f . u is
/// taken off the strain energy. Throws std::invalid_argument for non-positive options.
Relaxation relax_to_stable(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                           const RelaxationOptions& options = {},
                           const VectorX* external = nullptr);

}  // namespace kresling::solvers
