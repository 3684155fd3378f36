#pragma once
/// \file supernodal_kernels.hpp
/// The dense kernels of the supernodal factorisation (supernodal_cholesky.hpp), compiled once
/// for any x86-64 processor (SSE2) and once more for processors with AVX2 and FMA, chosen at
/// run time from what the processor supports.
///
/// Nearly all the flops of a large sheet's factorisation are in these two kernels (Eigen's
/// blocked products, triangular solves and Cholesky): AVX2 doubles the width of their
/// vectors and FMA fuses each multiply-add, so on a processor that has both they run about
/// twice as fast. The rest of the library stays compiled for the baseline instruction set,
/// so the module still loads and runs on processors without AVX2. Results differ between
/// the two only by rounding (the fused multiply-add rounds once where the baseline rounds
/// twice, and the products sum in another order).

namespace kresling::solvers {

/// Which compiled set of dense kernels to use.
enum class InstructionSet : int {
  Auto = 0,      ///< the fastest the processor supports
  Baseline = 1,  ///< SSE2: every x86-64 processor (or the compiler's default elsewhere)
  AVX2 = 2       ///< AVX2 and FMA
};

/// The dense kernels of one supernode, on column-major blocks.
struct SupernodalKernels {
  /// The update a descendant supernode sends: its block L (drow x dcol, leading dimension
  /// ld >= drow), of which rows [p1, p2) fall in the target's columns and rows [p1, drow) from
  /// there down. C (n2 x n1, n2 = drow - p1, n1 = p2 - p1, leading dimension n2) receives
  /// L[p1:, :] L[p1:p2, :]^T, or with L's diagonal D between for an LDL^T factor (whose
  /// scratch `scaled` then holds n1 x dcol entries); of C's top n1 x n1 block only the
  /// lower triangle is written.
  void (*update)(const double* L, int ld, int drow, int dcol, int p1, int p2, bool ldlt, double* C,
                 double* scaled);
  /// Factorise a supernode's block S (nrow x ncol, leading dimension ld >= nrow) in place: its
  /// diagonal block by Cholesky (or LDL^T without pivoting: unit L, D on the diagonal), then
  /// the rows below by a triangular solve. False if a pivot is not positive (Cholesky) or
  /// is zero, or any is not finite.
  bool (*factor)(double* S, int ld, int nrow, int ncol, bool ldlt);
  InstructionSet instruction_set;
};

/// Whether the AVX2 kernels were compiled in and the processor supports AVX2 and FMA.
bool avx2_kernels_supported();

/// The kernels for `wanted` (Auto: AVX2 where supported, else the baseline). Throws
/// std::invalid_argument for AVX2 where avx2_kernels_supported() is false.
const SupernodalKernels& supernodal_kernels(InstructionSet wanted = InstructionSet::Auto);

}  // namespace kresling::solvers
