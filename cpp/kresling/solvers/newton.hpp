#pragma once
/// \file newton.hpp
/// Newton iterations for equilibrium on the free DOFs: f_int(u) = f_ext there, the other
/// DOFs held where they are.

#include <string>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

/// Terms a solve adds to the model's own equilibrium (a time step's inertia and damping,
/// contact barriers): a force at every iterate, a tangent contribution, and a limit on each
/// correction (a barrier must never be stepped across). Newton calls them at every iterate,
/// right after assembling the model.
class ExtraTerms {
 public:
  virtual ~ExtraTerms() = default;
  /// Add the terms' force at u (one entry per DOF, like the internal force) to `force`.
  virtual void add_force(const VectorX& u, VectorX& force) = 0;
  /// Add their tangent at u into the tangent just assembled in `workspace` (its pattern:
  /// Workspace::add_to_diagonal, scale_matrix).
  virtual void add_tangent(const VectorX& u, assembly::Workspace& workspace) = 0;
  /// The fraction in (0, 1] of the correction du (one entry per DOF) that may be taken
  /// from u; 1 takes all of it.
  virtual double step_limit(const VectorX& /*u*/, const VectorX& /*du*/) { return 1.0; }
};

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
/// `extra` (optional) adds its force and tangent at every iterate and may shorten each
/// correction (then the full correction's size still decides convergence).
NewtonOutcome newton_equilibrium(assembly::Assembler& assembler, TangentSolver& solver,
                                 VectorX& u, const VectorX& external,
                                 const NewtonOptions& options, int max_iterations = 0,
                                 ExtraTerms* extra = nullptr);

/// The largest fraction in [0, 1] of the move `du` from `u` (one entry per DOF each) that
/// no family of the model that limits steps (a contact barrier) lets a pair cross along;
/// 1 when no family limits steps. Every move of a solver (a Newton correction, a time
/// step's predictor, a path's extrapolated start, a line search's step) is shortened by it.
double barrier_step_fraction(const model::Model& model, const VectorX& u, const VectorX& du);

/// Whether any element family of the model limits each move (a contact barrier).
bool families_limit_steps(const model::Model& model);

/// Add the correction `du` (one entry per assembled row) to `u` (all DOFs), shortened to
/// what the model's barriers allow when `limited` (families_limit_steps of the model);
/// returns the fraction of it taken (1 when not limited). Every corrector's update.
double add_correction_within_barriers(const assembly::Assembler& assembler, const VectorX& du,
                                      VectorX& u, bool limited);

/// Shorten the move from `from` to `to` (all DOFs) to the fraction barrier_step_fraction
/// allows; `to` is left as it is when the model has no barrier or the whole move is allowed.
void shorten_to_barriers(const model::Model& model, const VectorX& from, VectorX& to);

/// An increment's start under a drive that sets the DOFs it holds (a prescribed
/// displacement): the barriers cannot shorten that move, so it is checked on its own.
/// Returns false when moving only the `held` DOFs from their values in `from` to those in
/// `start` (all DOFs each) would close a pair past what barrier_step_fraction allows (the
/// drive would carry panels into or through each other within the increment); otherwise
/// shortens the free DOFs' part of the start, from there, as shorten_to_barriers does, and
/// returns true. Without a barrier in the model, or with no held DOF, nothing is done.
bool start_within_barriers(const model::Model& model, const VectorX& from, VectorX& start,
                           const std::vector<Index>& held);

/// The failure of an increment whose held move is blocked (start_within_barriers).
extern const char* const kHeldMoveBlocked;

/// Before factorising the tangent just assembled: tell `solver` its pattern when the model
/// has a family whose elements change with the state (contact pairs), so that a new pattern
/// is analysed anew; nothing otherwise.
void follow_pattern(assembly::Assembler& assembler, TangentSolver& solver);

/// Factorise the tangent just assembled at `u` (the model's, with `extra`'s terms added, its
/// force in `force`), its pattern first told to `solver` (follow_pattern). Where a family
/// adapts its tangent (ElementFamily::adapts_tangent: contact pairs' exact Hessians) and
/// that tangent is not positive definite, the tangent is assembled again at `u` with those
/// families' positive semi-definite forms (`force` and `extra`'s terms again too) and that
/// one is factorised: Newton's exact Jacobian where the structure is stable, a definite
/// tangent where the exact one would steer toward an unstable equilibrium.
FactorizeInfo factorize_tangent(assembly::Assembler& assembler, TangentSolver& solver,
                                const VectorX& u, VectorX& force, ExtraTerms* extra = nullptr);

/// Gather the entries of a full-length vector at the assembler's rows.
VectorX gather_rows(const assembly::Assembler& assembler, const VectorX& full);
/// Add a row-indexed vector into the full-length vector at the assembler's rows.
void scatter_add_rows(const assembly::Assembler& assembler, const VectorX& reduced, VectorX& full);

/// The names of the model's element families, in its order (PathResult::families).
std::vector<std::string> family_names(const model::Model& model);

/// Why a converged increment whose recorded step is not finite (finite_step) is refused.
inline constexpr const char* kStepNotFinite =
    "the converged state's internal force or energy is not finite (an element's law is "
    "singular there, e.g. a hinge folded flat)";

/// Whether a recorded step holds only finite numbers (displacement, constraint forces,
/// energies). A solver accepts no step that does not: a state where an element's law is
/// singular (a hinge folded flat) fails its increment instead of ending a "completed" path
/// with NaN or 1e16 N forces.
bool finite_step(const PathStep& step);

/// Record a converged state as a path step: energies and the internal force re-evaluated
/// at `u` itself (not at the last iterate), the constrained DOFs' forces times `sign`.
/// `internal` (optional) receives that internal force (one entry per DOF).
PathStep record_step(assembly::Assembler& assembler, const VectorX& u, double load_factor,
                     const NewtonOutcome& outcome, const std::vector<Index>& constraint_dofs,
                     double sign, VectorX* internal = nullptr);

}  // namespace kresling::solvers
