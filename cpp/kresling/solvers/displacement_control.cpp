#include "kresling/solvers/displacement_control.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/adaptive_path.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/merlin2_steps.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_follower.hpp"
#include "kresling/solvers/rigid_body.hpp"

namespace kresling::solvers {

namespace {

void check_options(const DisplacementControlOptions& o) {
  check_newton(o.newton);
  require_integer_in("reject_iterations", o.reject_iterations, 1, kMaxIterations);
  check_bisections(o.max_bisections);
  check_shift(o.shift);
  if (o.extrapolation < 0 || o.extrapolation > 3) {
    throw_invalid("extrapolation", o.extrapolation, "0, 1, 2 or 3");
  }
  check_adaptive_tolerance(o.adaptive_tolerance);
}

void check_inputs(const model::Model& model, const VectorX& prescribed, int steps,
                  const VectorX& initial) {
  const Index n = model.num_dofs();
  if (prescribed.size() != n) {
    throw std::invalid_argument("prescribed: has " + std::to_string(prescribed.size()) +
                                " entries, must have one per DOF (" + std::to_string(n) + ")");
  }
  if (!prescribed.allFinite()) throw std::invalid_argument("prescribed: contains NaN or inf");
  check_steps("steps", steps);
  if (initial.size() != 0 && initial.size() != n) {
    throw std::invalid_argument("initial: must be empty or have one entry per DOF");
  }
  if (!initial.allFinite()) throw std::invalid_argument("initial: contains NaN or inf");
}

// The DOFs the solve holds: the supports and the driven ones (each driven DOF free).
std::vector<std::uint8_t> held_dofs(const model::Model& model, const VectorX& prescribed) {
  std::vector<std::uint8_t> held = model.fixed();
  std::vector<Index> imposed;
  for (Index i = 0; i < model.num_dofs(); ++i) {
    if (prescribed[i] == 0.0) continue;
    if (model.fixed()[i]) {
      throw std::invalid_argument("prescribed: DOF " + std::to_string(i) + " (node " +
                                  std::to_string(i / 3) + ", " + "xyz"[i % 3] +
                                  ") is also fixed; a DOF is either supported or driven");
    }
    imposed.push_back(i);
    held[i] = 1;
  }
  if (imposed.empty()) throw std::invalid_argument("prescribed: every entry is zero");
  return held;
}

// Unbinds the solve's assemblers from its model when the solve returns (or throws).
struct Unbind {
  std::optional<assembly::Assembler>& assembler;
  std::optional<assembly::Assembler>& full;
  ~Unbind() {
    assembler.reset();
    full.reset();
  }
};

FollowOptions follow_options(const DisplacementControlOptions& o) {
  FollowOptions follow;
  follow.newton = o.newton;
  follow.max_bisections = o.max_bisections;
  follow.extrapolation = o.extrapolation;
  follow.reject_iterations = o.reject_iterations;
  follow.stop = o.stop;
  return follow;
}

AdaptiveOptions adaptive_options(const DisplacementControlOptions& o) {
  AdaptiveOptions adaptive;
  adaptive.newton = o.newton;
  adaptive.reject_iterations = o.reject_iterations;
  adaptive.max_bisections = o.max_bisections;
  adaptive.tolerance = o.adaptive_tolerance;
  adaptive.stop = o.stop;
  adaptive.keep_knots = o.keep_knots;
  return adaptive;
}

}  // namespace

DisplacementControl::DisplacementControl(DisplacementControlOptions options)
    : options_(options) {
  check_options(options_);
}

PathResult DisplacementControl::solve(const model::Model& model, const VectorX& prescribed,
                                      int steps, const VectorX& initial) {
  check_inputs(model, prescribed, steps, initial);
  const Index n = model.num_dofs();
  const std::vector<std::uint8_t> held = held_dofs(model, prescribed);
  require_rigid_body_constrained(model, held);
  // Reuse the pattern and the symbolic factorisation when only the geometry changed.
  if (!(workspace_ && held == held_ && workspace_->fits(model))) {
    workspace_ = std::make_unique<assembly::Workspace>(model, assembly::unmasked_dofs(held),
                                                       options_.shift, assembly::Storage::Lower);
    solver_ = std::make_unique<TangentSolver>(options_.newton.cholesky);
    held_ = held;
  }
  // `model` is bound for this solve only: nothing here refers to it once solve returns.
  assembler_.emplace(model, *workspace_);
  const Unbind unbind{assembler_, full_assembler_};
  VectorX u = initial.size() ? initial : VectorX::Zero(n);
  FollowOptions follow = follow_options(options_);
  if (options_.merlin2_steps) {
    // MERLIN2's step control: its own rejection budget and damping, no extrapolated start.
    PathResult result;
    DisplacementDrive drive(model, prescribed, u, steps);
    Merlin2Steps policy(steps, options_.newton.max_iterations);
    follow.extrapolation = 0;
    follow_path(drive, *assembler_, *solver_, u, policy, follow, result);
    return result;
  }
  int fallback_attempts = 0;  // of adaptive increments that could not finish the path
  long long fallback_iterations = 0;
  if (options_.adaptive) {
    if (!(full_workspace_ && full_workspace_->fits(model))) {
      full_workspace_ = std::make_unique<assembly::Workspace>(model, assembly::all_dofs(n), 0.0,
                                                              assembly::Storage::Lower);
    }
    full_assembler_.emplace(model, *full_workspace_);
    DisplacementDrive drive(model, prescribed, u);
    PathResult adaptive = follow_adaptive(drive, *assembler_, *full_assembler_, *solver_, u,
                                          steps, adaptive_options(options_));
    if (adaptive.completed) return adaptive;
    // A path the adaptive increments cannot finish (their predictor sent past a snap that
    // the last equilibrium crosses, say) is followed again in fixed increments from the
    // start, so that they never complete less of it than fixed increments would: the result
    // is the fixed increments' own, with both runs' attempts counted.
    fallback_attempts = adaptive.attempted_increments;
    fallback_iterations = adaptive.newton_iterations;
  }
  // Fixed increments: the path follower under the prescribed motion from u.
  PathResult result;
  result.attempted_increments = fallback_attempts;
  result.newton_iterations = fallback_iterations;
  DisplacementDrive drive(model, prescribed, u);
  follow_path(drive, *assembler_, *solver_, u, steps, follow, result);
  return result;
}

PathResult solve_displacement_control(const model::Model& model, const VectorX& prescribed,
                                      int steps, const DisplacementControlOptions& options,
                                      const VectorX& initial) {
  return DisplacementControl(options).solve(model, prescribed, steps, initial);
}

}  // namespace kresling::solvers
