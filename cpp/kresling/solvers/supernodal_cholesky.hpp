#pragma once
/// \file supernodal_cholesky.hpp
/// A supernodal sparse Cholesky factorisation whose dense kernels are Eigen's.
///
/// CHOLMOD's supernodal factorisation calls the system BLAS for its dense blocks; where that
/// is the reference BLAS (Debian's default) the blocks of large sheets run at a few GFlop/s.
/// Here CHOLMOD still does the symbolic work (fill-reducing ordering, supernode partition
/// with its relaxed amalgamation, the factor's pattern), once per sparsity pattern, and the
/// numeric factorisation is a left-looking supernodal one (George and Liu's, as in CHOLMOD):
/// each supernode gathers the updates of the supernodes below it in the elimination tree
/// (one dense product each), then factorises its diagonal block and solves for the rows
/// under it, all with Eigen's blocked, vectorised dense kernels (supernodal_kernels.hpp:
/// compiled for AVX2 and FMA beside the baseline, chosen by the processor). The symbolic analysis also
/// splits the elimination tree into independent subtrees, which factorise on separate
/// threads (nested dissection makes two halves of nearly equal work below the top
/// separator); the few large supernodes above them (the top separators, a fifth of a large
/// sheet's time on one thread) share their work among the threads by columns.
///
/// The same symbolic factor also serves an LDL^T factorisation without pivoting (L unit
/// lower triangular, D diagonal) of a symmetric indefinite matrix with the same pattern: the
/// updates carry D, each diagonal block is factorised by a blocked dense LDL^T. The signs of
/// D are the matrix's inertia (Sylvester's law), as in CHOLMOD's simplicial LDL^T, which
/// computes the same factor one column at a time; the blocks here run 5-8 times faster.

#include <memory>
#include <vector>

#include <Eigen/SparseCore>

#include "kresling/core/types.hpp"
#include "kresling/solvers/supernodal_kernels.hpp"

namespace kresling::solvers {

class SupernodalCholesky {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  SupernodalCholesky();
  ~SupernodalCholesky();
  SupernodalCholesky(const SupernodalCholesky&) = delete;
  SupernodalCholesky& operator=(const SupernodalCholesky&) = delete;

  /// What the symbolic analysis found, for the ordering CHOLMOD kept.
  struct Analysis {
    int ordering = 0;              ///< CHOLMOD's ordering (CHOLMOD_AMD, CHOLMOD_NESDIS, ...)
    double factor_nonzeros = 0.0;  ///< entries of L (without the amalgamation's zeros)
    double flops = 0.0;            ///< of one numeric factorisation, as CHOLMOD counts them
  };

  /// Symbolic analysis of K's pattern (the lower triangle is read) with each of CHOLMOD's
  /// `orderings` (CHOLMOD_AMD, CHOLMOD_NESDIS, ...); CHOLMOD keeps the one needing the fewest
  /// flops. `threads` > 1 factorises independent subtrees concurrently (see use_threads).
  /// Throws std::runtime_error if CHOLMOD fails.
  Analysis analyze(const SparseMatrix& K, const std::vector<int>& orderings, int threads = 1);
  Analysis analyze(const SparseMatrix& K, int ordering, int threads = 1) {
    return analyze(K, std::vector<int>{ordering}, threads);
  }

  /// Split the analysed elimination tree over `threads` threads (1: all on the caller's);
  /// for choosing the count from the analysis's flops.
  void use_threads(int threads);

  /// Which compiled dense kernels the numeric factorisations use (Auto, the default: AVX2
  /// and FMA where the processor has them). Kept across analyses; throws
  /// std::invalid_argument for AVX2 where it is not supported (avx2_kernels_supported).
  void use_instruction_set(InstructionSet set);
  InstructionSet instruction_set() const;

  /// Numeric factorisation of K (same pattern as analysed). False if K is not positive
  /// definite (a pivot is not positive or not finite): the factor is then unusable.
  bool factorize(const SparseMatrix& K);

  /// Numeric LDL^T factorisation of K, without pivoting (same pattern as analysed). False
  /// if a pivot is zero or not finite.
  bool factorize_ldlt(const SparseMatrix& K);

  /// D of the last LDL^T factorisation (in the permuted order: for counting signs).
  VectorX ldlt_diagonal() const;

  /// x with K x = b, from the last successful factorisation (Cholesky or LDL^T).
  VectorX solve(const VectorX& b) const;

  double factor_nonzeros() const;  ///< entries of L, explicit zeros of amalgamation included
  int supernodes() const;
  /// Threads that factorise a share of the elimination tree (1: no split paid off).
  int working_threads() const;
  /// Supernodes above the threads' subtrees large enough that the threads share their work
  /// (nested dissection's top separators of large sheets).
  int shared_supernodes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace kresling::solvers
