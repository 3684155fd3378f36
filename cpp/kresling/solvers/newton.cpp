#include "kresling/solvers/newton.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include <cmath>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"

namespace kresling::solvers {

VectorX gather_rows(const assembly::Assembler& assembler, const VectorX& full) {
  VectorX out(assembler.size());
  const auto& rows = assembler.rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i] >= 0) out[rows[i]] = full[static_cast<Index>(i)];
  }
  return out;
}

void scatter_add_rows(const assembly::Assembler& assembler, const VectorX& reduced, VectorX& full) {
  const auto& rows = assembler.rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i] >= 0) full[static_cast<Index>(i)] += reduced[rows[i]];
  }
}

void follow_pattern(assembly::Assembler& assembler, TangentSolver& solver) {
  for (const auto& family : assembler.model().families()) {
    if (family->changes_elements()) {
      solver.set_pattern(assembler.workspace().pattern_id());
      return;
    }
  }
}

FactorizeInfo factorize_tangent(assembly::Assembler& assembler, TangentSolver& solver,
                                const VectorX& u, VectorX& force, ExtraTerms* extra) {
  follow_pattern(assembler, solver);
  const auto& families = assembler.model().families();
  const bool adapts = std::any_of(families.begin(), families.end(),
                                  [](const auto& family) { return family->adapts_tangent(); });
  if (!adapts) return solver.factorize(assembler.matrix());
  const FactorizeInfo exact = solver.factorize(assembler.matrix(), /*cholesky_only=*/true);
  if (exact.ok) return exact;
  assembler.assemble(u, force, /*with_matrix=*/true, /*definite=*/true);
  if (extra) {
    extra->add_force(u, force);
    extra->add_tangent(u, assembler.workspace());
  }
  return solver.factorize(assembler.matrix());
}

namespace {

// The model's extent [mm] (at least 1): corrections beyond 1e6 times it mean a mechanism.
double mechanism_scale(const assembly::Assembler& assembler) {
  const NodeMatrix& X = assembler.model().nodes();
  return std::max((X.colwise().maxCoeff() - X.colwise().minCoeff()).norm(), 1.0);
}

// Apply the correction du (assembled rows) to u, shortened as `extra` and the model's
// families allow (a barrier that must not be stepped across).
void apply_correction(assembly::Assembler& assembler, const VectorX& du, VectorX& u,
                      ExtraTerms* extra, bool limited) {
  if (extra == nullptr) {
    add_correction_within_barriers(assembler, du, u, limited);
    return;
  }
  VectorX step = VectorX::Zero(u.size());
  scatter_add_rows(assembler, du, step);
  double fraction = extra ? extra->step_limit(u, step) : 1.0;
  if (limited) fraction = std::min(fraction, barrier_step_fraction(assembler.model(), u, step));
  u += (fraction < 1.0 ? fraction : 1.0) * step;
}

// Chord check first: the correction from the tangent already factorised (at the previous
// iterate). Its error is ~ |du_prev| / l of itself (l: the geometry's length scale), while
// Newton's final step leaves ~ |du|^2 / l <= tol^2 / l. So when |du_prev| |du_chord| <=
// tol^2 the chord step is as accurate as a Newton step would be, and a new tangent (its
// assembly and factorisation, most of an iteration's cost) is not needed. True when that
// step converged (and was applied).
bool chord_step_converges(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                          const VectorX& external, ExtraTerms* extra, bool limited,
                          double last_correction, double tol, VectorX& force) {
  assembler.assemble(u, force, /*with_matrix=*/false);
  if (extra) extra->add_force(u, force);
  const VectorX residual = gather_rows(assembler, external - force);
  if (!residual.allFinite()) return false;
  const VectorX du = solver.solve(residual);
  const double size = du.norm();
  if (!(std::isfinite(size) && size <= tol && last_correction * size <= tol * tol)) {
    return false;
  }
  apply_correction(assembler, du, u, extra, limited);
  return true;
}

// A Newton step at u: the tangent assembled and factorised, the correction solved and
// applied, its size in `correction`. False (with out.failure) when the force, the tangent
// or the correction is not usable.
bool newton_step(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                 const VectorX& external, ExtraTerms* extra, bool limited, VectorX& force,
                 NewtonOutcome& out, double& correction) {
  assembler.assemble(u, force, /*with_matrix=*/true);
  if (extra) {
    extra->add_force(u, force);
    extra->add_tangent(u, assembler.workspace());
  }
  const VectorX residual = gather_rows(assembler, external - force);
  if (!residual.allFinite()) {
    out.failure =
        "the internal force is not finite (an element inverted or degenerated, or a hinge "
        "folded flat)";
    return false;
  }
  const FactorizeInfo info = factorize_tangent(assembler, solver, u, force, extra);
  if (!info.ok) {
    out.failure = "the tangent stiffness is singular (an unconstrained mechanism)";
    return false;
  }
  out.negative_eigenvalues = info.negative_eigenvalues;
  const VectorX du = solver.solve(residual);
  if (!du.allFinite()) {
    out.failure = "the Newton correction is not finite";
    return false;
  }
  // The 1e-8 diagonal shift keeps a zero-stiffness mode factorisable; it shows up as a
  // correction far larger than the structure.
  if (du.norm() > 1e6 * mechanism_scale(assembler)) {
    out.failure = "the Newton correction is unbounded (" + format_rounded(du.norm(), 3) +
                  " mm): the free DOFs form a mechanism with no stiffness";
    return false;
  }
  apply_correction(assembler, du, u, extra, limited);
  correction = du.norm();
  return true;
}

std::string gave_up_message(int iterations, double last_correction, double first_correction) {
  char detail[160];
  std::snprintf(detail, sizeof detail,
                "Newton gave up after %d iterations (correction %.3g mm, still above "
                "%.0e of the first, %.3g mm)",
                iterations, last_correction, kGiveUpRatio, first_correction);
  return detail;
}

std::string wandered_message(int iterations, double correction, double first) {
  char detail[160];
  std::snprintf(detail, sizeof detail,
                "Newton wandered off: its correction at iteration %d, %.3g mm, is %.3g times "
                "its first (%.3g mm)",
                iterations, correction, correction / first, first);
  return detail;
}

// Say how it failed: corrections that stagnate around a small value are rounding noise of
// an ill-conditioned tangent (the absolute tolerance is below what it can resolve).
std::string not_converged_message(int limit, double last_correction, double tol) {
  char detail[96];
  std::snprintf(detail, sizeof detail, " (last correction %.3g mm > tolerance %.3g mm)",
                last_correction, tol);
  return "Newton did not converge in " + std::to_string(limit) + " iterations" + detail;
}

}  // namespace

bool families_limit_steps(const model::Model& model) {
  for (const auto& family : model.families()) {
    if (family->limits_steps()) return true;
  }
  return false;
}

double add_correction_within_barriers(const assembly::Assembler& assembler, const VectorX& du,
                                      VectorX& u, bool limited) {
  if (!limited) {
    scatter_add_rows(assembler, du, u);
    return 1.0;
  }
  VectorX step = VectorX::Zero(u.size());
  scatter_add_rows(assembler, du, step);
  const double fraction = std::min(1.0, barrier_step_fraction(assembler.model(), u, step));
  u += fraction * step;
  return fraction;
}

void shorten_to_barriers(const model::Model& model, const VectorX& from, VectorX& to) {
  if (!families_limit_steps(model)) return;
  const VectorX move = to - from;
  const double fraction = barrier_step_fraction(model, from, move);
  if (fraction < 1.0) to = from + fraction * move;
}

const char* const kHeldMoveBlocked =
    "the prescribed motion would carry panels into each other within the increment (the "
    "contact barrier holds them apart; the drive cannot go on past where they touch)";

bool start_within_barriers(const model::Model& model, const VectorX& from, VectorX& start,
                           const std::vector<Index>& held) {
  if (held.empty() || !families_limit_steps(model)) return true;
  VectorX moved = from;  // `from` with only the held DOFs moved
  for (Index i : held) moved[i] = start[i];
  if (barrier_step_fraction(model, from, moved - from) < 1.0) return false;
  shorten_to_barriers(model, moved, start);
  return true;
}

double barrier_step_fraction(const model::Model& model, const VectorX& u, const VectorX& du) {
  double fraction = 1.0;
  for (const auto& family : model.families()) {
    if (family->limits_steps()) {
      fraction = std::min(fraction, family->step_limit(model.nodes(), u, du));
    }
  }
  return fraction;
}

NewtonOutcome newton_equilibrium(assembly::Assembler& assembler, TangentSolver& solver,
                                 VectorX& u, const VectorX& external,
                                 const NewtonOptions& options, int max_iterations,
                                 ExtraTerms* extra) {
  NewtonOutcome out;
  const int limit = max_iterations > 0 ? max_iterations : options.max_iterations;
  const bool limited = families_limit_steps(assembler.model());
  VectorX force;
  bool factorized = false;  // a tangent of this solve is factorised
  double last_correction = INFINITY;
  double first_correction = INFINITY;  // of this solve (give_up_after, give_up_wandering)
  const double tol = options.tolerance;
  while (out.iterations < limit) {
    check_interrupt();
    ++out.iterations;
    if (factorized && chord_step_converges(assembler, solver, u, external, extra, limited,
                                           last_correction, tol, force)) {
      out.converged = true;
      return out;
    }
    if (!newton_step(assembler, solver, u, external, extra, limited, force, out,
                     last_correction)) {
      return out;
    }
    factorized = true;
    if (last_correction <= tol) {
      out.converged = true;
      return out;
    }
    if (out.iterations == 1) first_correction = last_correction;
    if (options.give_up_wandering > 0.0 &&
        last_correction > options.give_up_wandering * first_correction) {
      out.failure = wandered_message(out.iterations, last_correction, first_correction);
      return out;
    }
    if (options.give_up_after > 0 && out.iterations >= options.give_up_after &&
        last_correction > kGiveUpRatio * first_correction) {
      out.failure = gave_up_message(out.iterations, last_correction, first_correction);
      return out;
    }
  }
  out.failure = not_converged_message(limit, last_correction, tol);
  return out;
}

std::vector<std::string> family_names(const model::Model& model) {
  std::vector<std::string> names;
  for (const auto& family : model.families()) names.emplace_back(family->name());
  return names;
}

bool finite_step(const PathStep& step) {
  return std::isfinite(step.load_factor) && step.displacement.allFinite() &&
         step.constraint_force.allFinite() && step.energies.allFinite();
}

PathStep record_step(assembly::Assembler& assembler, const VectorX& u, double load_factor,
                     const NewtonOutcome& outcome, const std::vector<Index>& constraint_dofs,
                     double sign, VectorX* internal) {
  PathStep step;
  VectorX own;
  VectorX& force = internal ? *internal : own;
  const auto energies = assembler.assemble(u, force, /*with_matrix=*/false);
  step.load_factor = load_factor;
  step.displacement = u;
  step.constraint_force.resize(static_cast<Index>(constraint_dofs.size()));
  for (std::size_t k = 0; k < constraint_dofs.size(); ++k) {
    step.constraint_force[static_cast<Index>(k)] = sign * force[constraint_dofs[k]];
  }
  step.energies = energies.vector();
  step.iterations = outcome.iterations;
  step.negative_eigenvalues = outcome.negative_eigenvalues;
  return step;
}

}  // namespace kresling::solvers
