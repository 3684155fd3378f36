#include "kresling/solvers/tangent_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

#include "kresling/solvers/supernodal_cholesky.hpp"

namespace kresling::solvers {

namespace {

// The cost model, measured with benchmarks/cpp/factorisation_cost.cpp on this project's
// 2-core machine (Release build), on Kresling towers (18-2,001 free DOFs), MERLIN2's GMiura
// sheet (427) and Miura-ori sheets (12,285 and 100,233). One factorisation, microseconds:
//
//   DOFs      dense   CHOLMOD simplicial   CHOLMOD supernodal   supernodal (Eigen kernels)
//   18            1                    2                    4                            1
//   54            7                   14                   60                            5
//   153          82                  130                  286                           45
//   427       1,350                  280                  539                          106
//   2,001         -                3,444                9,754                        1,137
//   12,285        -               78,537               96,948                       20,716
//   100,233       -            2,619,532            1,832,645          455,809 (2 threads: 303,369)
//
// CHOLMOD's numeric factorisations lean on the system BLAS, which Debian links to the
// reference one; the supernodal factorisation with Eigen's kernels (supernodal_cholesky.hpp)
// wins from a few dozen DOFs up, and ties the dense one below.
constexpr Index kDenseBelow = 32;
// From this many flops per factorisation up, independent subtrees factorise on separate
// threads (12,285-DOF sheet, 2.9e8 flops: 20.7 -> 15.5 ms on 2 cores; at 1e7 the threads'
// start-up cancels the gain).
constexpr double kThreadedFlops = 1e8;
// From this many flops per factorisation up, the supernodal factorisation's dense kernels are
// the AVX2+FMA ones where the processor has them (supernodal_kernels.hpp; 0.47-0.76x the
// baseline's time measured). Below, the baseline kernels keep the results of small models
// (the bending specimens, MERLIN2's examples) bit for bit as they were: rounding alone moves
// an optimiser's path on the bending test (SLSQP's evaluations on the n = 10 K_B-ratio
// optimum went from 5 to 52 with the AVX2 kernels, to the same optimum).
constexpr double kAVX2Flops = 1e7;

Ordering ordering_of(int cholmod_ordering) {
  switch (cholmod_ordering) {
    case CHOLMOD_AMD:
      return Ordering::AMD;
    case CHOLMOD_METIS:
    case CHOLMOD_NESDIS:
      return Ordering::NestedDissection;
    default:
      return Ordering::Other;
  }
}

// The orderings to try: AMD alone for small tangents, AMD and CHOLMOD's nested dissection
// (METIS bisection) from kTryNestedDissection DOFs up; CHOLMOD keeps the better one.
std::vector<int> orderings_for(Index n) {
  if (n >= kTryNestedDissection) return {CHOLMOD_AMD, CHOLMOD_NESDIS};
  return {CHOLMOD_AMD};
}

// LDL^T by CHOLMOD (simplicial, no pivoting: D's signs are the inertia by Sylvester's law),
// with the ordering the Cholesky chose: for large indefinite tangents (sheets past a limit
// point), where Eigen's LDL^T with AMD would need up to twice the flops.
class CholmodLdlt {
 public:
  CholmodLdlt() {
    cholmod_start(&common_);
    common_.print = 0;
    common_.supernodal = CHOLMOD_SIMPLICIAL;
    common_.final_ll = 0;  // keep L D L^T
    common_.final_asis = 1;
  }
  ~CholmodLdlt() {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  CholmodLdlt(const CholmodLdlt&) = delete;
  CholmodLdlt& operator=(const CholmodLdlt&) = delete;

  /// Factorise (analysing on the first call); false if a pivot is zero or not finite.
  bool factorize(const SparseMatrix& K, int ordering) {
    cholmod_sparse A = Eigen::viewAsCholmod(K.selfadjointView<Eigen::Lower>());
    if (!factor_) {
      common_.nmethods = 1;
      common_.method[0].ordering = ordering;
      common_.postorder = 1;
      factor_ = cholmod_analyze(&A, &common_);
      if (!factor_) return false;
    }
    cholmod_factorize(&A, factor_, &common_);
    return common_.status == CHOLMOD_OK && factor_->minor == factor_->n;
  }

  /// The diagonal D (simplicial LDL^T: the first entry of each column of L).
  VectorX diagonal() const {
    const auto* p = static_cast<const int*>(factor_->p);
    const auto* x = static_cast<const double*>(factor_->x);
    VectorX d(static_cast<Index>(factor_->n));
    for (Index j = 0; j < d.size(); ++j) d[j] = x[p[j]];
    return d;
  }

  VectorX solve(const VectorX& b) const {
    VectorX rhs = b;
    cholmod_dense B = Eigen::viewAsCholmod(rhs);
    cholmod_dense* X = cholmod_solve(CHOLMOD_A, factor_, &B, &common_);
    VectorX x = Eigen::Map<const VectorX>(static_cast<const double*>(X->x), b.size());
    cholmod_free_dense(&X, &common_);
    return x;
  }

 private:
  mutable cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
};

}  // namespace

int factorisation_threads(double flops) {
  if (flops < kThreadedFlops) return 1;
  const unsigned hardware = std::thread::hardware_concurrency();
  return static_cast<int>(std::clamp(hardware, 1u, 4u));
}

CholeskyChoice choose_cholesky(Index n) {
  return n < kDenseBelow ? CholeskyChoice::Dense : CholeskyChoice::Supernodal;
}

struct TangentSolver::Impl {
  CholeskyChoice requested = CholeskyChoice::Auto;
  FactorizationPlan plan;
  bool planned = false;
  // The dense Cholesky factorises in place, as Eigen::LLT does internally (the same blocked
  // algorithm on the same matrix: the same factor, bit for bit), without LLT's copy of the
  // matrix and its L1 norm (for rcond, not used here): ~10 % of a 136-DOF factorisation.
  // The strict upper triangle stays zero (the lower-triangle algorithm never touches it).
  Eigen::MatrixXd dense_matrix;
  // CHOLMOD's simplicial factorisation, when forced (comparisons, tests).
  Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> cholesky;
  SupernodalCholesky supernodal;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  // From kTryNestedDissection DOFs up the LDL^T is CHOLMOD's, with the Cholesky's ordering.
  std::unique_ptr<CholmodLdlt> large_ldlt;
  int cholmod_ordering = CHOLMOD_AMD;
  Eigen::UmfPackLU<SparseMatrix> lu;
  bool ldlt_analysed = false, lu_analysed = false;
  bool supernodal_ldlt = false;  // the LDL^T is the supernodal one
  Factorization current = Factorization::None;
  SparseMatrix whole;  // the full matrix UMFPACK factorises

  void make_plan(const SparseMatrix& K);
  Factorization cholesky_of(const SparseMatrix& K);
  VectorX ldlt_pivots(const SparseMatrix& K);
  bool lu_of(const SparseMatrix& K);
};

void TangentSolver::Impl::make_plan(const SparseMatrix& K) {
  const auto start = std::chrono::steady_clock::now();
  const Index n = K.rows();
  // The choice needs only the size; the symbolic analysis is then done once, by the
  // factorisation chosen, and gives the plan its ordering, factor entries and flops.
  plan.cholesky = requested == CholeskyChoice::Auto ? choose_cholesky(n) : requested;
  auto record = [&](int ordering, double factor_nonzeros, double flops) {
    cholmod_ordering = ordering;
    plan.ordering = ordering_of(ordering);
    plan.factor_nonzeros = factor_nonzeros;
    plan.flops = flops;
  };
  if (plan.cholesky == CholeskyChoice::Simplicial) {
    cholmod_common& c = cholesky.cholmod();
    const std::vector<int> orderings = orderings_for(n);
    c.nmethods = static_cast<int>(orderings.size());
    for (std::size_t k = 0; k < orderings.size(); ++k) c.method[k].ordering = orderings[k];
    c.postorder = 1;
    cholesky.analyzePattern(K);
    record(c.method[c.selected].ordering, c.lnz, c.fl);
  } else if (plan.cholesky == CholeskyChoice::Supernodal) {
    const SupernodalCholesky::Analysis a = supernodal.analyze(K, orderings_for(n));
    supernodal.use_threads(factorisation_threads(a.flops));
    supernodal.use_instruction_set(a.flops >= kAVX2Flops ? InstructionSet::Auto
                                                         : InstructionSet::Baseline);
    record(a.ordering, a.factor_nonzeros, a.flops);
  } else {
    const double m = static_cast<double>(n);
    plan.ordering = Ordering::None;
    plan.factor_nonzeros = m * (m + 1) / 2;
    plan.flops = m * m * m / 3.0;
  }
  plan.analysis_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  planned = true;
}

TangentSolver::TangentSolver(CholeskyChoice choice) : impl_(std::make_unique<Impl>()) {
  impl_->requested = choice;
  // An indefinite tangent is an expected outcome here, not something to print about.
  impl_->cholesky.cholmod().print = 0;
}
TangentSolver::~TangentSolver() = default;

const FactorizationPlan& TangentSolver::plan() const { return impl_->plan; }

void TangentSolver::set_pattern(std::uint64_t pattern) {
  if (pattern_ != 0 && pattern != pattern_) {
    // Everything analysed belongs to the old pattern: start afresh, with the same choice.
    const CholeskyChoice requested = impl_->requested;
    impl_ = std::make_unique<Impl>();
    impl_->requested = requested;
    impl_->cholesky.cholmod().print = 0;
  }
  pattern_ = pattern;
}

// The plan's Cholesky factorisation of K: which one succeeded (None: K is not positive
// definite).
Factorization TangentSolver::Impl::cholesky_of(const SparseMatrix& K) {
  switch (plan.cholesky) {
    case CholeskyChoice::Dense:
      if (dense_matrix.rows() != K.rows()) dense_matrix.setZero(K.rows(), K.cols());
      for (Index col = 0; col < K.cols(); ++col) {
        // The previous factor filled in the lower triangle: clear it, then copy K's.
        dense_matrix.col(col).tail(K.rows() - col).setZero();
        for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
          if (it.row() >= it.col()) dense_matrix(it.row(), it.col()) = it.value();
        }
      }
      // -1: positive definite (else the index of the first non-positive pivot).
      if (Eigen::internal::llt_inplace<double, Eigen::Lower>::blocked(dense_matrix) == -1) {
        return Factorization::DenseCholesky;
      }
      return Factorization::None;
    case CholeskyChoice::Supernodal:
      return supernodal.factorize(K) ? Factorization::SupernodalCholesky : Factorization::None;
    default:
      cholesky.factorize(K);
      return cholesky.info() == Eigen::Success ? Factorization::Cholesky : Factorization::None;
  }
}

// The pivots of K's LDL^T (empty when it fails).
VectorX TangentSolver::Impl::ldlt_pivots(const SparseMatrix& K) {
  VectorX d;
  supernodal_ldlt = false;
  if (K.rows() >= kTryNestedDissection && plan.cholesky == CholeskyChoice::Supernodal) {
    // On the Cholesky's symbolic factor: no second analysis, and the dense kernels of the
    // supernodal factorisation (a 25,737-DOF Miura sheet: 0.25 s against CHOLMOD's
    // simplicial LDL^T's 1.6 s).
    if (supernodal.factorize_ldlt(K)) d = supernodal.ldlt_diagonal();
    supernodal_ldlt = true;
  } else if (K.rows() >= kTryNestedDissection) {
    if (!large_ldlt) large_ldlt = std::make_unique<CholmodLdlt>();
    if (large_ldlt->factorize(K, cholmod_ordering)) d = large_ldlt->diagonal();
  } else {
    if (!ldlt_analysed) {
      ldlt.analyzePattern(K);
      ldlt_analysed = true;
    }
    ldlt.factorize(K);
    if (ldlt.info() == Eigen::Success) d = ldlt.vectorD();
  }
  return d;
}

// LU needs the whole matrix: mirror the lower triangle (rare path).
bool TangentSolver::Impl::lu_of(const SparseMatrix& K) {
  whole = K.selfadjointView<Eigen::Lower>();
  if (!lu_analysed) {
    lu.analyzePattern(whole);
    lu_analysed = true;
  }
  lu.factorize(whole);
  return lu.info() == Eigen::Success;
}

FactorizeInfo TangentSolver::factorize(const SparseMatrix& K, bool cholesky_only) {
  Impl& s = *impl_;
  FactorizeInfo info;
  s.current = Factorization::None;
  if (K.rows() == 0) {  // nothing free: trivially "positive definite"
    s.current = Factorization::Cholesky;
    return {true, Factorization::Cholesky, 0};
  }
  if (!s.planned) s.make_plan(K);
  const Factorization cholesky = s.cholesky_of(K);
  if (cholesky != Factorization::None) {
    s.current = cholesky;
    return {true, cholesky, 0};
  }
  if (cholesky_only) return info;
  // Indefinite (or singular): LDL^T for the inertia, if its pivots are usable (none zero
  // or tiny against the largest: an exactly singular or badly conditioned leading block).
  const VectorX d = s.ldlt_pivots(K);
  if (d.size() > 0 && d.allFinite() &&
      d.cwiseAbs().minCoeff() > 1e-13 * d.cwiseAbs().maxCoeff()) {
    s.current = Factorization::LDLT;
    return {true, Factorization::LDLT, static_cast<int>((d.array() < 0.0).count())};
  }
  if (s.lu_of(K)) {
    s.current = Factorization::LU;
    return {true, Factorization::LU, -1};
  }
  return info;  // singular: ok = false
}

VectorX TangentSolver::solve(const VectorX& b) const {
  switch (impl_->current) {
    case Factorization::Cholesky:
      return b.size() ? VectorX(impl_->cholesky.solve(b)) : VectorX(b);
    case Factorization::SupernodalCholesky:
      return impl_->supernodal.solve(b);
    case Factorization::DenseCholesky: {
      // As Eigen::LLT::solve: L y = b, then L^T x = y, in place.
      VectorX x = b;
      impl_->dense_matrix.triangularView<Eigen::Lower>().solveInPlace(x);
      impl_->dense_matrix.adjoint().triangularView<Eigen::Upper>().solveInPlace(x);
      return x;
    }
    case Factorization::LDLT:
      if (impl_->supernodal_ldlt) return impl_->supernodal.solve(b);
      return impl_->large_ldlt ? impl_->large_ldlt->solve(b) : VectorX(impl_->ldlt.solve(b));
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
