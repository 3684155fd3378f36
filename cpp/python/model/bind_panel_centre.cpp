// kresling._core.model: what kresling/model/panel_centre.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/panel_centre.hpp"

namespace kresling::python {

void bind_panel_centre(py::module_& m) {
  m.def("quad_centre", &model::quad_centre);
  m.def("polygon_optimal_centre", &model::polygon_optimal_centre);
  m.def("polygon_centre_objective", &model::polygon_centre_objective);
}

}  // namespace kresling::python
