// kresling._core.solvers: what kresling/solvers/displacement_control.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/displacement_control.hpp"

namespace kresling::python {

void bind_displacement_control(py::module_& m) {
  bind_path_options<DisplacementControlOptions>(m, "DisplacementControlOptions")
      .def_readwrite("reject_iterations", &DisplacementControlOptions::reject_iterations)
      .def_readwrite("max_bisections", &DisplacementControlOptions::max_bisections)
      .def_readwrite("extrapolation", &DisplacementControlOptions::extrapolation)
      .def_readwrite("merlin2_steps", &DisplacementControlOptions::merlin2_steps)
      .def_readwrite("adaptive", &DisplacementControlOptions::adaptive)
      .def_readwrite("adaptive_tolerance", &DisplacementControlOptions::adaptive_tolerance)
      .def_readwrite("keep_knots", &DisplacementControlOptions::keep_knots);

  m.def(
      "displacement_control",
      [](const Model& model, const VectorX& prescribed, int steps,
         const DisplacementControlOptions& options, const VectorX& initial) {
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_displacement_control(model, prescribed, steps, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("prescribed"), py::arg("steps"), py::arg("options"),
      py::arg("initial"));
}

}  // namespace kresling::python
