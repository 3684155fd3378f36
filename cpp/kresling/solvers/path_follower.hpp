#pragma once
/// \file path_follower.hpp
/// The incremental driver every stepped path shares: displacement control (equal
/// increments or MERLIN2's step control), force control, crease actuation (folding), the
/// arm's cable ramps, MGDCM (mgdcm.hpp) and any other control (path_control.hpp). A step
/// policy (step_policy.hpp) proposes each increment of the path parameter t; each is solved
/// by the control's corrector (PathControl::correct: by default a Newton solve of the
/// control's model with its held DOFs and external force at the new t; MGDCM's solves the
/// parameter with the displacements), from the previous equilibrium or an extrapolation
/// along the path. The follower records each converged increment, applies the caller's
/// check and stop rule, and tells the policy whether it was accepted. (Adaptive increments
/// with dense output, adaptive_path.hpp, follow the same controls.)
/// Time integration is the same loop with time as the parameter (time_control.hpp): its
/// control supplies each increment's extra terms (inertia and damping), its corrector and
/// hears each accepted increment (PathControl's hooks), its policy halves failed steps
/// (time_steps.hpp).

#include <functional>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/path_control.hpp"
#include "kresling/solvers/step_policy.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct FollowOptions {
  NewtonOptions newton;
  int max_bisections = 10;
  /// Each increment's start: 0 = the previous equilibrium, 1-3 = a linear, quadratic or
  /// cubic extrapolation through the last 2-4 equilibria (see DisplacementControlOptions),
  /// to the increment's prescribed end (not for a corrector that solves the parameter).
  int extrapolation = 0;
  /// > 0: Newton's budget per increment, and an increment needing that many iterations is
  /// rejected (MERLIN2's rule); 0: newton.max_iterations, and every converged increment is
  /// accepted.
  int reject_iterations = 0;
  /// Start each increment from the secant through the last two equilibria, scaled by the
  /// increments' sizes (u + size / previous size (u - u_previous)), instead of
  /// `extrapolation` (the arm's ramps).
  bool secant_start = false;
  /// A caller's check of each converged increment before it is accepted, at the control's
  /// model for the increment's end: the reason to reject it (empty: accept). A stability
  /// or state condition (the arm's: stable, every cell in its state).
  std::function<std::string(const Increment&, const VectorX& u, const NewtonOutcome&)> check;
  StopRule stop;                  ///< ends the path early (completed) when it returns true
  /// Terms added to every Newton solve (optional), unless the control supplies an
  /// increment's own (PathControl::extra_terms: a time step's inertia and damping).
  ExtraTerms* extra = nullptr;
  /// Where the path ends (an increment fails at its smallest size: past a limit point of
  /// the parameter, no equilibrium is near), let the structure snap: descend the energy at
  /// the failed increment's end from the last equilibrium to a stable one
  /// (energy_minimum.hpp), record it as a step (PathStep::snapped) and follow the path on
  /// from there. Up to kMaxSnapDofs free DOFs the descent is dense (minimize_energy),
  /// beyond it sparse (minimize_energy_sparse); a descent that finds no stable state ends
  /// the path as before, saying so.
  bool snap = false;
  /// Follow stable states: an increment whose Newton solve fails, ends at an unstable
  /// equilibrium (a negative eigenvalue) or is rejected by the check is relaxed whole: from
  /// the last equilibrium, the energy at the increment's end is descended to a stable state
  /// (stable_relaxation.hpp) in at most `relax_iterations` iterations, which is recorded as
  /// a step (PathStep::snapped). Where that finds none, the increment is halved and its
  /// parts are followed as without `relax` (unstable equilibria accepted), and so is the
  /// path after them until an accepted increment is stable again (no stable state was near
  /// the unstable stretch: each relaxation there would spend its whole budget to fail).
  /// Snaps (`snap`) relax too, with the snap's budget.
  bool relax = false;
  int relax_iterations = 200;
};

/// The largest model (free DOFs) whose snap descends with dense eigen-decompositions.
inline constexpr Index kMaxSnapDofs = 3000;

/// Follow `control` with the increments of `policy` from `u` (all DOFs; the accepted state at t = 0,
/// left at the last accepted one). `assembler` is bound to a workspace whose rows leave out
/// the supports and the control's held DOFs; it is rebound to the control's model at each
/// attempt when the control changes the model, and `solver` keeps its factorisation
/// between solves. Steps are appended to `result` (whose attempted increments count on);
/// its recorded DOFs and families are set here.
/// The caller's stop rule ends the path completed.
void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, StepPolicy& policy, const FollowOptions& options,
                 PathResult& result);

/// The same in `steps` equal increments with bisection (EqualIncrements, increments.hpp;
/// options.max_bisections).
void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, int steps, const FollowOptions& options, PathResult& result);

}  // namespace kresling::solvers
