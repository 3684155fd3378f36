#include "kresling/solvers/stable_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"

namespace kresling::solvers {

namespace {

// Lanczos steps at most: the highest eigenvalue of a bar-and-hinge tangent converges in a
// few tens (its spectrum's top is well separated relative to its width).
constexpr Index kMaxLanczos = 300;

// The largest eigenvalue of the symmetric tridiagonal matrix (diagonal alphas, off-diagonal
// betas) and the last component of its unit eigenvector.
std::pair<double, double> top_ritz_value(const std::vector<double>& alphas,
                                         const std::vector<double>& betas) {
  const Index k = static_cast<Index>(alphas.size());
  VectorX diagonal = Eigen::Map<const VectorX>(alphas.data(), k);
  VectorX sub = k > 1 ? VectorX(Eigen::Map<const VectorX>(betas.data(), k - 1)) : VectorX(0);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
  eigen.computeFromTridiagonal(diagonal, sub, Eigen::ComputeEigenvectors);
  return {eigen.eigenvalues()[k - 1], eigen.eigenvectors()(k - 1, k - 1)};
}

void check_masses(const model::Model& model, const VectorX& masses, const VectorX& u) {
  const Index n = model.num_dofs();
  if (masses.size() != n || (u.size() != 0 && u.size() != n)) {
    throw std::invalid_argument("masses and u: must have one entry per DOF (" +
                                std::to_string(n) + ")");
  }
  for (Index i = 0; i < n; ++i) {
    if (!model.fixed()[i] && !(masses[i] > 0.0 && std::isfinite(masses[i]))) {
      throw std::invalid_argument("masses: DOF " + std::to_string(i) + " is free and has mass " +
                                  format_number(masses[i]) + ": every free DOF needs a mass > 0");
    }
  }
}

// Gershgorin: every eigenvalue of A = D K D lies within max_i sum_j |A_ij|.
double largest_row_sum(const assembly::SparseMatrix& K, const VectorX& d) {
  VectorX row_sums = VectorX::Zero(d.size());
  for (Index c = 0; c < K.outerSize(); ++c) {
    for (assembly::SparseMatrix::InnerIterator it(K, c); it; ++it) {
      row_sums[it.row()] += std::abs(it.value()) * d[it.row()] * d[c];
    }
  }
  return row_sums.maxCoeff();
}

// Lanczos on A = D K D from a fixed pseudo-random start (every mode present in it): the
// largest eigenvalue theta of its tridiagonal T_k approaches lambda_max from below, and the
// residual r = beta_k |s_k| of its Ritz vector bounds the distance to an eigenvalue, so
// theta + r is returned (its iterations in `iterations`).
double lanczos_top(const assembly::SparseMatrix& K, const VectorX& d, int& iterations) {
  const Index m = d.size();
  VectorX q(m), previous = VectorX::Zero(m), w(m);
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (Index i = 0; i < m; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    q[i] = static_cast<double>(state >> 11) * 0x1.0p-53 - 0.5;
  }
  q.normalize();
  std::vector<double> alphas, betas;
  double beta = 0.0, rho = 0.0;
  const int most = static_cast<int>(std::min<Index>(m, kMaxLanczos));
  for (int k = 1; k <= most; ++k) {
    w = d.cwiseProduct(K * d.cwiseProduct(q)) - beta * previous;
    const double alpha = q.dot(w);
    w -= alpha * q;
    beta = w.norm();
    alphas.push_back(alpha);
    iterations = k;
    if (k % 5 != 0 && k != most && beta > 1e-14 * std::abs(alpha)) {
      betas.push_back(beta);
      previous.swap(q);
      q = w / beta;
      continue;
    }
    const auto [theta, last] = top_ritz_value(alphas, betas);
    rho = theta + beta * std::abs(last);
    if (beta * std::abs(last) <= 1e-10 * std::abs(theta) || beta <= 1e-14 * std::abs(alpha)) break;
    betas.push_back(beta);
    previous.swap(q);
    q = w / beta;
  }
  return rho;
}

}  // namespace

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
  require_positive("mass_damping", mass_damping, /*allow_zero=*/true);
  require_positive("stiffness_damping", stiffness_damping, /*allow_zero=*/true);
  check_masses(model, masses, u);
  const Index n = model.num_dofs();
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), 0.0,
                                assembly::Storage::Full);
  VectorX force;
  assembler.assemble(u.size() ? u : VectorX::Zero(n), force, true);
  const assembly::SparseMatrix& K = assembler.matrix();
  const Index m = assembler.size();
  if (!Eigen::Map<const VectorX>(K.valuePtr(), K.nonZeros()).allFinite()) {
    throw std::invalid_argument("u: the tangent stiffness there is not finite (an element "
                                "degenerated), so it has no stable time step");
  }
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
  const double gershgorin = largest_row_sum(K, d);
  out.omega_bound = std::sqrt(gershgorin);
  const double rho = std::min(lanczos_top(K, d, out.iterations), gershgorin);
  out.omega_max = std::sqrt(std::max(rho, 0.0));
  out.time_step = damped_stable_step(out.omega_max, mass_damping, stiffness_damping);
  return out;
}

}  // namespace kresling::solvers
