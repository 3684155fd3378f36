#include "kresling/solvers/energy_minimum.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <Eigen/Dense>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/newton.hpp"

namespace kresling::solvers {

namespace {

struct Evaluation {
  double energy = 0.0;
  VectorX gradient;  // on the assembler's rows
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
};

// The load's work f . u (0 without a load).
double work(const VectorX* external, const VectorX& u) {
  return external ? external->dot(u) : 0.0;
}

bool evaluate(assembly::Assembler& assembler, const VectorX& u, const VectorX* external,
              Evaluation& e) {
  VectorX force;
  e.energy = assembler.assemble(u, force, /*with_matrix=*/true).total() - work(external, u);
  e.gradient = gather_rows(assembler, external ? VectorX(force - *external) : force);
  const Eigen::MatrixXd K = Eigen::MatrixXd(assembler.matrix()).selfadjointView<Eigen::Lower>();
  e.eigen.compute(K);
  return std::isfinite(e.energy) && e.gradient.allFinite() && e.eigen.info() == Eigen::Success;
}

double energy_at(assembly::Assembler& assembler, const VectorX& u, const VectorX* external) {
  VectorX force;
  return assembler.assemble(u, force, /*with_matrix=*/false).total() - work(external, u);
}

// Move u along `step` (on the assembler's rows; shortened to max_step) by backtracking on
// the energy from `energy` (slope from `gradient`), no further than a contact barrier
// allows: across it the energy is finite again. A step below the energy's rounding is
// taken whole. False, with `failure` said, when 40 halvings find no lower energy.
bool line_search(assembly::Assembler& assembler, VectorX& u, VectorX step, double energy,
                 const VectorX& gradient, const VectorX* external,
                 const EnergyMinimumOptions& o, std::string& failure) {
  if (step.norm() > o.max_step) step *= o.max_step / step.norm();
  const double slope = std::min(gradient.dot(step), 0.0);
  VectorX move = VectorX::Zero(u.size());
  scatter_add_rows(assembler, step, move);
  double alpha = std::min(1.0, barrier_step_fraction(assembler.model(), u, move));
  VectorX trial;
  for (int halvings = 0;; ++halvings) {
    trial = u;
    scatter_add_rows(assembler, alpha * step, trial);
    const double e = energy_at(assembler, trial, external);
    const bool rounding = alpha * step.norm() <= 10.0 * o.tolerance;
    if ((std::isfinite(e) && e <= energy + 1e-4 * alpha * slope) || rounding) break;
    if (halvings == 40) {
      failure = "the line search found no lower energy along the step";
      return false;
    }
    alpha *= 0.5;
  }
  u = std::move(trial);
  return true;
}

}  // namespace

void check_descent(double tolerance, double max_step, double escape_step, int max_iterations) {
  require_positive("tolerance", tolerance);
  require_positive("escape_step", escape_step);
  require_positive("max_step", max_step);
  if (max_iterations < 1) throw_invalid("max_iterations", max_iterations, "an integer >= 1");
}

EnergyMinimum minimize_energy(assembly::Assembler& assembler, VectorX& u,
                              const EnergyMinimumOptions& o, const VectorX* external) {
  check_descent(o.tolerance, o.max_step, o.escape_step, o.max_iterations);
  require_positive("min_curvature", o.min_curvature);
  EnergyMinimum out;
  Evaluation e;
  for (out.iterations = 0; out.iterations < o.max_iterations; ++out.iterations) {
    check_interrupt();
    if (!evaluate(assembler, u, external, e)) {
      out.failure = "the energy or its derivatives are not finite (an element degenerated)";
      return out;
    }
    const VectorX& lambda = e.eigen.eigenvalues();
    const Eigen::MatrixXd& V = e.eigen.eigenvectors();
    out.energy = e.energy;
    out.smallest_eigenvalue = lambda.size() ? lambda[0] : 0.0;
    out.negative_eigenvalues = static_cast<int>((lambda.array() < 0.0).count());
    // The saddle-free Newton step.
    const VectorX curvature = lambda.cwiseAbs().cwiseMax(o.min_curvature);
    VectorX step = -V * (V.transpose() * e.gradient).cwiseQuotient(curvature);
    if (step.norm() <= o.tolerance) {
      if (out.negative_eigenvalues == 0) {
        out.converged = true;
        return out;
      }
      step = o.escape_step * V.col(0);  // out of the saddle, down its steepest direction
    }
    if (!line_search(assembler, u, step, e.energy, e.gradient, external, o, out.failure)) {
      return out;
    }
  }
  out.failure = "no stable equilibrium within " + std::to_string(o.max_iterations) + " iterations";
  return out;
}

EnergyMinimum minimize_energy_sparse(assembly::Assembler& assembler, TangentSolver& solver,
                                     VectorX& u, const EnergyMinimumOptions& o,
                                     const VectorX* external) {
  require_positive("tolerance", o.tolerance);
  require_positive("max_step", o.max_step);
  if (o.max_iterations < 1) throw_invalid("max_iterations", o.max_iterations, "an integer >= 1");
  EnergyMinimum out;
  double mu = 0.0;  // the last shift that gave a Cholesky: where the next search starts
  for (out.iterations = 0; out.iterations < o.max_iterations; ++out.iterations) {
    check_interrupt();
    VectorX force;
    const double energy =
        assembler.assemble(u, force, /*with_matrix=*/true).total() - work(external, u);
    const VectorX gradient = gather_rows(assembler, external ? VectorX(force - *external) : force);
    if (!std::isfinite(energy) || !gradient.allFinite()) {
      out.failure = "the energy or its derivatives are not finite (an element degenerated)";
      return out;
    }
    out.energy = energy;
    SparseMatrix K = assembler.matrix();
    const double largest = K.diagonal().cwiseAbs().maxCoeff();
    // The smallest shift (from none, then from a tenth of the last one) whose Cholesky exists.
    double shift = 0.0;
    bool factorized = solver.factorize(K, /*cholesky_only=*/true).ok;
    if (!factorized) {
      shift = std::max(0.1 * mu, 1e-6 * largest);
      for (int tries = 0; tries < 60 && !factorized; ++tries, shift *= 4.0) {
        SparseMatrix shifted = K;
        shifted.diagonal().array() += shift;
        factorized = solver.factorize(shifted, /*cholesky_only=*/true).ok;
        if (factorized) break;
      }
      if (!factorized) {
        out.failure = "no shift of the tangent made it positive definite";
        return out;
      }
    }
    mu = shift;
    out.negative_eigenvalues = shift == 0.0 ? 0 : -1;
    VectorX step = -solver.solve(gradient);
    if (!step.allFinite()) {
      out.failure = "the descent step is not finite";
      return out;
    }
    if (step.norm() <= o.tolerance) {
      if (shift == 0.0) {
        out.converged = true;
        return out;
      }
      out.failure = "the descent stopped where the tangent is not positive definite (a saddle)";
      return out;
    }
    if (!line_search(assembler, u, step, energy, gradient, external, o, out.failure)) {
      return out;
    }
  }
  out.failure = "no stable equilibrium within " + std::to_string(o.max_iterations) + " iterations";
  return out;
}

}  // namespace kresling::solvers
