#include "kresling/solvers/fold.hpp"

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/solvers/adaptive_path.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/path_control.hpp"
#include "kresling/solvers/path_follower.hpp"
#include "kresling/solvers/rigid_body.hpp"

namespace kresling::solvers {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

void check_stages(const model::Model& model, const std::vector<FoldStage>& stages) {
  if (stages.empty()) throw std::invalid_argument("stages: there is no stage to fold");
  const auto num_hinges = static_cast<Index>(model.hinges().size());
  for (std::size_t s = 0; s < stages.size(); ++s) {
    const FoldStage& stage = stages[s];
    const std::string name = "stages[" + std::to_string(s) + "]";
    if (stage.targets.size() != static_cast<Index>(stage.hinges.size())) {
      throw std::invalid_argument(name + ": has " + std::to_string(stage.hinges.size()) +
                                  " hinges and " + std::to_string(stage.targets.size()) +
                                  " targets, must have one target per hinge");
    }
    if (stage.hinges.empty()) throw std::invalid_argument(name + ": drives no hinge");
    std::vector<char> seen(static_cast<std::size_t>(num_hinges), 0);
    for (std::size_t i = 0; i < stage.hinges.size(); ++i) {
      const Index h = stage.hinges[i];
      if (h < 0 || h >= num_hinges) {
        throw std::invalid_argument(name + ": hinge " + std::to_string(h) + " is out of range [0, " +
                                    std::to_string(num_hinges) + ")");
      }
      if (seen[static_cast<std::size_t>(h)]++) {
        throw std::invalid_argument(name + ": hinge " + std::to_string(h) + " is driven twice");
      }
      const double target = stage.targets[static_cast<Index>(i)];
      require_finite(name + ": target of hinge " + std::to_string(h), target);
      if (!(target >= 0.0 && target < kTwoPi)) {
        throw_invalid(name + ": target of hinge " + std::to_string(h), target,
                      "in [0, 2 pi) rad (a rest angle)");
      }
    }
  }
}

// The stage's hinges' rest angles in `model`.
VectorX rest_angles(const model::Model& model, const std::vector<Index>& hinges) {
  VectorX out(static_cast<Index>(hinges.size()));
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    out[static_cast<Index>(i)] = model.hinges()[static_cast<std::size_t>(hinges[i])].rest_angle;
  }
  return out;
}

// `model` with the stage's hinges at its targets.
model::Model after_stage(const model::Model& model, const FoldStage& stage) {
  std::vector<model::Hinge> hinges = model.hinges();
  for (std::size_t i = 0; i < stage.hinges.size(); ++i) {
    hinges[static_cast<std::size_t>(stage.hinges[i])].rest_angle = stage.targets[static_cast<Index>(i)];
  }
  return model.with_family(std::make_shared<model::HingeFamily>(std::move(hinges)));
}

}  // namespace

model::Model folded_rest_model(const model::Model& model, const std::vector<FoldStage>& stages) {
  check_stages(model, stages);
  model::Model current = model;
  for (const FoldStage& stage : stages) current = after_stage(current, stage);
  return current;
}

PathResult solve_fold(const model::Model& model, const std::vector<FoldStage>& stages, int steps,
                      const VectorX& forces, const FoldOptions& options, const VectorX& initial) {
  const Index n = model.num_dofs();
  check_stages(model, stages);
  check_steps("steps", steps);
  check_newton(options.newton);
  check_bisections(options.max_bisections);
  check_shift(options.shift);
  if (options.extrapolation < 0 || options.extrapolation > 3) {
    throw_invalid("extrapolation", options.extrapolation, "0, 1, 2 or 3");
  }
  check_adaptive_tolerance(options.adaptive_tolerance);
  if (forces.size() != n || !forces.allFinite()) {
    throw std::invalid_argument("forces: must have one finite entry per DOF (" + std::to_string(n) +
                                ")");
  }
  if (initial.size() != 0 && (initial.size() != n || !initial.allFinite())) {
    throw std::invalid_argument("initial: must be empty or one finite entry per DOF");
  }
  require_rigid_body_constrained(model, model.fixed());

  // One pattern and one symbolic factorisation serve every stage: only rest angles change.
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                                assembly::Storage::Lower);
  TangentSolver solver(options.newton.cholesky);
  VectorX u = initial.size() ? initial : VectorX::Zero(n);
  FollowOptions follow;
  follow.newton = options.newton;
  follow.max_bisections = options.max_bisections;
  follow.extrapolation = options.extrapolation;
  follow.snap = options.snap;
  follow.relax = options.relax;
  follow.relax_iterations = options.relax_iterations;
  bool stopped = false;  // the caller's rule ended the fold
  follow.stop = [&](const PathStep& step) {
    stopped = options.stop && options.stop(step);
    return stopped;
  };

  // Adaptive increments also assemble every DOF, unshifted (the path's derivatives).
  std::optional<assembly::Assembler> full;
  if (options.adaptive) {
    full.emplace(model, assembly::all_dofs(n), 0.0, assembly::Storage::Lower);
  }
  AdaptiveOptions adaptive;
  adaptive.newton = options.newton;
  adaptive.reject_iterations = 0;  // as the fixed increments: every converged one accepted
  adaptive.max_bisections = options.max_bisections;
  adaptive.tolerance = options.adaptive_tolerance;
  adaptive.stop = follow.stop;

  PathResult result;
  model::Model start = model;  // the rest angles this stage starts from
  for (std::size_t s = 0; s < stages.size(); ++s) {
    const FoldStage& stage = stages[s];
    RestAngleControl control(start, stage.hinges, rest_angles(start, stage.hinges), stage.targets,
                             forces, s == 0 ? 0.0 : 1.0, 1.0);
    const std::size_t before = result.steps.size();
    bool folded = false;  // by the adaptive increments
    if (options.adaptive) {
      PathResult part = follow_adaptive(control, assembler, *full, solver, u, steps, adaptive);
      result.attempted_increments += part.attempted_increments;
      result.newton_iterations += part.newton_iterations;
      if (part.completed) {
        folded = true;
        result.constraint_dofs = part.constraint_dofs;
        result.families = part.families;
        result.completed = true;
        for (PathStep& step : part.steps) result.steps.push_back(std::move(step));
        // The stage's last sample is a converged point (or the caller's stop ended it).
        if (!part.steps.empty()) u = result.steps.back().displacement;
      }
    }
    // Fixed increments (or a stage the adaptive ones could not finish, from its start).
    if (!folded) follow_path(control, assembler, solver, u, steps, follow, result);
    for (std::size_t k = before; k < result.steps.size(); ++k) {
      result.steps[k].load_factor += static_cast<double>(s);
    }
    if (!result.completed) {
      result.message = "stage " + std::to_string(s + 1) + ": " + result.message;
      return result;
    }
    if (stopped) return result;
    start = after_stage(start, stage);
    if (s + 1 < stages.size()) result.completed = false;  // the next stage decides
  }
  return result;
}

}  // namespace kresling::solvers
