#pragma once
/// \file tangent_solver.hpp
/// Factorise a symmetric tangent and solve with it, reporting its inertia.
///
/// CHOLMOD's simplicial Cholesky first (positive definite: a stable equilibrium, no
/// negative eigenvalues); for small tangents whose lower triangle is at least 10 % full
/// (up to 400 DOFs) a dense Cholesky instead, which is faster there. When that fails the tangent is indefinite: a sparse LDL^T
/// (Eigen's simplicial factorisation with AMD ordering) gives the count of negative
/// eigenvalues by Sylvester's law of inertia; if its pivots are unusable (an exactly
/// singular or badly conditioned leading block) UMFPACK's LU solves instead and the inertia
/// is reported unknown (-1). The symbolic analysis is done once per pattern.

#include <memory>

#include <Eigen/SparseCore>

#include "kresling/core/types.hpp"

namespace kresling::solvers {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class Factorization : int { None = 0, Cholesky = 1, LDLT = 2, LU = 3, DenseCholesky = 4 };

struct FactorizeInfo {
  bool ok = false;                 ///< a usable factorisation exists
  Factorization method = Factorization::None;
  int negative_eigenvalues = -1;   ///< inertia, or -1 when unknown (LU)
};

class TangentSolver {
 public:
  TangentSolver();
  ~TangentSolver();
  TangentSolver(const TangentSolver&) = delete;
  TangentSolver& operator=(const TangentSolver&) = delete;

  /// Factorise the symmetric K, of which only the lower triangle is read (store it whole or
  /// just that triangle). The pattern is analysed on the first call and must stay the same.
  FactorizeInfo factorize(const SparseMatrix& K);

  /// Solve K x = b with the last successful factorisation.
  VectorX solve(const VectorX& b) const;
  /// Solve for several right-hand sides (columns of B) with one factorisation.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace kresling::solvers
