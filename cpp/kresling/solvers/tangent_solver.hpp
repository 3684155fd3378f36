#pragma once
/// \file tangent_solver.hpp
/// Factorise a symmetric tangent and solve with it, reporting its inertia.
///
/// The Cholesky factorisation (positive definite: a stable equilibrium, no negative
/// eigenvalues) is chosen once per sparsity pattern, on the first call, by a cost model
/// calibrated by measurement (choose_cholesky): a dense Cholesky (Eigen) for the smallest
/// tangents, else a supernodal one whose dense kernels are Eigen's, on CHOLMOD's symbolic
/// analysis (supernodal_cholesky.hpp; threaded across independent subtrees for large
/// sheets; its AVX2+FMA kernels from 1e7 flops per factorisation up, where the processor
/// has them). CHOLMOD's own simplicial factorisation can be forced. The fill-reducing
/// ordering is CHOLMOD's: AMD for small tangents (its analysis is cheapest), and from
/// kTryNestedDissection DOFs up whichever of AMD and nested dissection (METIS) gives the
/// fewer flops: nested dissection for sheets, AMD for towers. When the Cholesky fails the
/// tangent is indefinite: a sparse LDL^T without pivoting (Eigen's simplicial factorisation
/// with AMD ordering; from kTryNestedDissection DOFs up the supernodal one on the Cholesky's
/// symbolic factor, or CHOLMOD's where its simplicial Cholesky was forced) gives the count of
/// negative eigenvalues by Sylvester's law of inertia; if its pivots are unusable (an exactly singular or badly
/// conditioned leading block) UMFPACK's LU solves instead and the inertia is reported
/// unknown (-1). Symbolic analyses are done once per pattern.

#include <cstdint>
#include <memory>

#include <Eigen/SparseCore>

#include "kresling/core/types.hpp"

namespace kresling::solvers {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class Factorization : int {
  None = 0,
  Cholesky = 1,           ///< CHOLMOD simplicial LL^T
  LDLT = 2,
  LU = 3,
  DenseCholesky = 4,
  SupernodalCholesky = 5  ///< supernodal LL^T, Eigen kernels (SupernodalCholesky)
};

/// Which Cholesky to use for positive definite tangents: chosen by cost (Auto), or forced
/// (tests and benchmarks compare the paths).
enum class CholeskyChoice : int { Auto = 0, Dense = 1, Simplicial = 2, Supernodal = 3 };

/// The fill-reducing ordering CHOLMOD chose.
enum class Ordering : int { None = 0, AMD = 1, NestedDissection = 2, Other = 3 };

/// From this many DOFs up, nested dissection is tried beside AMD (its analysis costs
/// ~1 ms at 1,000 DOFs, ~0.1 s at 50,000; it saves 10-40 % of the flops on sheets).
inline constexpr Index kTryNestedDissection = 1000;

struct FactorizeInfo {
  bool ok = false;                 ///< a usable factorisation exists
  Factorization method = Factorization::None;
  int negative_eigenvalues = -1;   ///< inertia, or -1 when unknown (LU)
};

/// What the first call decided for the pattern (and what the sparse analysis predicted).
struct FactorizationPlan {
  CholeskyChoice cholesky = CholeskyChoice::Auto;  ///< Dense, Simplicial or Supernodal
  Ordering ordering = Ordering::None;              ///< of the sparse Cholesky (None if dense)
  double factor_nonzeros = 0.0;  ///< entries of the Cholesky factor L (n (n+1)/2 if dense)
  double flops = 0.0;            ///< flops of one factorisation, as CHOLMOD counts them
  double analysis_seconds = 0.0; ///< symbolic analysis and choice, once per pattern
};

/// The cost model behind CholeskyChoice::Auto, for a tangent of n DOFs: measured, it needs
/// only the size (tangent_solver.cpp has the table). Exposed so that the rule can be tested.
CholeskyChoice choose_cholesky(Index n);

/// Threads the supernodal factorisation splits its elimination tree over, for a
/// factorisation of `flops` (one below 1e8 flops, where starting threads costs more than
/// it saves; else the processor's threads, at most 4).
int factorisation_threads(double flops);

class TangentSolver {
 public:
  explicit TangentSolver(CholeskyChoice choice = CholeskyChoice::Auto);
  ~TangentSolver();
  TangentSolver(const TangentSolver&) = delete;
  TangentSolver& operator=(const TangentSolver&) = delete;

  /// Factorise the symmetric K, of which only the lower triangle is read (store it whole or
  /// just that triangle). The pattern is analysed on the first call and must stay the same.
  /// `cholesky_only`: when K is not positive definite, return ok = false at once instead of
  /// going on to LDL^T or LU (a caller that would rather change K than factorise it).
  FactorizeInfo factorize(const SparseMatrix& K, bool cholesky_only = false);

  /// Tell the solver which pattern the next factorize calls see (Workspace::pattern_id): when
  /// it differs from the one the symbolic analysis was made for, the next call analyses the
  /// new pattern (contact pairs came or went). The first call only records the id.
  void set_pattern(std::uint64_t pattern);

  /// Solve K x = b with the last successful factorisation.
  VectorX solve(const VectorX& b) const;
  /// Solve for several right-hand sides (columns of B) with one factorisation.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

  /// The plan made on the first call (default-constructed before it).
  const FactorizationPlan& plan() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::uint64_t pattern_ = 0;  // 0: none recorded yet
};

}  // namespace kresling::solvers
