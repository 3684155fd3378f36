// kresling._core.analyses: what kresling/analyses/linear_bending.hpp declares.
#include "analyses/analyses_bindings.hpp"
#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/linear_bending.hpp"

namespace kresling::python {

void bind_linear_bending(py::module_& m) {
  // The linearised bending test (kresling.analyses.LinearBendingTester wraps it): runs
  // without the GIL, so threads of a sweep evaluate designs in parallel.
  py::class_<analyses::LinearBendingTest>(m, "LinearBendingTest")
      .def(py::init<int, int, SpecimenParameters>(), py::arg("n"), py::arg("cells"),
           py::arg("parameters"))
      .def(
          "run",
          [](analyses::LinearBendingTest& test, const Design& design, int state, double angle,
             double pin_offset) {
            analyses::LinearBendingResult r;
            {
              py::gil_scoped_release release;
              r = test.run(design, state, angle, pin_offset);
            }
            return py::make_tuple(r.stiffness, r.condensed_force, r.cancelled);
          },
          py::arg("design"), py::arg("state"), py::arg("angle"), py::arg("pin_offset"),
          "(K_B [N m/rad], condensed force F [N/mm], e^T K_pp e [N/mm] of which F is the "
          "remainder).");
}

}  // namespace kresling::python
