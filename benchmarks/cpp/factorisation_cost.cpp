// Calibration of the tangent solver's cost model (kresling/solvers/tangent_solver.cpp):
// for each symmetric matrix given (Matrix Market, the lower triangle of a tangent restricted
// to its free DOFs, e.g. K = kresling.assembly.tangent_stiffness(model, u, shift=1e-8)
// written by scipy.io.mmwrite(path, scipy.sparse.tril(K[free][:, free]),
// symmetry="symmetric")), the time of one factorisation by every candidate, the factor's
// entries and flops with each ordering, one solve with ours and with CHOLMOD's simplicial
// factor, and what the cost model picks.
//
// Run: build/py/factorisation_cost DIR/*.mtx  (built with KRESLING_BUILD_BENCHMARKS=ON).
//
// With --compare first, instead: per matrix, one factorisation, side by side, by our
// supernodal factorisation with its baseline (SSE2) dense kernels and with its AVX2+FMA
// ones (both on the tangent solver's threads, LL^T and LDL^T of the same matrix shifted to
// be indefinite), and by CHOLMOD's supernodal LL^T on the BLAS this process loaded (Debian's
// reference BLAS, or another one preloaded: LD_PRELOAD=.../libopenblas.so.0), with the
// solves, the inertia of the shifted matrix by each kernel set, and the residuals. One line
// of JSON per matrix (benchmarks/pattern_scaling.py --compare prints the table).

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <unsupported/Eigen/SparseExtra>

#include "kresling/solvers/supernodal_cholesky.hpp"
#include "kresling/solvers/tangent_solver.hpp"

using kresling::solvers::SparseMatrix;

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

template <class F>
double best_of(F f, int repeat) {
  double best = 1e300;
  for (int i = 0; i < repeat; ++i) {
    const double start = now();
    f();
    best = std::min(best, now() - start);
  }
  return best;
}

const char* name(kresling::solvers::CholeskyChoice c) {
  switch (c) {
    case kresling::solvers::CholeskyChoice::Dense: return "dense";
    case kresling::solvers::CholeskyChoice::Simplicial: return "simplicial";
    case kresling::solvers::CholeskyChoice::Supernodal: return "supernodal";
    default: return "auto";
  }
}

// The Matrix Market file at path, compressed; false (and a message) if it cannot be read.
bool read_matrix(const char* path, SparseMatrix& K) {
  if (!Eigen::loadMarket(K, path)) {
    std::fprintf(stderr, "%s: cannot read\n", path);
    return false;
  }
  K.makeCompressed();
  return true;
}

extern "C" void dgemm_();  // the BLAS CHOLMOD calls, to name the library it comes from

// The file the dynamic linker took dgemm_ (the BLAS) from.
std::string blas_library() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&dgemm_), &info) && info.dli_fname) return info.dli_fname;
  return "unknown";
}

// K with its diagonal lowered by 1e-3 of the median diagonal entry, pattern kept: an
// indefinite tangent as past a limit point (benchmarks/pattern_scaling.py shifts alike).
SparseMatrix shifted(const SparseMatrix& K) {
  std::vector<double> diagonal;
  for (int c = 0; c < K.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(K, c); it; ++it)
      if (it.row() == it.col()) diagonal.push_back(it.value());
  std::nth_element(diagonal.begin(), diagonal.begin() + diagonal.size() / 2, diagonal.end());
  const double shift = diagonal.empty() ? 0.0 : 1e-3 * diagonal[diagonal.size() / 2];
  SparseMatrix S = K;
  for (int c = 0; c < S.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(S, c); it; ++it)
      if (it.row() == it.col()) it.valueRef() -= shift;
  return S;
}

double residual(const SparseMatrix& K, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (K.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm();
}

// One JSON line per matrix: see the file's comment.
int compare(int argc, char** argv) {
  using kresling::solvers::InstructionSet;
  const std::string blas = blas_library();
  for (int a = 0; a < argc; ++a) {
    SparseMatrix K;
    if (!read_matrix(argv[a], K)) return 1;
    const SparseMatrix indefinite = shifted(K);
    const int n = static_cast<int>(K.rows());
    const int repeat = n < 3000 ? 200 : (n < 30000 ? 5 : 3);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
    kresling::solvers::SupernodalCholesky ours;
    // The tangent solver's orderings: AMD, and nested dissection too from
    // kTryNestedDissection DOFs up (CHOLMOD keeps the one with fewer flops).
    std::vector<int> orderings{CHOLMOD_AMD};
    if (n >= kresling::solvers::kTryNestedDissection) orderings.push_back(CHOLMOD_NESDIS);
    const auto analysis = ours.analyze(K, orderings);
    const int threads = kresling::solvers::factorisation_threads(analysis.flops);
    ours.use_threads(threads);
    std::printf("{\"matrix\": \"%s\", \"n\": %d, \"flops\": %.6e, \"threads\": %d, "
                "\"nested_dissection\": %s, \"blas\": \"%s\"", argv[a], n, analysis.flops,
                threads, analysis.ordering == CHOLMOD_AMD ? "false" : "true", blas.c_str());
    struct Kernels { const char* name; InstructionSet set; };
    for (const Kernels k : {Kernels{"baseline", InstructionSet::Baseline},
                            Kernels{"avx2", InstructionSet::AVX2}}) {
      if (k.set == InstructionSet::AVX2 && !kresling::solvers::avx2_kernels_supported()) continue;
      ours.use_instruction_set(k.set);
      bool positive = true;
      const double llt = best_of([&] { positive = ours.factorize(K); }, repeat);
      Eigen::VectorXd x;
      const double solve = best_of([&] { x = ours.solve(b); }, repeat);
      const double error = residual(K, x, b);
      bool usable = true;
      const double ldlt = best_of([&] { usable = ours.factorize_ldlt(indefinite); }, repeat);
      const Eigen::VectorXd d = ours.ldlt_diagonal();
      std::printf(", \"%s\": {\"llt\": %.6e, \"solve\": %.6e, \"ldlt\": %.6e, "
                  "\"positive_definite\": %s, \"negative\": %d, \"residual\": %.2e}",
                  k.name, llt, solve, ldlt, positive ? "true" : "false",
                  usable ? static_cast<int>((d.array() < 0.0).count()) : -1, error);
    }
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholmod;
    cholmod_common& c = cholmod.cholmod();
    c.nmethods = 1;
    c.method[0].ordering = analysis.ordering;
    c.postorder = 1;
    cholmod.analyzePattern(K);
    const double llt = best_of([&] { cholmod.factorize(K); }, repeat);
    Eigen::VectorXd x;
    const double solve = best_of([&] { x = cholmod.solve(b); }, repeat);
    std::printf(", \"cholmod\": {\"llt\": %.6e, \"solve\": %.6e, \"residual\": %.2e}}\n",
                llt, solve, residual(K, x, b));
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--compare") == 0) return compare(argc - 2, argv + 2);
  std::printf("%-28s %7s %9s %10s %9s %10s %10s %10s %10s %10s %10s %10s %10s %10s %10s %9s %s\n",
              "matrix", "n", "ordering", "nnz(L)", "fl/nnz(L)", "dense us", "simpl us",
              "super us", "ND simpl", "ND super", "own 1t us", "own 2t us", "solve us",
              "simpl sol", "residual", "CHOLMOD", "model");
  for (int a = 1; a < argc; ++a) {
    SparseMatrix K;
    if (!read_matrix(argv[a], K)) return 1;
    const int n = static_cast<int>(K.rows());
    const int repeat = n < 3000 ? 30 : (n < 30000 ? 5 : 2);
    double dense = NAN;
    if (n <= 3000) {
      Eigen::MatrixXd D;
      Eigen::LLT<Eigen::MatrixXd, Eigen::Lower> llt;
      dense = best_of([&] {
        D.setZero(n, n);
        for (int c = 0; c < K.outerSize(); ++c)
          for (SparseMatrix::InnerIterator it(K, c); it; ++it)
            if (it.row() >= it.col()) D(it.row(), it.col()) = it.value();
        llt.compute(D);
      }, repeat);
    }
    double t[2][2], lnz[2], fl[2];  // [ordering AMD, NESDIS][simplicial, supernodal]
    const int orderings[2] = {CHOLMOD_AMD, CHOLMOD_NESDIS};
    for (int o = 0; o < 2; ++o) {
      for (int super = 0; super < 2; ++super) {
        Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> simplicial;
        Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> supernodal;
        cholmod_common& c = super ? supernodal.cholmod() : simplicial.cholmod();
        c.nmethods = 1;
        c.method[0].ordering = orderings[o];
        c.postorder = 1;
        if (super) supernodal.analyzePattern(K); else simplicial.analyzePattern(K);
        lnz[o] = c.lnz;
        fl[o] = c.fl;
        t[o][super] = best_of([&] {
          if (super) supernodal.factorize(K); else simplicial.factorize(K);
        }, repeat);
      }
    }
    kresling::solvers::TangentSolver solver;
    solver.factorize(K);
    const auto& plan = solver.plan();
    const int o = fl[1] < fl[0] ? 1 : 0;
    // Ours: CHOLMOD's symbolic analysis, Eigen's dense kernels; one thread and two.
    double own[2];
    double error = NAN, own_solve = NAN;
    for (int threads = 1; threads <= 2; ++threads) {
      kresling::solvers::SupernodalCholesky ours;
      ours.analyze(K, orderings[o], threads);
      own[threads - 1] = best_of([&] { ours.factorize(K); }, repeat);
      const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
      Eigen::VectorXd x;
      own_solve = best_of([&] { x = ours.solve(b); }, repeat);
      error = (K.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm();
    }
    // CHOLMOD's simplicial residual on the same system: the matrix's own conditioning.
    double reference = NAN, simplicial_solve = NAN;
    {
      Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> simplicial;
      simplicial.compute(K);
      const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
      Eigen::VectorXd x;
      simplicial_solve = best_of([&] { x = simplicial.solve(b); }, repeat);
      reference = (K.selfadjointView<Eigen::Lower>() * x - b).norm() / b.norm();
    }
    std::printf("%-28s %7d %9s %10.0f %9.0f %10.0f %10.0f %10.0f %10.0f %10.0f %10.0f %10.0f %10.1f %10.1f %10.1e %9.1e %s\n",
                argv[a], n, o ? "ND" : "AMD", lnz[o], fl[o] / lnz[o], dense * 1e6, t[0][0] * 1e6,
                t[0][1] * 1e6, t[1][0] * 1e6, t[1][1] * 1e6, own[0] * 1e6, own[1] * 1e6, own_solve * 1e6,
                simplicial_solve * 1e6, error, reference,
                name(plan.cholesky));
  }
  return 0;
}
