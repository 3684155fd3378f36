#include "kresling/solvers/damped_newton.hpp"

#include <string>

#include "kresling/core/interrupt.hpp"

namespace kresling::solvers {

NewtonOutcome damped_newton(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                            const NewtonOptions& options, double damping) {
  NewtonOutcome out;
  const bool limited = families_limit_steps(assembler.model());
  VectorX force;
  while (out.iterations < options.max_iterations) {
    check_interrupt();
    ++out.iterations;
    assembler.assemble(u, force, /*with_matrix=*/true);
    const FactorizeInfo info = factorize_tangent(assembler, solver, u, force);
    const VectorX du = info.ok ? solver.solve(gather_rows(assembler, -force)) : VectorX();
    if (!info.ok || !du.allFinite()) {
      out.failure = "the tangent stiffness is singular or the correction is not finite";
      return out;
    }
    out.negative_eigenvalues = info.negative_eigenvalues;
    // Shortened further where a barrier would be stepped across (newton.hpp).
    add_correction_within_barriers(assembler, damping * du, u, limited);
    if (du.norm() <= options.tolerance) {
      out.converged = true;
      return out;
    }
  }
  out.failure = "Newton did not converge in " + std::to_string(options.max_iterations) +
                " iterations";
  return out;
}

}  // namespace kresling::solvers
