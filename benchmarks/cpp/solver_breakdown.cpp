// Where one Newton iteration's time goes: tangent assembly, force-only assembly, sparse
// factorisation and solve, for Kresling bending specimens of growing height (n = 4 and 10).
// Prints one row per model; the Python benchmark (benchmarks/solver_speed.py) runs it.
//
// Usage: solver_breakdown [--quick]

#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/solvers/tangent_solver.hpp"

using namespace kresling;
using Clock = std::chrono::steady_clock;

namespace {

template <typename F>
double microseconds_per_call(F&& f, double budget_seconds) {
  f();  // warm up (first factorisation includes the symbolic analysis)
  int calls = 0;
  const auto start = Clock::now();
  double elapsed = 0.0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  } while (elapsed < budget_seconds);
  return 1e6 * elapsed / calls;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const double budget = quick ? 0.05 : 0.5;
  std::printf("%3s %5s %6s %8s %12s %12s %12s %12s %10s\n", "n", "cells", "dofs", "nnz(L)",
              "setup_us", "tangent_us", "force_us", "factor_us", "solve_us");
  struct Case { int n; double lam, Lc; int cells; };
  std::vector<Case> cases = {{4, 0.7, 30.0, 4}, {10, 0.9, 15.0, 4}, {10, 0.9, 15.0, 8},
                             {10, 0.9, 15.0, 16}, {10, 0.9, 15.0, 30}, {10, 0.9, 15.0, 60}};
  if (quick) cases.resize(3);
  for (const Case& c : cases) {
    const geometry::Design design(c.n, 30.0, c.lam, c.Lc);
    std::vector<int> states(c.cells, 1), chirality(c.cells);
    for (int i = 0; i < c.cells; ++i) chirality[i] = i % 2 ? -1 : 1;
    const auto specimen = model::build_kresling_specimen(design, states, chirality);
    // The bending test's constraints: pins at both ends, the middle polygon driven in y.
    std::vector<std::uint8_t> held(static_cast<std::size_t>(specimen.model.num_dofs()), 0);
    for (int level : {0, c.cells}) {
      for (int j : {0, c.n / 2, c.n}) {
        for (int k = 0; k < 3; ++k) held[3 * specimen.node(level, j) + k] = 1;
      }
    }
    for (int j = 0; j <= c.n; ++j) held[3 * specimen.node(c.cells / 2, j) + 1] = 1;

    const double setup = microseconds_per_call([&] {
      assembly::Assembler a(specimen.model, assembly::unmasked_dofs(held), 1e-8,
                            assembly::Storage::Lower);
    }, budget);
    assembly::Assembler assembler(specimen.model, assembly::unmasked_dofs(held), 1e-8,
                                  assembly::Storage::Lower);
    const VectorX u = VectorX::Random(specimen.model.num_dofs()) * 1e-3;
    VectorX force;
    const double tangent = microseconds_per_call([&] { assembler.assemble(u, force, true); }, budget);
    const double force_only = microseconds_per_call([&] { assembler.assemble(u, force, false); }, budget);
    solvers::TangentSolver solver;
    const double factor = microseconds_per_call([&] { solver.factorize(assembler.matrix()); }, budget);
    const VectorX b = VectorX::Ones(assembler.size());
    const double solve = microseconds_per_call([&] { VectorX x = solver.solve(b); }, budget);
    std::printf("%3d %5d %6ld %8ld %12.1f %12.1f %12.1f %12.1f %10.1f\n", c.n, c.cells,
                static_cast<long>(assembler.size()),
                static_cast<long>(assembler.matrix().nonZeros()), setup, tangent, force_only,
                factor, solve);
  }
  return 0;
}
