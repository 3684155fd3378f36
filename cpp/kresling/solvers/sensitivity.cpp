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
  const SparseMatrix& K = assembler_->matrix();
  const auto nf = static_cast<Index>(free_dofs_.size());
  const bool same_K = kff_slot_.size() == static_cast<std::size_t>(K.nonZeros()) &&
                      std::equal(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1,
                                 k_outer_.begin()) &&
                      std::equal(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros(),
                                 k_inner_.begin());
  if (same_K) {
    // The states of a path share the pattern: copy K's free block's values in place.
    for (std::size_t i = 0; i < kff_slot_.size(); ++i) {
      if (kff_slot_[i] >= 0) Kff_.valuePtr()[kff_slot_[i]] = K.valuePtr()[i];
    }
  } else {
    std::vector<Eigen::Triplet<double, int>> ff;
    ff.reserve(static_cast<std::size_t>(K.nonZeros()));
    for (int col = 0; col < K.outerSize(); ++col) {
      for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
        const Index r = free_row_[it.row()], c = free_row_[it.col()];
        if (r >= 0 && c >= 0) ff.emplace_back(static_cast<int>(r), static_cast<int>(c), it.value());
      }
    }
    SparseMatrix Kff(nf, nf);
    Kff.setFromTriplets(ff.begin(), ff.end());
    // A new pattern: a new symbolic analysis (contact can change it).
    solver_ = std::make_unique<TangentSolver>();
    Kff_ = std::move(Kff);
    // Where each of K's entries goes in K_ff's value array (-1: a held row or column).
    kff_slot_.assign(static_cast<std::size_t>(K.nonZeros()), -1);
    for (int col = 0; col < K.outerSize(); ++col) {
      for (int i = K.outerIndexPtr()[col]; i < K.outerIndexPtr()[col + 1]; ++i) {
        const Index r = free_row_[K.innerIndexPtr()[i]], c = free_row_[col];
        if (r < 0 || c < 0) continue;
        const int* begin = Kff_.innerIndexPtr() + Kff_.outerIndexPtr()[c];
        const int* end = Kff_.innerIndexPtr() + Kff_.outerIndexPtr()[c + 1];
        kff_slot_[i] = static_cast<int>(std::lower_bound(begin, end, static_cast<int>(r)) -
                                        Kff_.innerIndexPtr());
      }
    }
    k_outer_.assign(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1);
    k_inner_.assign(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());
  }
  if (nf == 0) {
    info_.ok = true;
    info_.negative_eigenvalues = 0;
    return;
  }
  info_ = solver_->factorize(Kff_);
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
  const SparseMatrix& K = tangent();
  const Index n = K.rows(), P = dresidual.cols();
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
  // K.c du_c, whose free rows are K_fc du_c.
  Eigen::MatrixXd coupled;
  if (moving) coupled = K * du;
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
  const SparseMatrix& K = tangent();
  const Index n = K.rows();
  if (dforce.rows() != n || du.rows() != n || dforce.cols() != du.cols()) {
    throw std::invalid_argument("dforce and du must both be " + std::to_string(n) +
                                " x P (DOFs x parameters)");
  }
  const Eigen::MatrixXd total = dforce + K * du;
  Eigen::MatrixXd out(static_cast<Index>(held_dofs_.size()), du.cols());
  for (std::size_t k = 0; k < held_dofs_.size(); ++k) out.row(static_cast<Index>(k)) = total.row(held_dofs_[k]);
  return out;
}

VectorX EquilibriumSensitivity::adjoint(const VectorX& g) const {
  require_ok();
  const Index n = tangent().rows();
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

namespace {

// A family's columns among a path sensitivity's: the family evaluates its elements once
// per state for all of them (ElementFamily::parameter_derivatives).
struct FamilyColumns {
  const model::ElementFamily* family;
  std::vector<std::string> names;
  std::vector<const Eigen::MatrixXd*> weights;
};

void check_path_inputs(Index n, Index P, const std::vector<VectorX>& states,
                       const std::vector<double>& fractions, const Eigen::MatrixXd& positions,
                       const Eigen::MatrixXd& drive) {
  if (fractions.size() != states.size()) {
    throw std::invalid_argument("fractions: has " + std::to_string(fractions.size()) +
                                " entries; must have one per state (" +
                                std::to_string(states.size()) + ")");
  }
  if (positions.cols() > 0 && positions.rows() != n) {
    throw std::invalid_argument("positions must have 3N = " + std::to_string(n) + " rows");
  }
  if (drive.cols() > 0 && (drive.rows() != n || drive.cols() != P)) {
    throw std::invalid_argument("drive must be 3N x P = " + std::to_string(n) + " x " +
                                std::to_string(P));
  }
}

// The columns grouped by family, in the order the families first appear.
std::vector<FamilyColumns> group_by_family(const model::Model& model,
                                           const std::vector<ColumnMotion>& columns, Index P) {
  std::vector<FamilyColumns> groups;
  for (const ColumnMotion& c : columns) {
    const model::ElementFamily* f = model.family(c.family);
    if (f == nullptr) throw std::invalid_argument("the model has no element family '" + c.family + "'");
    if (c.weights.cols() != P) {
      throw std::invalid_argument(c.family + "." + c.column + ": weights must have P = " +
                                  std::to_string(P) + " columns");
    }
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const FamilyColumns& g) { return g.family == f; });
    if (it == groups.end()) it = groups.insert(groups.end(), FamilyColumns{f, {}, {}});
    it->names.push_back(c.column);
    it->weights.push_back(&c.weights);
  }
  return groups;
}

// The columns' explicit derivatives at u, weighted, added to the force's (n x P) and the
// energy's (1 x P).
void add_column_derivatives(const model::Model& model, const VectorX& u,
                            const std::vector<FamilyColumns>& groups,
                            std::vector<model::ParameterDerivative>& derivatives,
                            Eigen::MatrixXd& dforce, Eigen::RowVectorXd& denergy) {
  for (const FamilyColumns& g : groups) {
    g.family->parameter_derivatives(model.nodes(), u, g.names, derivatives);
    for (std::size_t c = 0; c < g.names.size(); ++c) {
      const model::ParameterDerivative& d = derivatives[c];
      const Eigen::MatrixXd& W = *g.weights[c];
      if (W.rows() != d.energy.size()) {
        throw std::invalid_argument(std::string(g.family->name()) + "." + g.names[c] +
                                    ": weights have " + std::to_string(W.rows()) +
                                    " rows; the column has " + std::to_string(d.energy.size()) +
                                    " entries");
      }
      for (const auto& t : d.force) dforce.row(t.row()) += t.value() * W.row(t.col());
      denergy += d.energy.transpose() * W;
    }
  }
}

}  // namespace

PathSensitivityResult path_sensitivity(const model::Model& model,
                                       const std::vector<VectorX>& states,
                                       const std::vector<double>& fractions,
                                       const std::vector<Index>& held,
                                       const Eigen::MatrixXd& positions,
                                       const std::vector<ColumnMotion>& columns,
                                       const Eigen::MatrixXd& drive) {
  const Index n = model.num_dofs();
  const Index P = positions.cols() > 0 ? positions.cols()
                  : !columns.empty()   ? columns.front().weights.cols()
                                       : drive.cols();
  check_path_inputs(n, P, states, fractions, positions, drive);
  const std::vector<FamilyColumns> groups = group_by_family(model, columns, P);
  PathSensitivityResult r;
  r.energy = Eigen::MatrixXd::Zero(static_cast<Index>(states.size()), P);
  if (states.empty()) return r;
  EquilibriumSensitivity s(model, states.front(), held);
  r.held_dofs = s.held_dofs();
  const auto H = static_cast<Index>(r.held_dofs.size());
  std::vector<model::ParameterDerivative> derivatives;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const VectorX& u = states[k];
    if (k > 0) s.update(u);
    if (!s.ok()) {
      throw std::runtime_error("state " + std::to_string(k) +
                               ": the tangent is singular (a limit or bifurcation point, or a "
                               "mechanism the supports leave free): it has no derivative");
    }
    Eigen::MatrixXd dforce = Eigen::MatrixXd::Zero(n, P);
    Eigen::RowVectorXd denergy = Eigen::RowVectorXd::Zero(P);
    if (positions.cols() > 0) {
      dforce = s.tangent() * positions;  // x = X + u: the positions move with X
      denergy = s.internal_force().transpose() * positions;
    }
    add_column_derivatives(model, u, groups, derivatives, dforce, denergy);
    Eigen::MatrixXd motion;
    if (drive.cols() > 0) {
      motion.resize(H, P);
      for (Index h = 0; h < H; ++h) motion.row(h) = fractions[k] * drive.row(r.held_dofs[h]);
    }
    Eigen::MatrixXd du = s.displacement(dforce, motion);
    r.held_force.push_back(s.held_force(dforce, du));
    r.energy.row(static_cast<Index>(k)) = denergy + s.internal_force().transpose() * du;
    r.displacement.push_back(std::move(du));
  }
  return r;
}

}  // namespace kresling::solvers
