// The supernodal factorisation's dense kernels for the compiler's default instruction set
// (SSE2 on x86-64): the fallback every processor runs.
#define KRESLING_KERNEL_NAMESPACE baseline_kernels
#include "kresling/solvers/supernodal_kernels.inc"
