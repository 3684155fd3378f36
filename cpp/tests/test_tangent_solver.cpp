// The tangent solver's paths (dense Cholesky, CHOLMOD, LDL^T with inertia, UMFPACK)
// against dense references.

#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "kresling/solvers/tangent_solver.hpp"

using namespace kresling;
using kresling::solvers::Factorization;
using kresling::solvers::SparseMatrix;
using kresling::solvers::TangentSolver;

namespace {

// A symmetric banded matrix with the given diagonal, random off-diagonal couplings.
Eigen::MatrixXd banded(int n, int bandwidth, const Eigen::VectorXd& diagonal, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    A(i, i) = diagonal[i];
    for (int j = std::max(0, i - bandwidth); j < i; ++j) A(i, j) = A(j, i) = 0.3 * u(rng);
  }
  return A;
}

SparseMatrix lower_sparse(const Eigen::MatrixXd& A) {
  SparseMatrix S = A.triangularView<Eigen::Lower>().toDenseMatrix().sparseView();
  S.makeCompressed();
  return S;
}

void expect_solves(const Eigen::MatrixXd& A, TangentSolver& solver) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 2.0);
  const Eigen::VectorXd x = solver.solve(b);
  EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm());
}

}  // namespace

TEST(TangentSolver, SmallPositiveDefiniteUsesDenseCholesky) {
  const Eigen::MatrixXd A = banded(60, 20, Eigen::VectorXd::Constant(60, 10.0), 1);
  TangentSolver solver;
  const auto info = solver.factorize(lower_sparse(A));
  EXPECT_TRUE(info.ok);
  EXPECT_EQ(info.method, Factorization::DenseCholesky);
  EXPECT_EQ(info.negative_eigenvalues, 0);
  expect_solves(A, solver);
}

TEST(TangentSolver, LargeSparsePositiveDefiniteUsesCholmod) {
  const Eigen::MatrixXd A = banded(600, 5, Eigen::VectorXd::Constant(600, 10.0), 2);
  TangentSolver solver;
  const auto info = solver.factorize(lower_sparse(A));
  EXPECT_TRUE(info.ok);
  EXPECT_EQ(info.method, Factorization::Cholesky);
  EXPECT_EQ(info.negative_eigenvalues, 0);
  expect_solves(A, solver);
}

TEST(TangentSolver, IndefiniteReportsItsInertia) {
  for (int n : {60, 600}) {  // both the dense-first and the sparse-first paths
    Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(n, 10.0);
    for (int k : {3, 17, 41}) diagonal[k] = -10.0;
    const Eigen::MatrixXd A = banded(n, 5, diagonal, 3);
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
    TangentSolver solver;
    const auto info = solver.factorize(lower_sparse(A));
    EXPECT_TRUE(info.ok);
    EXPECT_EQ(info.method, Factorization::LDLT);
    EXPECT_EQ(info.negative_eigenvalues, (eigenvalues.array() < 0).count()) << "n = " << n;
    expect_solves(A, solver);
  }
}

TEST(TangentSolver, UnusableLdltFallsBackToLu) {
  // A zero leading pivot breaks LDL^T without pivoting; LU still solves it.
  Eigen::MatrixXd A(2, 2);
  A << 0.0, 1.0, 1.0, 0.0;
  TangentSolver solver;
  const auto info = solver.factorize(lower_sparse(A));
  EXPECT_TRUE(info.ok);
  EXPECT_EQ(info.method, Factorization::LU);
  EXPECT_EQ(info.negative_eigenvalues, -1);
  expect_solves(A, solver);
}

TEST(TangentSolver, SingularMatrixIsReported) {
  SparseMatrix S(3, 3);
  for (int i = 0; i < 3; ++i) S.insert(i, i) = 0.0;
  TangentSolver solver;
  EXPECT_FALSE(solver.factorize(S).ok);
}
