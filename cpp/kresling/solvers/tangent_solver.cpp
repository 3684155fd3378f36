#include "kresling/solvers/tangent_solver.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

namespace kresling::solvers {

namespace {

// Below this size, and with a lower triangle at least this dense, a dense Cholesky is
// faster than CHOLMOD's sparse one: the Kresling specimens' tangents (136 DOFs for n = 10,
// factor ~57 % dense) factorise in ~112 us dense against ~142 us sparse (benchmarks/).
constexpr Index kDenseLimit = 400;
constexpr double kDenseFill = 0.10;

bool prefer_dense(const SparseMatrix& K) {
  const double n = static_cast<double>(K.rows());
  return K.rows() <= kDenseLimit && K.nonZeros() >= kDenseFill * n * (n + 1) / 2;
}

}  // namespace

struct TangentSolver::Impl {
  Eigen::MatrixXd dense_matrix;
  Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> dense;
  // Simplicial: at the sizes of these models (10^2-10^4 DOFs, sparse) it beats the
  // supernodal factorisation, which leans on BLAS (Debian links the reference BLAS) and
  // OpenMP threads whose start-up cost dominates small factorisations.
  Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> cholesky;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::UmfPackLU<SparseMatrix> lu;
  bool cholesky_analysed = false, ldlt_analysed = false, lu_analysed = false;
  Factorization current = Factorization::None;
  SparseMatrix whole;  // the full matrix UMFPACK factorises
};

TangentSolver::TangentSolver() : impl_(std::make_unique<Impl>()) {
  // An indefinite tangent is an expected outcome here, not something to print about.
  impl_->cholesky.cholmod().print = 0;
}
TangentSolver::~TangentSolver() = default;

FactorizeInfo TangentSolver::factorize(const SparseMatrix& K) {
  Impl& s = *impl_;
  FactorizeInfo info;
  s.current = Factorization::None;
  if (K.rows() == 0) {  // nothing free: trivially "positive definite"
    s.current = Factorization::Cholesky;
    return {true, Factorization::Cholesky, 0};
  }
  if (prefer_dense(K)) {
    s.dense_matrix.setZero(K.rows(), K.cols());
    for (int col = 0; col < K.outerSize(); ++col) {
      for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
        if (it.row() >= it.col()) s.dense_matrix(it.row(), it.col()) = it.value();
      }
    }
    s.dense.compute(s.dense_matrix);
    if (s.dense.info() == Eigen::Success) {
      s.current = Factorization::DenseCholesky;
      return {true, Factorization::DenseCholesky, 0};
    }
  } else {
    if (!s.cholesky_analysed) {
      s.cholesky.analyzePattern(K);
      s.cholesky_analysed = true;
    }
    s.cholesky.factorize(K);
    if (s.cholesky.info() == Eigen::Success) {
      s.current = Factorization::Cholesky;
      return {true, Factorization::Cholesky, 0};
    }
  }
  // Indefinite (or singular): LDL^T for the inertia.
  if (!s.ldlt_analysed) {
    s.ldlt.analyzePattern(K);
    s.ldlt_analysed = true;
  }
  s.ldlt.factorize(K);
  if (s.ldlt.info() == Eigen::Success) {
    const VectorX d = s.ldlt.vectorD();
    const double largest = d.cwiseAbs().maxCoeff();
    const bool usable = d.allFinite() && d.cwiseAbs().minCoeff() > 1e-13 * largest;
    if (usable) {
      s.current = Factorization::LDLT;
      info = {true, Factorization::LDLT, static_cast<int>((d.array() < 0.0).count())};
      return info;
    }
  }
  // LU needs the whole matrix: mirror the lower triangle (rare path).
  s.whole = K.selfadjointView<Eigen::Lower>();
  if (!s.lu_analysed) {
    s.lu.analyzePattern(s.whole);
    s.lu_analysed = true;
  }
  s.lu.factorize(s.whole);
  if (s.lu.info() == Eigen::Success) {
    s.current = Factorization::LU;
    return {true, Factorization::LU, -1};
  }
  return info;  // singular: ok = false
}

VectorX TangentSolver::solve(const VectorX& b) const {
  switch (impl_->current) {
    case Factorization::Cholesky:
      return b.size() ? VectorX(impl_->cholesky.solve(b)) : VectorX(b);
    case Factorization::DenseCholesky:
      return impl_->dense.solve(b);
    case Factorization::LDLT:
      return impl_->ldlt.solve(b);
    case Factorization::LU:
      return impl_->lu.solve(b);
    default:
      throw std::logic_error("TangentSolver::solve called without a factorisation");
  }
}

Eigen::MatrixXd TangentSolver::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (Index j = 0; j < B.cols(); ++j) X.col(j) = solve(VectorX(B.col(j)));
  return X;
}

}  // namespace kresling::solvers
