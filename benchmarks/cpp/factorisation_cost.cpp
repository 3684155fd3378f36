// Calibration of the tangent solver's cost model (kresling/solvers/tangent_solver.cpp):
// for each symmetric matrix given (Matrix Market, the lower triangle of a tangent restricted
// to its free DOFs, e.g. K = kresling.assembly.tangent_stiffness(model, u, shift=1e-8)
// written by scipy.io.mmwrite(path, scipy.sparse.tril(K[free][:, free]),
// symmetry="symmetric")), the time of one factorisation by every candidate, the factor's
// entries and flops with each ordering, one solve with ours and with CHOLMOD's simplicial
// factor, and what the cost model picks.
//
// Run: build/py/factorisation_cost DIR/*.mtx  (built with KRESLING_BUILD_BENCHMARKS=ON).

#include <algorithm>
#include <chrono>
#include <cstdio>

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

}  // namespace

int main(int argc, char** argv) {
  std::printf("%-28s %7s %9s %10s %9s %10s %10s %10s %10s %10s %10s %10s %10s %10s %10s %9s %s\n",
              "matrix", "n", "ordering", "nnz(L)", "fl/nnz(L)", "dense us", "simpl us",
              "super us", "ND simpl", "ND super", "own 1t us", "own 2t us", "solve us",
              "simpl sol", "residual", "CHOLMOD", "model");
  for (int a = 1; a < argc; ++a) {
    SparseMatrix K;
    if (!Eigen::loadMarket(K, argv[a])) {
      std::fprintf(stderr, "%s: cannot read\n", argv[a]);
      return 1;
    }
    K.makeCompressed();
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
