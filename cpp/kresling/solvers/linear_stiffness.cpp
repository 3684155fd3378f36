#include "kresling/solvers/linear_stiffness.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

assembly::SparseMatrix tangent_matrix(const model::Model& model, const VectorX& u, double shift) {
  assembly::Assembler assembler(model, assembly::all_dofs(model.num_dofs()), shift);
  VectorX force;
  assembler.assemble(u, force, /*with_matrix=*/true);
  return assembler.matrix();
}

Eigen::MatrixXd condensed_stiffness(const model::Model& model, const VectorX& u,
                                    const std::vector<Index>& dofs, bool* singular) {
  const Index n = model.num_dofs();
  std::vector<std::uint8_t> held = model.fixed();
  for (Index d : dofs) {
    if (d < 0 || d >= n) {
      throw std::invalid_argument("dofs: DOF " + std::to_string(d) + " is out of range");
    }
    if (model.fixed()[d]) {
      throw std::invalid_argument("dofs: DOF " + std::to_string(d) + " is supported");
    }
    if (held[d] == 2) throw std::invalid_argument("dofs: DOF " + std::to_string(d) + " repeats");
    held[d] = 2;
  }
  const assembly::SparseMatrix K = tangent_matrix(model, u);
  // Split into free (f) and condensed (p) blocks.
  std::vector<Index> free_rows(n, -1);
  Index nf = 0;
  for (Index i = 0; i < n; ++i) {
    if (held[i] == 0) free_rows[i] = nf++;
  }
  const Index np = static_cast<Index>(dofs.size());
  std::vector<Index> p_rows(n, -1);
  for (Index k = 0; k < np; ++k) p_rows[dofs[k]] = k;
  std::vector<Eigen::Triplet<double, int>> ff;
  Eigen::MatrixXd Kfp = Eigen::MatrixXd::Zero(nf, np), Kpp = Eigen::MatrixXd::Zero(np, np);
  for (int col = 0; col < K.outerSize(); ++col) {
    for (assembly::SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const Index r = it.row(), c = it.col();
      if (free_rows[r] >= 0 && free_rows[c] >= 0) ff.emplace_back(free_rows[r], free_rows[c], it.value());
      if (free_rows[r] >= 0 && p_rows[c] >= 0) Kfp(free_rows[r], p_rows[c]) += it.value();
      if (p_rows[r] >= 0 && p_rows[c] >= 0) Kpp(p_rows[r], p_rows[c]) += it.value();
    }
  }
  SparseMatrix Kff(nf, nf);
  Kff.setFromTriplets(ff.begin(), ff.end());
  TangentSolver solver;
  const FactorizeInfo info = solver.factorize(Kff);
  if (singular) *singular = !info.ok;
  if (!info.ok) {
    return Eigen::MatrixXd::Constant(np, np, std::numeric_limits<double>::quiet_NaN());
  }
  const Eigen::MatrixXd X = solver.solve(Kfp);
  return Kpp - Kfp.transpose() * X;
}

}  // namespace kresling::solvers
