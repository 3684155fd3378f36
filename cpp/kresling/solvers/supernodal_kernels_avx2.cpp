// The supernodal factorisation's dense kernels compiled with -mavx2 -mfma (the build adds
// the flags to this file alone). Eigen's templates are instantiated here with 256-bit
// vectors; renaming Eigen's namespace for this unit keeps those instances apart from the
// baseline ones of the same name, which the linker would otherwise merge (leaving either
// AVX2 code where a processor lacks it, or the baseline code everywhere).
#define Eigen kresling_eigen_avx2
#define KRESLING_KERNEL_NAMESPACE avx2_kernels
#include "kresling/solvers/supernodal_kernels.inc"
