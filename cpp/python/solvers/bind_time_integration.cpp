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
      .def_readwrite("damping_current_tangent", &TimeIntegrationOptions::damping_current_tangent)
      // Creases driven in time: terms (hinges, start [rad], delta [rad], time function);
      // read back as the number of terms.
      .def_property(
          "actuation",
          [](const TimeIntegrationOptions& o) { return o.actuation.terms.size(); },
          [](TimeIntegrationOptions& o,
             const std::vector<std::tuple<std::vector<Index>, VectorX, VectorX,
                                          TimeFunctionTuple>>& terms) {
            RestAngleSchedule schedule;
            for (const auto& [hinges, start, delta, time] : terms) {
              schedule.terms.push_back({hinges, start, delta, time_factor_of(time)});
            }
            o.actuation = std::move(schedule);
          })
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
      .def_readonly("actuation_work", &TimeHistory::actuation_work)
      .def_readonly("stable_time_step", &TimeHistory::stable_time_step)
      .def_readonly("time_step", &TimeHistory::time_step);

  m.def(
      "time_factor",
      [](const TimeFunctionTuple& f, const VectorX& times) {
        const auto factor = time_factor_of(f);
        VectorX out(times.size());
        for (Index i = 0; i < times.size(); ++i) out[i] = factor ? factor(times[i]) : 1.0;
        return out;
      },
      py::arg("function"), py::arg("times"),
      "A time function (times, factors, amplitude, frequency_hz, end_frequency_hz, "
      "sweep_time) at the given times [s]");

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
