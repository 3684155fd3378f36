#include "kresling/solvers/displacement_control.hpp"

#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/rigid_body.hpp"

namespace kresling::solvers {

PathResult solve_displacement_control(const model::Model& model, const VectorX& prescribed,
                                      int steps, const DisplacementControlOptions& options,
                                      const VectorX& initial) {
  const Index n = model.num_dofs();
  if (prescribed.size() != n) {
    throw std::invalid_argument("prescribed: has " + std::to_string(prescribed.size()) +
                                " entries, must have one per DOF (" + std::to_string(n) + ")");
  }
  if (!prescribed.allFinite()) throw std::invalid_argument("prescribed: contains NaN or inf");
  if (steps < 1) throw_invalid("steps", steps, "an integer >= 1");
  if (initial.size() != 0 && initial.size() != n) {
    throw std::invalid_argument("initial: must be empty or have one entry per DOF");
  }

  std::vector<std::uint8_t> held = model.fixed();
  std::vector<Index> imposed;
  for (Index i = 0; i < n; ++i) {
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
  require_rigid_body_constrained(model, held);

  assembly::Assembler assembler(model, assembly::unmasked_dofs(held), options.shift);
  TangentSolver solver;
  const VectorX no_load = VectorX::Zero(n);
  VectorX u = initial.size() ? initial : VectorX::Zero(n);
  const VectorX start = u;

  PathResult result;
  result.constraint_dofs = imposed;
  const double nominal = 1.0 / steps;
  const double smallest = nominal / double(1 << options.max_bisections);
  double t = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const double target = (k == steps) ? 1.0 : k * nominal;
    double dt = target - t;
    std::string first_failure;  // why the whole increment failed, the most telling reason
    while (t < target) {
      ++result.attempted_increments;
      VectorX trial = u;
      const double t_new = (dt >= target - t) ? target : t + dt;
      for (Index i : imposed) trial[i] = start[i] + t_new * prescribed[i];
      const NewtonOutcome outcome = newton_equilibrium(
          assembler, solver, trial, no_load, options.newton, options.reject_iterations);
      if (outcome.converged && outcome.iterations < options.reject_iterations) {
        u = trial;
        t = t_new;
        result.steps.push_back(record_step(assembler, u, t, outcome, imposed, -1.0));
        dt = target - t;  // back to the rest of the nominal increment
        continue;
      }
      if (first_failure.empty()) {
        first_failure = outcome.failure.empty()
                            ? "Newton needed " + std::to_string(outcome.iterations) + " iterations"
                            : outcome.failure;
      }
      dt *= 0.5;
      if (dt < smallest) {
        result.failed_increment = result.attempted_increments;
        result.message = "increment " + std::to_string(k) + " (of " + std::to_string(steps) +
                         ", at " + format_number(t) + " of the prescribed motion) failed after " +
                         std::to_string(options.max_bisections) + " bisections; at full size: " +
                         first_failure;
        return result;
      }
    }
  }
  result.completed = true;
  return result;
}

}  // namespace kresling::solvers
