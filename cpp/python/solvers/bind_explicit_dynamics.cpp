// kresling._core.solvers: what kresling/solvers/explicit_dynamics.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/explicit_dynamics.hpp"
#include "kresling/solvers/time_integration.hpp"

namespace kresling::python {

void bind_explicit_dynamics(py::module_& m) {
  py::class_<ExplicitOptions>(m, "ExplicitOptions")
      .def(py::init<>())
      .def_readwrite("time_step", &ExplicitOptions::time_step)
      .def_readwrite("duration", &ExplicitOptions::duration)
      .def_readwrite("mass_damping", &ExplicitOptions::mass_damping)
      .def_readwrite("stiffness_damping", &ExplicitOptions::stiffness_damping)
      .def_readwrite("record_every", &ExplicitOptions::record_every)
      .def_property(
          "stop", [](const ExplicitOptions& o) { return static_cast<bool>(o.stop); },
          [](ExplicitOptions& o, const py::object& f) { o.stop = stop_rule(f); });
  bind_integrator<ExplicitOptions>(
      m, "integrate_explicit",
      [](const Model& model, const VectorX& masses, const TimeLoad& load,
         const ExplicitOptions& options, const VectorX& u0, const VectorX& v0) {
        return integrate_explicit(model, masses, load, options, u0, v0);
      },
      "Explicit central differences with lumped masses under load terms");
}

}  // namespace kresling::python
