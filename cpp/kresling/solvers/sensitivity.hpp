#pragma once
/// \file sensitivity.hpp
/// The sensitivity of an equilibrium to parameters, from its tangent.
///
/// At an equilibrium r(u, p) = f_int(u, p) - f_ext = 0 with the held DOFs c (supports, and
/// the DOFs a displacement control prescribes) at given values, the free DOFs f satisfy
/// r_f = 0 for every p. Differentiating,
///
///     K_ff du_f/dp = -(d r_f/dp + K_fc du_c/dp)            (direct: one solve per parameter)
///     d f_c/dp     = d f_int,c/dp + K_cf du_f/dp + K_cc du_c/dp   (the held DOFs' forces)
///
/// with K the tangent d f_int/du (exact, unshifted: the equilibrium is that of f_int) and
/// d r/dp the partial derivative at fixed u (assembly/parameter_jacobian.hpp, minus any
/// change of the applied loads). For a scalar J(u, p) the adjoint gives every parameter's
/// derivative with one solve:
///
///     K_ff lambda = dJ/du_f,    dJ/dp = dJ/dp|_u - lambda^T (d r_f/dp + K_fc du_c/dp)
///                                       + dJ/du_c du_c/dp.
///
/// K_ff is factorised once per state (tangent_solver.hpp), and the states of a path reuse
/// one assembly workspace and one symbolic analysis (update()). It must be nonsingular: at
/// a limit or bifurcation point the derivative of the state does not exist (a path's limit
/// load has its own derivative, which the analyses give).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/workspace.hpp"
#include "kresling/core/types.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

class EquilibriumSensitivity {
 public:
  /// Factorise the tangent of `model` at u with its supports and the DOFs `held` (each in
  /// range, not supported, listed once; throws std::invalid_argument otherwise) held.
  EquilibriumSensitivity(const model::Model& model, const VectorX& u, const std::vector<Index>& held);

  EquilibriumSensitivity(const EquilibriumSensitivity&) = delete;
  EquilibriumSensitivity& operator=(const EquilibriumSensitivity&) = delete;

  /// Factorise again at another state u of the same model (the next step of a path): the
  /// workspace and the symbolic analysis are reused.
  void update(const VectorX& u);

  /// False when K_ff is singular (then every solve throws std::runtime_error).
  bool ok() const { return info_.ok; }
  /// Negative eigenvalues of K_ff (0: a stable equilibrium; -1: unknown).
  int negative_eigenvalues() const { return info_.negative_eigenvalues; }
  /// Every held DOF: the model's supports in DOF order, then `held` in its order.
  const std::vector<Index>& held_dofs() const { return held_dofs_; }
  /// The tangent d f_int/du at the state (3N x 3N, symmetric, unshifted).
  const SparseMatrix& tangent() const { return assembler_->matrix(); }
  /// The assembly workspace (every DOF, unshifted): a copy evaluates the model at other
  /// states without building the pattern again.
  const assembly::Workspace& workspace() const { return assembler_->workspace(); }
  /// The internal force f_int at the state (3N).
  const VectorX& internal_force() const { return force_; }

  /// du/dp, 3N x P, for the residual's partial derivatives `dresidual` (3N x P) and the
  /// held DOFs' motion `held_motion` (held_dofs().size() x P; empty: they do not move).
  Eigen::MatrixXd displacement(const Eigen::MatrixXd& dresidual,
                               const Eigen::MatrixXd& held_motion = Eigen::MatrixXd()) const;
  /// d f_int/dp at the held DOFs (held_dofs().size() x P): the internal-force partials
  /// `dforce` (3N x P) plus the tangent along `du` (3N x P, from displacement()).
  Eigen::MatrixXd held_force(const Eigen::MatrixXd& dforce, const Eigen::MatrixXd& du) const;
  /// The adjoint lambda (3N, zero at the held DOFs) of K_ff lambda = g_f.
  VectorX adjoint(const VectorX& g) const;

 private:
  void require_ok() const;

  model::Model model_;                           // the assembler binds to this copy
  std::unique_ptr<assembly::Assembler> assembler_;  // its matrix: the tangent at the state
  VectorX force_;
  std::vector<Index> held_dofs_;
  std::vector<Index> free_row_;  // per DOF: its row in K_ff, or -1 if held
  std::vector<Index> free_dofs_;
  std::unique_ptr<TangentSolver> solver_;
  SparseMatrix Kff_;                // the last factorised K_ff
  std::vector<int> kff_slot_;       // per entry of K: its place in Kff_'s values, or -1
  std::vector<int> k_outer_, k_inner_;  // K's pattern when kff_slot_ was made
  FactorizeInfo info_;
};

/// How one parameter column moves per unit of each of P variables: its entries x P
/// (assembly/parameter_jacobian.hpp orders the entries).
struct ColumnMotion {
  std::string family;
  std::string column;
  Eigen::MatrixXd weights;
};

/// The derivatives of a path's states with respect to P variables.
struct PathSensitivityResult {
  std::vector<Index> held_dofs;                ///< as EquilibriumSensitivity::held_dofs
  std::vector<Eigen::MatrixXd> displacement;   ///< per state: du/dp, 3N x P
  std::vector<Eigen::MatrixXd> held_force;     ///< per state: d f_int/dp at held_dofs, H x P
  Eigen::MatrixXd energy;                      ///< states x P: dE/dp along each equilibrium
};

/// Differentiate the equilibria `states` of a path (each 3N) with respect to P variables,
/// one factorisation per state on one workspace and one symbolic analysis. Each variable
/// moves the reference positions by a column of `positions` (3N x P; no columns: none moves
/// them; the rest values that hold the reference geometry must already be in `columns`),
/// the parameter columns by `columns`, and the held DOFs by fractions[k] times its column of
/// `drive` (3N x P, read at the held DOFs; no columns: they stay). Per state the residual's
/// partial derivative is K positions + sum_c G_c W_c. Throws std::invalid_argument for
/// mismatched sizes or names, std::runtime_error naming the state where the tangent is
/// singular.
PathSensitivityResult path_sensitivity(const model::Model& model,
                                       const std::vector<VectorX>& states,
                                       const std::vector<double>& fractions,
                                       const std::vector<Index>& held,
                                       const Eigen::MatrixXd& positions,
                                       const std::vector<ColumnMotion>& columns,
                                       const Eigen::MatrixXd& drive);

/// The knots of an adaptive path and how its samples were read from them (path.hpp:
/// PathResult::knots, step_knot).
struct PathKnots {
  std::vector<double> t;          ///< per knot, increasing
  std::vector<VectorX> u;         ///< per knot, all DOFs
  std::vector<VectorX> velocity;  ///< per knot, du/dt, all DOFs
  std::vector<int> step_knot;     ///< per state: the knot ending its curve, or -1
};

/// As path_sensitivity, for a path in adaptive increments whose `states` were read off the
/// cubic Hermite curves between `knots` (the rest, step_knot -1, converged on their own and
/// differentiated as path_sensitivity does). Only the knots are factorised. A sample's
/// value is the Hermite combination of its knots' values and path rates, so its derivative
/// is the same combination of the knots' derivatives s = du/dp and of their rates
/// ds/dt = d(du/dt)/dp (the knots' t held), which solves
///
///     K_ff ds_f/dt = -[d/dt (dr/dp + K s)]_f - K_fc ds_c/dt,
///
/// the bracket the derivative along the path at fixed s (the residual's mixed second
/// derivative), taken by a central difference along du/dt with a step of 1e-6 of the
/// model's size (its error, ~1e-9 of the derivative, is measured in the tests). The
/// recorded forces' and the energy's rates follow as d/dp (K du/dt) = d/dt(dr/dp + K s) +
/// K ds/dt and d/dp (f . du/dt). Only for paths of a fixed model (no rest angles moving
/// with t) whose loads do not depend on the variables. Throws as path_sensitivity, and
/// std::invalid_argument for knots and states that do not match.
PathSensitivityResult interpolated_path_sensitivity(const model::Model& model,
                                                    const std::vector<VectorX>& states,
                                                    const std::vector<double>& fractions,
                                                    const PathKnots& knots,
                                                    const std::vector<Index>& held,
                                                    const Eigen::MatrixXd& positions,
                                                    const std::vector<ColumnMotion>& columns,
                                                    const Eigen::MatrixXd& drive);

}  // namespace kresling::solvers
