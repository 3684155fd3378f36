// The supernodal Cholesky with Eigen's kernels against CHOLMOD's simplicial factorisation
// (an independent implementation on the same matrices) and against the residual itself.

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>

#include "kresling/solvers/supernodal_cholesky.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace {

using kresling::solvers::SupernodalCholesky;
using SparseMatrix = SupernodalCholesky::SparseMatrix;

// A sheet-like tangent: an m x m grid of nodes with 3 DOFs each, every grid edge and
// diagonal a random symmetric positive semi-definite 6 x 6 element, plus `shift` on the
// diagonal. Stored whole (both triangles), as the assembler's callers may pass it.
SparseMatrix sheet(int m, double shift, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> entries;
  auto node = [m](int i, int j) { return i * m + j; };
  auto element = [&](int a, int b) {
    Eigen::Matrix<double, 6, 6> R;
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) R(r, c) = uniform(random);
    const Eigen::Matrix<double, 6, 6> E = R * R.transpose();
    const int dofs[6] = {3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2};
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) entries.emplace_back(dofs[r], dofs[c], E(r, c));
  };
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < m; ++j) {
      if (i + 1 < m) element(node(i, j), node(i + 1, j));
      if (j + 1 < m) element(node(i, j), node(i, j + 1));
      if (i + 1 < m && j + 1 < m) element(node(i, j), node(i + 1, j + 1));
    }
  }
  const int n = 3 * m * m;
  for (int k = 0; k < n; ++k) entries.emplace_back(k, k, shift);
  SparseMatrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  return K;
}

Eigen::VectorXd right_hand_side(int n) {
  return Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();
}

Eigen::VectorXd cholmod_solution(const SparseMatrix& K, const Eigen::VectorXd& b) {
  Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> reference(K);
  EXPECT_EQ(reference.info(), Eigen::Success);
  return reference.solve(b);
}

}  // namespace

// Both orderings CHOLMOD offers, one to three threads: the solution equals CHOLMOD's to
// 1e-12 relative (these matrices' condition numbers are ~1e3: both are accurate to ~1e-13).
TEST(SupernodalCholesky, SolvesAsCholmodDoes) {
  for (int m : {4, 12, 30}) {
    const SparseMatrix K = sheet(m, 0.5, 7u + m);
    const Eigen::VectorXd b = right_hand_side(K.rows());
    const Eigen::VectorXd expected = cholmod_solution(K, b);
    for (int ordering : {CHOLMOD_AMD, CHOLMOD_NESDIS}) {
      for (int threads : {1, 2, 3}) {
        SupernodalCholesky ours;
        ours.analyze(K, ordering, threads);
        ASSERT_TRUE(ours.factorize(K)) << "m " << m << " threads " << threads;
        const Eigen::VectorXd x = ours.solve(b);
        EXPECT_LE((x - expected).norm(), 1e-12 * expected.norm())
            << "m " << m << " ordering " << ordering << " threads " << threads;
        EXPECT_LE((K * x - b).norm(), 1e-12 * b.norm());
      }
    }
  }
}

// A large sheet splits into subtrees for the threads: the factor then sums each
// supernode's updates in another order, equal to rounding.
TEST(SupernodalCholesky, ThreadsChangeOnlyTheRounding) {
  const SparseMatrix K = sheet(60, 0.5, 11u);
  const Eigen::VectorXd b = right_hand_side(K.rows());
  SupernodalCholesky one, two;
  one.analyze(K, CHOLMOD_NESDIS, 1);
  two.analyze(K, CHOLMOD_NESDIS, 2);
  ASSERT_TRUE(one.factorize(K));
  ASSERT_TRUE(two.factorize(K));
  const Eigen::VectorXd x1 = one.solve(b), x2 = two.solve(b);
  EXPECT_LE((x1 - x2).norm(), 1e-13 * x1.norm());
  EXPECT_EQ(one.factor_nonzeros(), two.factor_nonzeros());
  EXPECT_GT(one.supernodes(), 1);
  EXPECT_EQ(one.working_threads(), 1);
  EXPECT_EQ(two.working_threads(), 2);  // nested dissection's halves, one per thread
}

// New values on the analysed pattern: the factor starts again from the matrix (nothing of
// the previous factorisation's fill is left), whichever triangle is stored.
TEST(SupernodalCholesky, RefactorisesNewValuesOnTheSamePattern) {
  const SparseMatrix first = sheet(10, 0.5, 1u), second = sheet(10, 2.0, 2u);
  SupernodalCholesky ours;
  ours.analyze(first, CHOLMOD_AMD);
  const Eigen::VectorXd b = right_hand_side(first.rows());
  for (const SparseMatrix* K : {&first, &second, &first}) {
    ASSERT_TRUE(ours.factorize(*K));
    const Eigen::VectorXd expected = cholmod_solution(*K, b);
    EXPECT_LE((ours.solve(b) - expected).norm(), 1e-12 * expected.norm());
  }
  // Only the lower triangle is read: a lower-triangle copy gives the same factor.
  const SparseMatrix lower = first.triangularView<Eigen::Lower>();
  SupernodalCholesky from_lower;
  from_lower.analyze(lower, CHOLMOD_AMD);
  ASSERT_TRUE(from_lower.factorize(lower));
  ASSERT_TRUE(ours.factorize(first));
  const Eigen::VectorXd x = ours.solve(b), y = from_lower.solve(b);
  for (Eigen::Index i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], y[i]) << "entry " << i;
}

// Not positive definite (a negative eigenvalue, or a NaN): factorize says so.
TEST(SupernodalCholesky, RefusesMatricesThatAreNotPositiveDefinite) {
  SparseMatrix K = sheet(8, 0.5, 3u);
  SupernodalCholesky ours;
  ours.analyze(K, CHOLMOD_AMD, 2);
  ASSERT_TRUE(ours.factorize(K));
  SparseMatrix indefinite = K;
  indefinite.coeffRef(40, 40) = -1e3;
  EXPECT_FALSE(ours.factorize(indefinite));
  EXPECT_THROW(ours.solve(right_hand_side(K.rows())), std::logic_error);
  SparseMatrix not_finite = K;
  not_finite.coeffRef(100, 100) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(ours.factorize(not_finite));
}

TEST(SupernodalCholesky, RefusesAnotherPattern) {
  const SparseMatrix K = sheet(6, 0.5, 4u), other = sheet(7, 0.5, 4u);
  SupernodalCholesky ours;
  ours.analyze(K, CHOLMOD_AMD);
  EXPECT_THROW(ours.factorize(other), std::invalid_argument);
}

TEST(SupernodalCholesky, EmptyMatrix) {
  SparseMatrix K(0, 0);
  SupernodalCholesky ours;
  ours.analyze(K, CHOLMOD_AMD);
  EXPECT_TRUE(ours.factorize(K));
  EXPECT_EQ(ours.solve(Eigen::VectorXd()).size(), 0);
}

// The LDL^T without pivoting on an indefinite sheet (the positive semi-definite elements
// shifted down, so that some eigenvalues are negative): D has as many negative entries as
// the matrix has negative eigenvalues (Eigen's dense eigensolver, an independent method), and
// the solution solves the system to 1e-10 relative (the shifted spectrum passes near zero:
// the condition number is far above the positive definite sheets'), on one and three
// threads, with both orderings. On a positive definite matrix D is positive and the solution
// is the Cholesky's to rounding.
TEST(SupernodalCholesky, LdltGivesTheInertiaAndSolvesIndefiniteSystems) {
  for (int m : {5, 12}) {
    // The shift: midway between the 5 %-th and the next eigenvalue of the unshifted sheet,
    // so that 5 % of the eigenvalues are negative and none is near zero.
    const Eigen::VectorXd spectrum = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
        Eigen::MatrixXd(sheet(m, 0.0, 5u + m)), Eigen::EigenvaluesOnly).eigenvalues();
    const Eigen::Index k = spectrum.size() / 20;
    const SparseMatrix K = sheet(m, -0.5 * (spectrum[k - 1] + spectrum[k]), 5u + m);
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(
        Eigen::MatrixXd(K), Eigen::EigenvaluesOnly).eigenvalues();
    const long negative = (eigenvalues.array() < 0.0).count();
    ASSERT_EQ(negative, k);
    ASSERT_GT(eigenvalues.cwiseAbs().minCoeff(), 1e-9);  // not singular: the inertia is sharp
    const Eigen::VectorXd b = right_hand_side(K.rows());
    for (int ordering : {CHOLMOD_AMD, CHOLMOD_NESDIS}) {
      for (int threads : {1, 3}) {
        SupernodalCholesky ours;
        ours.analyze(K, ordering, threads);
        EXPECT_FALSE(ours.factorize(K));
        ASSERT_TRUE(ours.factorize_ldlt(K)) << "m " << m;
        const Eigen::VectorXd d = ours.ldlt_diagonal();
        EXPECT_EQ((d.array() < 0.0).count(), negative) << "m " << m << " threads " << threads;
        const Eigen::VectorXd x = ours.solve(b);
        EXPECT_LE((K * x - b).norm(), 1e-10 * b.norm()) << "m " << m;
      }
    }
  }
  const SparseMatrix K = sheet(30, 0.5, 9u);
  const Eigen::VectorXd b = right_hand_side(K.rows());
  SupernodalCholesky ours;
  ours.analyze(K, CHOLMOD_NESDIS, 2);
  ASSERT_TRUE(ours.factorize_ldlt(K));
  EXPECT_EQ((ours.ldlt_diagonal().array() <= 0.0).count(), 0);
  const Eigen::VectorXd expected = cholmod_solution(K, b);
  EXPECT_LE((ours.solve(b) - expected).norm(), 1e-12 * expected.norm());
}

// Each compiled set of dense kernels (the baseline, and AVX2+FMA where the processor has
// them) factorises alike: the solutions equal CHOLMOD's simplicial one to 1e-12 relative
// (as above: the kernels differ only in rounding), and the LDL^T's inertia is the same. The
// default is AVX2 exactly where it is supported; asking for it elsewhere is refused.
TEST(SupernodalCholesky, EveryKernelSetFactorisesAlike) {
  using kresling::solvers::InstructionSet;
  const bool avx2 = kresling::solvers::avx2_kernels_supported();
  SupernodalCholesky ours;
  EXPECT_EQ(ours.instruction_set(), avx2 ? InstructionSet::AVX2 : InstructionSet::Baseline);
  if (!avx2) EXPECT_THROW(ours.use_instruction_set(InstructionSet::AVX2), std::invalid_argument);
  std::vector<InstructionSet> sets{InstructionSet::Baseline};
  if (avx2) sets.push_back(InstructionSet::AVX2);
  // Wide enough that the dense kernels block (supernodes of a hundred columns and more).
  const SparseMatrix K = sheet(40, 0.5, 13u);
  const Eigen::VectorXd b = right_hand_side(K.rows());
  const Eigen::VectorXd expected = cholmod_solution(K, b);
  // The same sheet shifted down by 4, past its smallest eigenvalues (indefinite): its
  // LDL^T's negative pivots, per set.
  const SparseMatrix shifted = sheet(40, -4.0, 13u);
  std::vector<long> negative;
  for (InstructionSet set : sets) {
    for (int threads : {1, 2}) {
      ours.use_instruction_set(set);
      ours.analyze(K, CHOLMOD_NESDIS, threads);
      EXPECT_EQ(ours.instruction_set(), set);  // kept across the analysis
      ASSERT_TRUE(ours.factorize(K));
      EXPECT_LE((ours.solve(b) - expected).norm(), 1e-12 * expected.norm());
      ASSERT_TRUE(ours.factorize_ldlt(shifted));
      negative.push_back((ours.ldlt_diagonal().array() < 0.0).count());
      EXPECT_LE((shifted * ours.solve(b) - b).norm(), 1e-8 * b.norm());
    }
  }
  EXPECT_GT(negative.front(), 0);
  for (long count : negative) EXPECT_EQ(count, negative.front());
}

// A sheet large enough that its top separator (~390 columns) is shared by the threads:
// the factors on two threads solve as the one-thread factor does, to rounding (1e-12
// relative: the shared panels sum their updates in another order), and the LDL^T of the
// sheet shifted to be indefinite has the same inertia on either.
TEST(SupernodalCholesky, SharedTopSupernodesChangeOnlyTheRounding) {
  const SparseMatrix K = sheet(128, 0.5, 17u), shifted = sheet(128, -4.0, 17u);
  const Eigen::VectorXd b = right_hand_side(K.rows());
  SupernodalCholesky one, two;
  one.analyze(K, CHOLMOD_NESDIS, 1);
  two.analyze(K, CHOLMOD_NESDIS, 2);
  EXPECT_EQ(one.shared_supernodes(), 0);
  EXPECT_GE(two.shared_supernodes(), 1);
  ASSERT_TRUE(one.factorize(K));
  ASSERT_TRUE(two.factorize(K));
  const Eigen::VectorXd x1 = one.solve(b), x2 = two.solve(b);
  EXPECT_LE((x1 - x2).norm(), 1e-12 * x1.norm());
  EXPECT_LE((K * x2 - b).norm(), 1e-12 * b.norm());
  ASSERT_TRUE(one.factorize_ldlt(shifted));
  ASSERT_TRUE(two.factorize_ldlt(shifted));
  const long negative = (one.ldlt_diagonal().array() < 0.0).count();
  EXPECT_GT(negative, 0);
  EXPECT_EQ((two.ldlt_diagonal().array() < 0.0).count(), negative);
  const Eigen::VectorXd y1 = one.solve(b), y2 = two.solve(b);
  EXPECT_LE((shifted * y2 - b).norm(), 1e-8 * b.norm());
  EXPECT_LE((y1 - y2).norm(), 1e-8 * y1.norm());
  // Not positive definite: the shared supernode's panels refuse as the one-thread path does.
  EXPECT_FALSE(two.factorize(shifted));
}

// The tangent solver keeps small factorisations (below 1e7 flops: the bending specimens,
// MERLIN2's examples) on the baseline kernels, so their results stay bit for bit: its
// solution on a small sheet equals the baseline kernels' exactly.
TEST(SupernodalCholesky, SmallTangentsKeepTheBaselineKernels) {
  using kresling::solvers::InstructionSet;
  const SparseMatrix K = sheet(8, 0.5, 19u);  // 192 DOFs: supernodal, AMD, one thread
  const Eigen::VectorXd b = right_hand_side(K.rows());
  kresling::solvers::TangentSolver solver;
  ASSERT_TRUE(solver.factorize(K).ok);
  ASSERT_EQ(solver.plan().cholesky, kresling::solvers::CholeskyChoice::Supernodal);
  ASSERT_LT(solver.plan().flops, 1e7);
  SupernodalCholesky baseline;
  baseline.use_instruction_set(InstructionSet::Baseline);
  baseline.analyze(K, CHOLMOD_AMD, 1);
  ASSERT_TRUE(baseline.factorize(K));
  const Eigen::VectorXd x = solver.solve(b), y = baseline.solve(b);
  for (Eigen::Index i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], y[i]) << "entry " << i;
}
