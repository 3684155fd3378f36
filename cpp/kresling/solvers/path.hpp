#pragma once
/// \file path.hpp
/// What every nonlinear solver returns: the equilibrium path, step by step, and how it
/// ended. Numerical outcomes (a Newton failure, an exhausted step budget, a singular
/// tangent) end the path with a reason; they are never thrown.

#include <functional>
#include <string>
#include <vector>

#include "kresling/core/types.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

/// Newton iteration controls (docs/model.md, 'Solvers': ||du_free||_2 <= 1e-6, at most 50
/// iterations).
struct NewtonOptions {
  double tolerance = 1e-6;   ///< on the 2-norm of the free-DOF correction [mm]
  int max_iterations = 50;
  /// Which Cholesky factorises positive definite tangents (Auto: by the measured cost
  /// model). The others are for comparisons: near a bifurcation the branch a path takes is
  /// decided by rounding, which differs from one factorisation to another.
  CholeskyChoice cholesky = CholeskyChoice::Auto;
  /// > 0: a solve whose correction at this iteration or any later one is still above
  /// kGiveUpRatio times its first correction ends there, not converged (its caller halves
  /// the increment), instead of wandering on to max_iterations; 0: never.
  int give_up_after = 0;
  /// > 0: a solve whose correction grows to more than this many times its first ends
  /// there, not converged: the iterates wander off from the start instead of closing in on
  /// an equilibrium near it (for callers with a more robust fallback, such as a
  /// relaxation); 0: never.
  double give_up_wandering = 0.0;
};

/// What NewtonOptions::give_up_after asks of a solve's corrections by then.
inline constexpr double kGiveUpRatio = 1e-3;

/// One converged equilibrium point of a path.
struct PathStep {
  double load_factor = 0.0;   ///< lambda (force control) or fraction of the prescribed motion
  VectorX displacement;       ///< all DOFs
  VectorX constraint_force;   ///< internal force at the constrained DOFs (see PathResult)
  /// Stored energy of each element family, in the order of the model's families()
  /// (PathResult::families names them) [N mm].
  VectorX energies;
  int iterations = 0;
  /// Negative eigenvalues of the free tangent factorised in the step's last iteration:
  /// 0 = stable equilibrium; -1 = unknown (the tangent needed an LU factorisation).
  int negative_eigenvalues = -1;
  /// Reached by a snap (FollowOptions::snap): where the path the step before it was on
  /// ended, an energy descent at this step's parameter from that step's state, not a
  /// continuation of it.
  bool snapped = false;

  /// The total stored energy (the families' energies summed in order).
  double energy() const {
    double sum = 0.0;
    for (Index i = 0; i < energies.size(); ++i) sum += energies[i];
    return sum;
  }
};

/// A converged point of an adaptive path that samples were read from (its cubic Hermite
/// curves): kept when asked (AdaptiveOptions::keep_knots), for the path's sensitivities.
struct PathKnot {
  double t = 0.0;    ///< the path parameter (load factor or fraction of the motion)
  VectorX u;         ///< all DOFs
  VectorX velocity;  ///< du/dt, all DOFs (at the held ones, the control's motion)
};

/// A caller's stopping rule, asked after every accepted step: true ends the path there
/// (completed). An empty rule never stops.
using StopRule = std::function<bool(const PathStep&)>;

struct PathResult {
  std::vector<PathStep> steps;
  /// DOFs whose forces `constraint_force` lists: the imposed DOFs under displacement
  /// control (the force the structure exerts on the actuator, -f_int, the reported force of
  /// docs/model.md, 'Solvers'), the supported DOFs under force control (the support
  /// reactions, f_int).
  std::vector<Index> constraint_dofs;
  /// The model's element families, as PathStep::energies lists them.
  std::vector<std::string> families;
  bool completed = false;
  /// Why the path ended early (empty when completed).
  std::string message;
  /// 1-based number of the increment that failed, 0 if none.
  int failed_increment = 0;
  /// Increments tried, accepted or not.
  int attempted_increments = 0;
  /// Newton iterations of every increment tried, accepted or not (the steps' `iterations`
  /// count the accepted ones only).
  long long newton_iterations = 0;
  /// Adaptive increments with AdaptiveOptions::keep_knots only (else empty): the accepted
  /// converged points, from the start, in order of t.
  std::vector<PathKnot> knots;
  /// Per step, with `knots`: j when the step was read off the Hermite curves between knots
  /// j - 1 and j (a step at knot j itself included), -1 when it was converged by Newton on
  /// its own.
  std::vector<int> step_knot;
};

}  // namespace kresling::solvers
