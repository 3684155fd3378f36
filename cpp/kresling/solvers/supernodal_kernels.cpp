#include "kresling/solvers/supernodal_kernels.hpp"

#include <stdexcept>

namespace kresling::solvers {

// Each compiled set's kernels (supernodal_kernels.inc, in its own namespace).
namespace baseline_kernels {
void update(const double* L, int ld, int drow, int dcol, int p1, int p2, bool ldlt, double* C,
            double* scaled);
bool factor(double* S, int ld, int nrow, int ncol, bool ldlt);
}  // namespace baseline_kernels

#if KRESLING_AVX2_KERNELS
namespace avx2_kernels {
void update(const double* L, int ld, int drow, int dcol, int p1, int p2, bool ldlt, double* C,
            double* scaled);
bool factor(double* S, int ld, int nrow, int ncol, bool ldlt);
}  // namespace avx2_kernels
#endif

namespace {

bool processor_has_avx2_and_fma() {
#if KRESLING_AVX2_KERNELS
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

const SupernodalKernels kBaseline{&baseline_kernels::update, &baseline_kernels::factor,
                                  InstructionSet::Baseline};
#if KRESLING_AVX2_KERNELS
const SupernodalKernels kAVX2{&avx2_kernels::update, &avx2_kernels::factor,
                              InstructionSet::AVX2};
#endif

}  // namespace

bool avx2_kernels_supported() {
  static const bool supported = processor_has_avx2_and_fma();
  return supported;
}

const SupernodalKernels& supernodal_kernels(InstructionSet wanted) {
  switch (wanted) {
    case InstructionSet::Baseline:
      return kBaseline;
    case InstructionSet::AVX2:
      if (!avx2_kernels_supported()) {
        throw std::invalid_argument(
            "supernodal_kernels: instruction set AVX2 is not available (this processor lacks "
            "AVX2 or FMA, or the build did not compile the AVX2 kernels); use Auto or "
            "Baseline");
      }
      [[fallthrough]];
    default:
#if KRESLING_AVX2_KERNELS
      if (avx2_kernels_supported()) return kAVX2;
#endif
      return kBaseline;
  }
}

}  // namespace kresling::solvers
