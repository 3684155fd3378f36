#include "kresling/solvers/stable_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kresling/assembly/assembler.hpp"

namespace kresling::solvers {

double damped_stable_step(double omega, double mass_damping, double stiffness_damping) {
  if (!(omega > 0.0)) {
    // No stiffness: only mass damping limits the step (its explicit, lagged velocity).
    return mass_damping > 0.0 ? 2.0 / mass_damping : std::numeric_limits<double>::infinity();
  }
  const double s = 0.5 * (mass_damping + stiffness_damping * omega * omega);
  return 2.0 / (std::sqrt(omega * omega + s * s) + s);
}

StableStep stable_time_step(const model::Model& model, const VectorX& masses, const VectorX& u,
                            double mass_damping, double stiffness_damping) {
  const Index n = model.num_dofs();
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), 0.0,
                                assembly::Storage::Full);
  VectorX force;
  assembler.assemble(u.size() ? u : VectorX::Zero(n), force, true);
  const assembly::SparseMatrix& K = assembler.matrix();
  const Index m = assembler.size();
  StableStep out;
  if (m == 0) {
    out.time_step = damped_stable_step(0.0, mass_damping, stiffness_damping);
    return out;
  }
  // The free DOFs' 1/sqrt(m): A = D K D is symmetric with the eigenvalues of M^-1 K.
  VectorX d(m);
  const auto& rows = assembler.rows();
  for (Index i = 0; i < n; ++i) {
    if (rows[i] >= 0) d[rows[i]] = 1.0 / std::sqrt(masses[i]);
  }
  // Gershgorin: every eigenvalue lies within max_i sum_j |A_ij|.
  VectorX row_sums = VectorX::Zero(m);
  for (Index c = 0; c < K.outerSize(); ++c) {
    for (assembly::SparseMatrix::InnerIterator it(K, c); it; ++it) {
      row_sums[it.row()] += std::abs(it.value()) * d[it.row()] * d[c];
    }
  }
  out.omega_bound = std::sqrt(row_sums.maxCoeff());
  // Power iteration from a fixed pseudo-random start (every mode present in it).
  VectorX x(m);
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (Index i = 0; i < m; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    x[i] = static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5;
  }
  x.normalize();
  double rho = 0.0, checkpoint = 0.0;
  constexpr int kMaxIterations = 5000;
  for (int k = 1; k <= kMaxIterations; ++k) {
    VectorX y = d.cwiseProduct(K * d.cwiseProduct(x));
    rho = x.dot(y);
    out.iterations = k;
    const double norm = y.norm();
    if (!(norm > 0.0)) break;  // no stiffness along x: w_max = 0 (or x lies in K's null space)
    x = y / norm;
    if (k % 10 == 0) {
      if (std::abs(rho - checkpoint) <= 1e-6 * std::abs(rho)) break;
      checkpoint = rho;
    }
  }
  out.omega_max = std::sqrt(std::max(rho, 0.0));
  out.time_step = damped_stable_step(out.omega_max, mass_damping, stiffness_damping);
  return out;
}

}  // namespace kresling::solvers
