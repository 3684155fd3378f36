// The tangent solver's paths (dense Cholesky, CHOLMOD simplicial and supernodal with AMD or
// nested dissection, LDL^T with inertia, UMFPACK) against dense references, and the cost
// model that chooses among the Cholesky factorisations.

#include <random>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "kresling/solvers/tangent_solver.hpp"

using namespace kresling;
using kresling::solvers::CholeskyChoice;
using kresling::solvers::Factorization;
using kresling::solvers::Ordering;
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

// The 5-point Laplacian of an m x m grid, shifted to be positive definite (lower triangle):
// the sparsity of a sheet, for which nested dissection beats AMD.
SparseMatrix grid_laplacian(int m) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      const int k = i * m + j;
      t.emplace_back(k, k, 4.01);
      if (i + 1 < m) t.emplace_back(k + m, k, -1.0);
      if (j + 1 < m) t.emplace_back(k + 1, k, -1.0);
    }
  }
  SparseMatrix S(m * m, m * m);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

// A banded positive definite matrix built sparse (lower triangle), for sizes where the
// dense helper above would be wasteful.
SparseMatrix sparse_banded(int n, int bandwidth, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double, int>> t;
  for (int j = 0; j < n; ++j) {
    t.emplace_back(j, j, 1.0 + 0.3 * 2 * bandwidth);  // diagonally dominant
    for (int i = j + 1; i <= std::min(n - 1, j + bandwidth); ++i) {
      t.emplace_back(i, j, 0.3 * u(rng));
    }
  }
  SparseMatrix S(n, n);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

void expect_solves_sparse(const SparseMatrix& lower, TangentSolver& solver) {
  const SparseMatrix A = lower.selfadjointView<Eigen::Lower>();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 2.0);
  const Eigen::VectorXd x = solver.solve(b);
  EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm());
}

void expect_solves(const Eigen::MatrixXd& A, TangentSolver& solver) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 2.0);
  const Eigen::VectorXd x = solver.solve(b);
  EXPECT_LE((A * x - b).norm(), 1e-10 * b.norm());
}

// A positive definite A: factorised by `method`, no negative eigenvalue, and solved.
void expect_positive_definite_by(const Eigen::MatrixXd& A, TangentSolver& solver,
                                 Factorization method) {
  const auto info = solver.factorize(lower_sparse(A));
  EXPECT_TRUE(info.ok);
  EXPECT_EQ(info.method, method);
  EXPECT_EQ(info.negative_eigenvalues, 0);
  expect_solves(A, solver);
}

}  // namespace

TEST(TangentSolver, SmallPositiveDefiniteUsesDenseCholesky) {
  TangentSolver solver;
  expect_positive_definite_by(banded(24, 20, Eigen::VectorXd::Constant(24, 10.0), 1), solver,
                              Factorization::DenseCholesky);
}

// The dense path factorises in place with the blocked algorithm Eigen::LLT runs: its solves
// must equal LLT's bit for bit (the sweeps' results must not move), also on a refactorisation
// of new values on the same pattern, where the previous factor's fill-in must be cleared.
// 136 DOFs (a four-cell n = 10 bending specimen) factorises in blocks of 16.
TEST(TangentSolver, DenseCholeskyEqualsEigenLltBitForBit) {
  TangentSolver solver(CholeskyChoice::Dense);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(136, -1.0, 2.0);
  for (unsigned seed : {3u, 4u, 5u}) {
    Eigen::VectorXd diagonal = Eigen::VectorXd::LinSpaced(136, 9.0, 14.0);
    diagonal *= seed;
    const Eigen::MatrixXd A = banded(136, 40, diagonal, seed);
    ASSERT_TRUE(solver.factorize(lower_sparse(A)).ok);
    const Eigen::VectorXd expected = Eigen::LLT<Eigen::MatrixXd, Eigen::Lower>(A).solve(b);
    const Eigen::VectorXd x = solver.solve(b);
    for (Index i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], expected[i]) << "entry " << i;
  }
}

TEST(TangentSolver, LargerPositiveDefiniteUsesTheSupernodalCholesky) {
  for (int n : {60, 600}) {
    TangentSolver solver;
    expect_positive_definite_by(banded(n, 5, Eigen::VectorXd::Constant(n, 10.0), 2), solver,
                                Factorization::SupernodalCholesky);
  }
}

TEST(TangentSolver, ForcedSimplicialUsesCholmod) {
  TangentSolver solver(CholeskyChoice::Simplicial);
  expect_positive_definite_by(banded(600, 5, Eigen::VectorXd::Constant(600, 10.0), 2), solver,
                              Factorization::Cholesky);
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

// The cost model's decisions (benchmarks/cpp/factorisation_cost.cpp): dense below 32 DOFs
// (18 DOFs: 1 us either way), the supernodal factorisation with Eigen's kernels above it
// (54 DOFs: 5 us against dense 7; the 427-DOF GMiura sheet: 106 us against CHOLMOD's
// simplicial 280; a 100,233-DOF sheet: 0.46 s against CHOLMOD's supernodal 1.83 s).
TEST(TangentSolver, CostModelChoosesByMeasuredCost) {
  EXPECT_EQ(solvers::choose_cholesky(18), CholeskyChoice::Dense);
  EXPECT_EQ(solvers::choose_cholesky(54), CholeskyChoice::Supernodal);
  EXPECT_EQ(solvers::choose_cholesky(136), CholeskyChoice::Supernodal);
  EXPECT_EQ(solvers::choose_cholesky(427), CholeskyChoice::Supernodal);
  EXPECT_EQ(solvers::choose_cholesky(100233), CholeskyChoice::Supernodal);
}

TEST(TangentSolver, EveryForcedCholeskySolves) {
  const Eigen::MatrixXd A = banded(300, 8, Eigen::VectorXd::Constant(300, 10.0), 4);
  const std::pair<CholeskyChoice, Factorization> paths[] = {
      {CholeskyChoice::Dense, Factorization::DenseCholesky},
      {CholeskyChoice::Simplicial, Factorization::Cholesky},
      {CholeskyChoice::Supernodal, Factorization::SupernodalCholesky}};
  for (const auto& [choice, method] : paths) {
    TangentSolver solver(choice);
    for (int repeat = 0; repeat < 2; ++repeat) {  // the second call reuses the analysis
      const auto info = solver.factorize(lower_sparse(A));
      EXPECT_TRUE(info.ok);
      EXPECT_EQ(info.method, method);
      EXPECT_EQ(info.negative_eigenvalues, 0);
      expect_solves(A, solver);
    }
    EXPECT_EQ(solver.plan().cholesky, choice);
  }
}

TEST(TangentSolver, SupernodalPathAlsoFindsTheInertia) {
  Eigen::VectorXd diagonal = Eigen::VectorXd::Constant(300, 10.0);
  diagonal[7] = diagonal[150] = -10.0;
  const Eigen::MatrixXd A = banded(300, 5, diagonal, 5);
  TangentSolver solver(CholeskyChoice::Supernodal);
  const auto info = solver.factorize(lower_sparse(A));
  EXPECT_TRUE(info.ok);
  EXPECT_EQ(info.method, Factorization::LDLT);
  EXPECT_EQ(info.negative_eigenvalues, 2);
  expect_solves(A, solver);
}

TEST(TangentSolver, HighFlopsPerEntryChoosesSupernodal) {
  // 2,400 DOFs with a band of 300: ~300 flops per factor entry, 2e8 flops in all, so the
  // supernodal factorisation runs its threaded path.
  const SparseMatrix S = sparse_banded(2400, 300, 6);
  TangentSolver solver;
  const auto info = solver.factorize(S);
  EXPECT_TRUE(info.ok);
  EXPECT_EQ(info.method, Factorization::SupernodalCholesky);
  EXPECT_GE(solver.plan().flops / solver.plan().factor_nonzeros, 250.0);
  EXPECT_GE(solver.plan().flops, 1e8);
  expect_solves_sparse(S, solver);
}

TEST(TangentSolver, SheetsGetNestedDissectionChainsAmd) {
  // A 90 x 90 grid (8,100 DOFs): nested dissection needs fewer flops than AMD.
  const SparseMatrix grid = grid_laplacian(90);
  TangentSolver sheet;
  EXPECT_TRUE(sheet.factorize(grid).ok);
  EXPECT_EQ(sheet.plan().ordering, Ordering::NestedDissection);
  expect_solves_sparse(grid, sheet);
  // A long narrow band (a tower's tangent is one): AMD's ordering is already optimal.
  const SparseMatrix chain = sparse_banded(3000, 4, 7);
  TangentSolver tower;
  EXPECT_TRUE(tower.factorize(chain).ok);
  EXPECT_EQ(tower.factorize(chain).method, Factorization::SupernodalCholesky);
  EXPECT_EQ(tower.plan().ordering, Ordering::AMD);
  expect_solves_sparse(chain, tower);
  // Below kTryNestedDissection DOFs only AMD is tried (its analysis is the cheapest).
  TangentSolver small;
  EXPECT_TRUE(small.factorize(grid_laplacian(30)).ok);
  EXPECT_EQ(small.plan().ordering, Ordering::AMD);
}

TEST(TangentSolver, LargeIndefiniteUsesCholmodLdltWithTheInertia) {
  // 3,000 DOFs, strictly diagonally dominant (off-diagonal row sums <= 3 against |10| on the
  // diagonal): by Gershgorin the negative eigenvalues are exactly as many as the negative
  // diagonal entries, an independent count of the inertia.
  const int n = 3000;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double, int>> t;
  int negative = 0;
  for (int j = 0; j < n; ++j) {
    const bool flip = j % 97 == 5;
    negative += flip;
    t.emplace_back(j, j, flip ? -10.0 : 10.0);
    for (int i = j + 1; i <= std::min(n - 1, j + 5); ++i) t.emplace_back(i, j, 0.3 * u(rng));
  }
  SparseMatrix S(n, n);
  S.setFromTriplets(t.begin(), t.end());
  for (const auto choice : {CholeskyChoice::Auto, CholeskyChoice::Supernodal}) {
    TangentSolver solver(choice);
    for (int repeat = 0; repeat < 2; ++repeat) {
      const auto info = solver.factorize(S);
      EXPECT_TRUE(info.ok);
      EXPECT_EQ(info.method, Factorization::LDLT);
      EXPECT_EQ(info.negative_eigenvalues, negative);
      expect_solves_sparse(S, solver);
    }
  }
}
