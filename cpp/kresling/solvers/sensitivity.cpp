#include "kresling/solvers/sensitivity.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kresling/solvers/path_point.hpp"
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
  // Column by column, gathering and scattering the free rows (a row expression per DOF
  // costs more than its few entries).
  Eigen::MatrixXd rhs(nf, P);
  for (Index p = 0; p < P; ++p) {
    for (Index r = 0; r < nf; ++r) {
      const Index d = free_dofs_[r];
      rhs(r, p) = moving ? -(dresidual(d, p) + coupled(d, p)) : -dresidual(d, p);
    }
  }
  const Eigen::MatrixXd x = solver_->solve(rhs);
  for (Index p = 0; p < P; ++p) {
    for (Index r = 0; r < nf; ++r) du(free_dofs_[r], p) = x(r, p);
  }
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
      // Plain strided loops: an Eigen row expression per triplet costs more than its
      // P multiply-adds (thousands of triplets per state).
      const Index P = W.cols(), n = dforce.rows(), m = W.rows();
      double* out = dforce.data();
      const double* w = W.data();
      for (const auto& t : d.force) {
        const double v = t.value();
        const Index r = t.row(), c = t.col();
        for (Index p = 0; p < P; ++p) out[p * n + r] += v * w[p * m + c];
      }
      denergy += d.energy.transpose() * W;
    }
  }
}

// The derivatives of states of one path with respect to P variables, on one factorisation
// workspace: what path_sensitivity and interpolated_path_sensitivity share.
class PathDifferentiator {
 public:
  PathDifferentiator(const model::Model& model, const VectorX& first,
                     const std::vector<Index>& held, const Eigen::MatrixXd& positions,
                     const std::vector<ColumnMotion>& columns, const Eigen::MatrixXd& drive,
                     Index P)
      : model_(model),
        positions_(positions),
        drive_(drive),
        P_(P),
        groups_(group_by_family(model, columns, P)),
        s_(model, first, held),
        factorised_at_(first) {}

  const std::vector<Index>& held_dofs() const { return s_.held_dofs(); }
  const EquilibriumSensitivity& factorised() const { return s_; }

  // One equilibrium at path parameter t, factorised there (once: a state factorised last,
  // the first one at construction, is not factorised again).
  struct State {
    Eigen::MatrixXd du;      // 3N x P
    Eigen::MatrixXd dforce;  // d f_int/dp along the equilibrium (total), 3N x P
    Eigen::RowVectorXd denergy;
  };
  State at(const VectorX& u, double t, const std::string& where) {
    if (u.size() != factorised_at_.size() || u != factorised_at_) {
      s_.update(u);
      factorised_at_ = u;
    }
    if (!s_.ok()) {
      throw std::runtime_error(where +
                               ": the tangent is singular (a limit or bifurcation point, or a "
                               "mechanism the supports leave free): it has no derivative");
    }
    State out;
    partials(u, s_.tangent(), s_.internal_force(), out.dforce, out.denergy);
    out.du = s_.displacement(out.dforce, held_rows(drive_, t));
    out.denergy += s_.internal_force().transpose() * out.du;
    out.dforce += s_.tangent() * out.du;
    return out;
  }

  // The residual's partial derivatives at u at fixed u (3N x P) and the energy's: the
  // positions' motion through the tangent (x = X + u), the columns' own.
  void partials(const VectorX& u, const SparseMatrix& K, const VectorX& f, Eigen::MatrixXd& dforce,
                Eigen::RowVectorXd& denergy) {
    dforce = Eigen::MatrixXd::Zero(model_.num_dofs(), P_);
    denergy = Eigen::RowVectorXd::Zero(P_);
    if (positions_.cols() > 0) {
      dforce = K * positions_;
      denergy = f.transpose() * positions_;
    }
    add_column_derivatives(model_, u, groups_, derivatives_, dforce, denergy);
  }

  // The held DOFs' motion per variable: `scale` times the drive's rows (empty: none).
  Eigen::MatrixXd held_rows(const Eigen::MatrixXd& drive, double scale) const {
    Eigen::MatrixXd motion;
    if (drive.cols() == 0) return motion;
    const std::vector<Index>& h = s_.held_dofs();
    motion.resize(static_cast<Index>(h.size()), P_);
    for (std::size_t k = 0; k < h.size(); ++k) motion.row(static_cast<Index>(k)) = scale * drive.row(h[k]);
    return motion;
  }

  Eigen::MatrixXd held_of(const Eigen::MatrixXd& full) const {
    const std::vector<Index>& h = s_.held_dofs();
    Eigen::MatrixXd out(static_cast<Index>(h.size()), full.cols());
    for (std::size_t k = 0; k < h.size(); ++k) out.row(static_cast<Index>(k)) = full.row(h[k]);
    return out;
  }

 private:
  const model::Model& model_;
  const Eigen::MatrixXd& positions_;
  const Eigen::MatrixXd& drive_;
  const Index P_;
  const std::vector<FamilyColumns> groups_;
  EquilibriumSensitivity s_;
  VectorX factorised_at_;  // the state s_ holds the factorisation of
  std::vector<model::ParameterDerivative> derivatives_;
};

// One state's derivatives, as state k of a path's result.
void record(PathSensitivityResult& r, std::size_t k, const PathDifferentiator& d,
            PathDifferentiator::State&& x) {
  r.held_force.push_back(d.held_of(x.dforce));
  r.energy.row(static_cast<Index>(k)) = x.denergy;
  r.displacement.push_back(std::move(x.du));
}

Index variable_count(const Eigen::MatrixXd& positions, const std::vector<ColumnMotion>& columns,
                     const Eigen::MatrixXd& drive) {
  return positions.cols() > 0 ? positions.cols()
         : !columns.empty()   ? columns.front().weights.cols()
                              : drive.cols();
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
  const Index P = variable_count(positions, columns, drive);
  check_path_inputs(n, P, states, fractions, positions, drive);
  PathSensitivityResult r;
  r.energy = Eigen::MatrixXd::Zero(static_cast<Index>(states.size()), P);
  if (states.empty()) return r;
  PathDifferentiator d(model, states.front(), held, positions, columns, drive, P);
  r.held_dofs = d.held_dofs();
  for (std::size_t k = 0; k < states.size(); ++k) {
    record(r, k, d, d.at(states[k], fractions[k], "state " + std::to_string(k)));
  }
  return r;
}

namespace {

// How far along the path tangent the knots' rates are differenced, relative to the model's
// size: measured on the bending specimen (bars 1e5 times stiffer than hinges), 1e-5 leaves
// 1.5e-6 of truncation, 1e-7 2e-6 of rounding, 1e-6 about 2e-7 of either.
constexpr double kRateReach = 1e-6;

// A knot's derivatives and their rates along the path.
struct KnotDerivative {
  Eigen::MatrixXd du, du_rate;          // 3N x P
  Eigen::MatrixXd force, force_rate;    // held DOFs x P
  Eigen::RowVectorXd energy, energy_rate;
};

// The model's size: the largest extent of its nodes' box [mm].
double model_size(const model::Model& model) {
  const auto& X = model.nodes();
  if (X.rows() == 0) return 1.0;
  const double size = (X.colwise().maxCoeff() - X.colwise().minCoeff()).maxCoeff();
  return size > 0.0 ? size : 1.0;
}

void check_knots(Index n, const std::vector<VectorX>& states, const PathKnots& knots) {
  const std::size_t m = knots.t.size();
  if (knots.u.size() != m || knots.velocity.size() != m) {
    throw std::invalid_argument("knots: t, u and velocity must have one entry per knot");
  }
  for (std::size_t j = 0; j < m; ++j) {
    if (knots.u[j].size() != n || knots.velocity[j].size() != n) {
      throw std::invalid_argument("knot " + std::to_string(j) + ": u and velocity must have 3N = " +
                                  std::to_string(n) + " entries");
    }
    if (j > 0 && !(knots.t[j] > knots.t[j - 1])) {
      throw std::invalid_argument("knots: t must increase (knot " + std::to_string(j) + ")");
    }
  }
  if (knots.step_knot.size() != states.size()) {
    throw std::invalid_argument("step_knot: must have one entry per state (" +
                                std::to_string(states.size()) + ")");
  }
  for (int j : knots.step_knot) {
    if (j != -1 && (j < 1 || static_cast<std::size_t>(j) >= m)) {
      throw std::invalid_argument("step_knot: " + std::to_string(j) +
                                  " is not -1 or a knot after the first");
    }
  }
}

// A knot's derivatives and their rates along the path (interpolated_path_sensitivity):
// factorised at the knot, the rate of dr/dp + K s by a central difference between the
// states u +- h v (|h v| = reach) evaluated by `probe`.
KnotDerivative knot_derivative(PathDifferentiator& d, assembly::Assembler& probe,
                               const PathKnots& knots, std::size_t j, double reach,
                               const Eigen::MatrixXd& drive) {
  PathDifferentiator::State x = d.at(knots.u[j], knots.t[j], "knot " + std::to_string(j));
  const VectorX& v = knots.velocity[j];
  const double speed = v.lpNorm<Eigen::Infinity>();
  Eigen::MatrixXd rate = Eigen::MatrixXd::Zero(x.du.rows(), x.du.cols());
  if (speed > 0.0) {
    const double h = reach / speed;
    for (const double side : {1.0, -1.0}) {
      const VectorX w = knots.u[j] + side * h * v;
      VectorX f;
      probe.assemble(w, f, /*with_matrix=*/true);
      Eigen::MatrixXd g;
      Eigen::RowVectorXd unused;
      d.partials(w, probe.matrix(), f, g, unused);
      g += probe.matrix() * x.du;
      rate += (side / (2.0 * h)) * g;
    }
  }
  const EquilibriumSensitivity& s = d.factorised();
  KnotDerivative k;
  k.du_rate = s.displacement(rate, d.held_rows(drive, 1.0));
  k.force = d.held_of(x.dforce);
  k.force_rate = d.held_of(rate + s.tangent() * k.du_rate);
  k.energy = x.denergy;
  k.energy_rate = v.transpose() * x.dforce + s.internal_force().transpose() * k.du_rate;
  k.du = std::move(x.du);
  return k;
}

}  // namespace

PathSensitivityResult interpolated_path_sensitivity(const model::Model& model,
                                                    const std::vector<VectorX>& states,
                                                    const std::vector<double>& fractions,
                                                    const PathKnots& knots,
                                                    const std::vector<Index>& held,
                                                    const Eigen::MatrixXd& positions,
                                                    const std::vector<ColumnMotion>& columns,
                                                    const Eigen::MatrixXd& drive) {
  const Index n = model.num_dofs();
  const Index P = variable_count(positions, columns, drive);
  check_path_inputs(n, P, states, fractions, positions, drive);
  check_knots(n, states, knots);
  PathSensitivityResult r;
  r.energy = Eigen::MatrixXd::Zero(static_cast<Index>(states.size()), P);
  if (states.empty()) return r;
  const VectorX& first = knots.u.empty() ? states.front() : knots.u.front();
  PathDifferentiator d(model, first, held, positions, columns, drive, P);
  r.held_dofs = d.held_dofs();
  // The probe states either side of a knot along its path tangent.
  assembly::Workspace probe_workspace = d.factorised().workspace();
  assembly::Assembler probe(model, probe_workspace);
  const double reach = kRateReach * model_size(model);
  std::vector<KnotDerivative> at_knot(knots.t.size());
  std::vector<bool> done(knots.t.size(), false);
  const auto knot = [&](std::size_t j) -> const KnotDerivative& {
    if (!done[j]) at_knot[j] = knot_derivative(d, probe, knots, j, reach, drive);
    done[j] = true;
    return at_knot[j];
  };
  for (std::size_t i = 0; i < states.size(); ++i) {
    const int j = knots.step_knot[i];
    if (j < 0) {
      record(r, i, d, d.at(states[i], fractions[i], "state " + std::to_string(i)));
      continue;
    }
    const double ta = knots.t[j - 1], tb = knots.t[j], t = fractions[i];
    const KnotDerivative& a = knot(static_cast<std::size_t>(j - 1));
    const KnotDerivative& b = knot(static_cast<std::size_t>(j));
    r.displacement.push_back(hermite<Eigen::MatrixXd>(ta, a.du, a.du_rate, tb, b.du, b.du_rate, t));
    r.held_force.push_back(hermite<Eigen::MatrixXd>(ta, a.force, a.force_rate, tb, b.force, b.force_rate, t));
    r.energy.row(static_cast<Index>(i)) =
        hermite<Eigen::RowVectorXd>(ta, a.energy, a.energy_rate, tb, b.energy, b.energy_rate, t);
  }
  return r;
}

}  // namespace kresling::solvers
