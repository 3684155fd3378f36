// kresling._core.solvers: what kresling/solvers/supernodal_cholesky.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/sensitivity.hpp"
#include "kresling/solvers/supernodal_cholesky.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::python {

void bind_supernodal_cholesky(py::module_& m) {
  // What the tangent solver decides for a matrix's pattern, and one factorisation's outcome
  // (benchmarks report the fill and the choice; tests check the paths).
  m.def(
      "factorization_plan",
      [](const SparseMatrix& K) {
        FactorizationPlan plan;
        FactorizeInfo info;
        {
          py::gil_scoped_release release;
          TangentSolver solver;
          info = solver.factorize(K);
          plan = solver.plan();
        }
        static const char* choices[] = {"auto", "dense", "simplicial", "supernodal"};
        static const char* orderings[] = {"none", "amd", "nested dissection", "other"};
        static const char* methods[] = {"none", "cholesky", "ldlt", "lu", "dense cholesky",
                                        "supernodal cholesky"};
        py::dict out;
        out["cholesky"] = choices[static_cast<int>(plan.cholesky)];
        out["ordering"] = orderings[static_cast<int>(plan.ordering)];
        out["factor_nonzeros"] = plan.factor_nonzeros;
        out["flops"] = plan.flops;
        out["analysis_seconds"] = plan.analysis_seconds;
        out["ok"] = info.ok;
        out["method"] = methods[static_cast<int>(info.method)];
        out["negative_eigenvalues"] = info.negative_eigenvalues;
        return out;
      },
      py::arg("K"),
      "The factorisation chosen for the symmetric K (its lower triangle is read; scipy CSC), "
      "as a dict: cholesky, ordering, factor_nonzeros, flops, analysis_seconds, and the "
      "first factorisation's ok, method and negative_eigenvalues.");
}

}  // namespace kresling::python
