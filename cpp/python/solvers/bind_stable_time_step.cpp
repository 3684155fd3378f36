// kresling._core.solvers: what kresling/solvers/stable_time_step.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/stable_time_step.hpp"

namespace kresling::python {

void bind_stable_time_step(py::module_& m) {
  py::class_<StableStep>(m, "StableStep")
      .def_readonly("time_step", &StableStep::time_step)
      .def_readonly("omega_max", &StableStep::omega_max)
      .def_readonly("omega_bound", &StableStep::omega_bound)
      .def_readonly("iterations", &StableStep::iterations);
  m.def(
      "stable_time_step",
      [](const Model& model, const VectorX& masses, const VectorX& u, double mass_damping,
         double stiffness_damping) {
        py::gil_scoped_release release;
        return stable_time_step(model, masses, u, mass_damping, stiffness_damping);
      },
      py::arg("model"), py::arg("masses"), py::arg("u"), py::arg("mass_damping"),
      py::arg("stiffness_damping"));
}

}  // namespace kresling::python
