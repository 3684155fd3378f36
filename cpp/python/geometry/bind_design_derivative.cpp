// kresling._core.geometry: what kresling/geometry/design_derivative.hpp declares.
#include "geometry/geometry_bindings.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/geometry/design_derivative.hpp"

namespace kresling::python {

void bind_design_derivative(py::module_& m) {
  m.def(
      "state_derivative",
      [](const Design& design, int state, const std::string& variable) {
        if (state != 0 && state != 1) {
          throw std::invalid_argument("state = " + std::to_string(state) +
                                      " is invalid: must be 0 (contracted) or 1 (extended)");
        }
        const auto d = kresling::geometry::state_derivative(
            design, static_cast<kresling::geometry::State>(state),
            kresling::geometry::design_variable(variable));
        return py::make_tuple(d.height, d.twist);
      },
      py::arg("design"), py::arg("state"), py::arg("variable"),
      "(d height/dv [mm per unit], d twist/dv [rad per unit]) of a stable state by lam, Lc or R");
}

}  // namespace kresling::python
