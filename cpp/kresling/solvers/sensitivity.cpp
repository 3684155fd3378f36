#include "kresling/solvers/sensitivity.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kresling/solvers/rigid_body.hpp"

namespace kresling::solvers {

EquilibriumSensitivity::EquilibriumSensitivity(const model::Model& model, const VectorX& u,
                                               const std::vector<Index>& held)
    : model_(model) {
  const Index n = model.num_dofs();
  std::vector<std::uint8_t> mark = model.fixed();
  for (Index d = 0; d < n; ++d) {
    if (mark[d]) held_dofs_.push_back(d);
  }
  for (Index d : held) {
    if (d < 0 || d >= n) {
      throw std::invalid_argument("held: DOF " + std::to_string(d) + " is out of range [0, " +
                                  std::to_string(n) + ")");
    }
    if (model.fixed()[d]) throw std::invalid_argument("held: DOF " + std::to_string(d) + " is supported");
    if (mark[d]) throw std::invalid_argument("held: DOF " + std::to_string(d) + " repeats");
    mark[d] = 1;
    held_dofs_.push_back(d);
  }
  // A motion no element resists (a free rigid-body motion, an unattached node) makes K_ff
  // singular; rounding could hide that from the factorisation, so it is refused by name.
  require_rigid_body_constrained(model, mark);
  free_row_.assign(n, -1);
  for (Index d = 0; d < n; ++d) {
    if (!mark[d]) {
      free_row_[d] = static_cast<Index>(free_dofs_.size());
      free_dofs_.push_back(d);
    }
  }
  // Unshifted: the derivative is that of f_int's own equilibrium.
  assembler_ = std::make_unique<assembly::Assembler>(model_, assembly::all_dofs(n), /*shift=*/0.0);
  update(u);
}

void EquilibriumSensitivity::update(const VectorX& u) {
  const Index n = model_.num_dofs();
  if (u.size() != n) {
    throw std::invalid_argument("u has " + std::to_string(u.size()) + " entries: must have " +
                                std::to_string(n) + " (3 per node)");
  }
  assembler_->assemble(u, force_, /*with_matrix=*/true);
  K_ = assembler_->matrix();
  std::vector<Eigen::Triplet<double, int>> ff;
  ff.reserve(static_cast<std::size_t>(K_.nonZeros()));
  for (int col = 0; col < K_.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(K_, col); it; ++it) {
      const Index r = free_row_[it.row()], c = free_row_[it.col()];
      if (r >= 0 && c >= 0) ff.emplace_back(static_cast<int>(r), static_cast<int>(c), it.value());
    }
  }
  const auto nf = static_cast<Index>(free_dofs_.size());
  SparseMatrix Kff(nf, nf);
  Kff.setFromTriplets(ff.begin(), ff.end());
  if (nf == 0) {
    info_.ok = true;
    info_.negative_eigenvalues = 0;
    return;
  }
  // The symbolic analysis is kept while the pattern is (contact can change it).
  const bool same_pattern =
      solver_ && Kff_.nonZeros() == Kff.nonZeros() && Kff_.rows() == Kff.rows() &&
      std::equal(Kff.outerIndexPtr(), Kff.outerIndexPtr() + Kff.outerSize() + 1,
                 Kff_.outerIndexPtr()) &&
      std::equal(Kff.innerIndexPtr(), Kff.innerIndexPtr() + Kff.nonZeros(), Kff_.innerIndexPtr());
  if (!same_pattern) solver_ = std::make_unique<TangentSolver>();
  info_ = solver_->factorize(Kff);
  Kff_ = std::move(Kff);
}

void EquilibriumSensitivity::require_ok() const {
  if (!info_.ok) {
    throw std::runtime_error(
        "the tangent at this state is singular: the state has no derivative (a limit or "
        "bifurcation point, or a mechanism the supports leave free)");
  }
}

Eigen::MatrixXd EquilibriumSensitivity::displacement(const Eigen::MatrixXd& dresidual,
                                                     const Eigen::MatrixXd& held_motion) const {
  require_ok();
  const Index n = K_.rows(), P = dresidual.cols();
  const auto nh = static_cast<Index>(held_dofs_.size());
  if (dresidual.rows() != n) {
    throw std::invalid_argument("dresidual has " + std::to_string(dresidual.rows()) +
                                " rows: must have " + std::to_string(n));
  }
  const bool moving = held_motion.size() > 0;
  if (moving && (held_motion.rows() != nh || held_motion.cols() != P)) {
    throw std::invalid_argument("held_motion must be " + std::to_string(nh) + " x " +
                                std::to_string(P) + " (held DOFs x parameters)");
  }
  Eigen::MatrixXd du = Eigen::MatrixXd::Zero(n, P);
  if (moving) {
    for (Index k = 0; k < nh; ++k) du.row(held_dofs_[k]) = held_motion.row(k);
  }
  // Right-hand side -(d r_f/dp + K_fc du_c/dp): K du with only the held rows of du set is
  // K_.c du_c, whose free rows are K_fc du_c.
  Eigen::MatrixXd coupled;
  if (moving) coupled = K_ * du;
  const auto nf = static_cast<Index>(free_dofs_.size());
  if (nf == 0) return du;
  Eigen::MatrixXd rhs(nf, P);
  for (Index r = 0; r < nf; ++r) {
    rhs.row(r) = -dresidual.row(free_dofs_[r]);
    if (moving) rhs.row(r) -= coupled.row(free_dofs_[r]);
  }
  const Eigen::MatrixXd x = solver_->solve(rhs);
  for (Index r = 0; r < nf; ++r) du.row(free_dofs_[r]) = x.row(r);
  return du;
}

Eigen::MatrixXd EquilibriumSensitivity::held_force(const Eigen::MatrixXd& dforce,
                                                   const Eigen::MatrixXd& du) const {
  const Index n = K_.rows();
  if (dforce.rows() != n || du.rows() != n || dforce.cols() != du.cols()) {
    throw std::invalid_argument("dforce and du must both be " + std::to_string(n) +
                                " x P (DOFs x parameters)");
  }
  const Eigen::MatrixXd total = dforce + K_ * du;
  Eigen::MatrixXd out(static_cast<Index>(held_dofs_.size()), du.cols());
  for (std::size_t k = 0; k < held_dofs_.size(); ++k) out.row(static_cast<Index>(k)) = total.row(held_dofs_[k]);
  return out;
}

VectorX EquilibriumSensitivity::adjoint(const VectorX& g) const {
  require_ok();
  const Index n = K_.rows();
  if (g.size() != n) {
    throw std::invalid_argument("g has " + std::to_string(g.size()) + " entries: must have " +
                                std::to_string(n));
  }
  const auto nf = static_cast<Index>(free_dofs_.size());
  VectorX lambda = VectorX::Zero(n);
  if (nf == 0) return lambda;
  VectorX rhs(nf);
  for (Index r = 0; r < nf; ++r) rhs[r] = g[free_dofs_[r]];
  const VectorX x = solver_->solve(rhs);
  for (Index r = 0; r < nf; ++r) lambda[free_dofs_[r]] = x[r];
  return lambda;
}

}  // namespace kresling::solvers
