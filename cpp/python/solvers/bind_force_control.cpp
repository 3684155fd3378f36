// kresling._core.solvers: what kresling/solvers/force_control.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/force_control.hpp"

namespace kresling::python {

void bind_force_control(py::module_& m) {
  bind_path_options<ForceControlOptions>(m, "ForceControlOptions")
      .def_readwrite("max_bisections", &ForceControlOptions::max_bisections);

  m.def(
      "force_control",
      [](const Model& model, const VectorX& forces, int steps, const ForceControlOptions& options,
         const VectorX& initial) {
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_force_control(model, forces, steps, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("forces"), py::arg("steps"), py::arg("options"),
      py::arg("initial"));
}

}  // namespace kresling::python
