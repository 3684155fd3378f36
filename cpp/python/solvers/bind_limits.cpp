// kresling._core.solvers: what kresling/solvers/limits.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/limits.hpp"

namespace kresling::python {

void bind_limits(py::module_& m) {
  // The documented bounds of the solvers' controls (kresling/solvers/limits.hpp).
  m.attr("MAX_STEPS") = kMaxSteps;
  m.attr("MAX_BISECTIONS") = kMaxBisections;
  m.attr("MAX_ITERATIONS") = kMaxIterations;
  m.attr("MAX_SHIFT") = kMaxShift;
}

}  // namespace kresling::python
