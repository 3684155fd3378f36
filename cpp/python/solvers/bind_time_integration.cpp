// kresling._core.solvers: what kresling/solvers/time_integration.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/stable_time_step.hpp"
#include "kresling/solvers/time_integration.hpp"

namespace kresling::python {

void bind_time_integration(py::module_& m) {
  bind_path_options<TimeIntegrationOptions>(m, "TimeIntegrationOptions")
      .def_readwrite("time_step", &TimeIntegrationOptions::time_step)
      .def_readwrite("duration", &TimeIntegrationOptions::duration)
      .def_readwrite("hht_alpha", &TimeIntegrationOptions::hht_alpha)
      .def_readwrite("mass_damping", &TimeIntegrationOptions::mass_damping)
      .def_readwrite("stiffness_damping", &TimeIntegrationOptions::stiffness_damping)
      .def_readwrite("max_halvings", &TimeIntegrationOptions::max_halvings);
  py::class_<TimeHistory>(m, "TimeHistory")
      .def_readonly("path", &TimeHistory::path)
      .def_property_readonly("velocity", [](const TimeHistory& h) {
        const Index n = h.velocity.empty() ? 0 : h.velocity.front().size();
        RowMatrix out(static_cast<Index>(h.velocity.size()), n);
        for (std::size_t k = 0; k < h.velocity.size(); ++k) out.row(static_cast<Index>(k)) = h.velocity[k].transpose();
        return out;
      })
      .def_readonly("kinetic", &TimeHistory::kinetic)
      .def_readonly("strain", &TimeHistory::strain)
      .def_readonly("dissipated", &TimeHistory::dissipated)
      .def_readonly("work", &TimeHistory::work)
      .def_readonly("stable_time_step", &TimeHistory::stable_time_step)
      .def_readonly("time_step", &TimeHistory::time_step);

  bind_integrator<TimeIntegrationOptions>(
      m, "integrate_newmark",
      [](const Model& model, const VectorX& masses, const TimeLoad& load,
         const TimeIntegrationOptions& options, const VectorX& u0, const VectorX& v0) {
        return integrate_newmark(model, masses, load, options, u0, v0);
      },
      "Newmark / HHT-alpha time integration under load terms (forces, times, factors, "
      "amplitude, frequency_hz)");
}

}  // namespace kresling::python
