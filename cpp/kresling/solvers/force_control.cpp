#include "kresling/solvers/force_control.hpp"

#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/path_follower.hpp"
#include "kresling/solvers/rigid_body.hpp"

namespace kresling::solvers {

void check_load_inputs(const model::Model& model, const VectorX& forces, const VectorX& initial) {
  const Index n = model.num_dofs();
  if (forces.size() != n) {
    throw std::invalid_argument("forces: has " + std::to_string(forces.size()) +
                                " entries, must have one per DOF (" + std::to_string(n) + ")");
  }
  if (!forces.allFinite()) throw std::invalid_argument("forces: contains NaN or inf");
  bool any = false;
  for (Index i = 0; i < n; ++i) any |= (forces[i] != 0.0 && !model.fixed()[i]);
  if (!any) throw std::invalid_argument("forces: no force acts on a free DOF");
  if (initial.size() != 0 && (initial.size() != n || !initial.allFinite())) {
    throw std::invalid_argument("initial: must be empty or one finite entry per DOF");
  }
  require_rigid_body_constrained(model, model.fixed());
}

PathResult solve_force_control(const model::Model& model, const VectorX& forces, int steps,
                               const ForceControlOptions& options, const VectorX& initial) {
  check_load_inputs(model, forces, initial);
  check_steps("steps", steps);
  check_newton(options.newton);
  check_bisections(options.max_bisections);
  check_shift(options.shift);
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                                assembly::Storage::Lower);
  TangentSolver solver(options.newton.cholesky);
  VectorX u = initial.size() ? initial : VectorX::Zero(model.num_dofs());
  // Load steps: the path follower under lambda * forces, every converged step accepted.
  LoadControl control(model, forces);
  FollowOptions follow;
  follow.newton = options.newton;
  follow.max_bisections = options.max_bisections;
  follow.stop = options.stop;
  PathResult result;
  follow_path(control, assembler, solver, u, steps, follow, result);
  return result;
}

}  // namespace kresling::solvers
