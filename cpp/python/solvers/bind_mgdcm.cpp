// kresling._core.solvers: what kresling/solvers/mgdcm.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/mgdcm.hpp"

namespace kresling::python {

void bind_mgdcm(py::module_& m) {
  bind_path_options<MgdcmOptions>(m, "MgdcmOptions")
      .def_readwrite("initial_load_factor", &MgdcmOptions::initial_load_factor)
      .def_readwrite("max_increments", &MgdcmOptions::max_increments)
      .def_readwrite("max_load_factor", &MgdcmOptions::max_load_factor)
      .def_readwrite("monitor_dof", &MgdcmOptions::monitor_dof)
      .def_readwrite("max_displacement", &MgdcmOptions::max_displacement)
      .def_readwrite("max_step_factor", &MgdcmOptions::max_step_factor);

  m.def(
      "mgdcm",
      [](const Model& model, const VectorX& forces, const MgdcmOptions& options,
         const VectorX& initial) {
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_mgdcm(model, forces, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("forces"), py::arg("options"), py::arg("initial"));
}

}  // namespace kresling::python
