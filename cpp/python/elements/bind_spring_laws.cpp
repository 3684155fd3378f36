// kresling._core.elements: what kresling/elements/spring_laws.hpp declares.
#include "elements/elements_bindings.hpp"
#include "kresling/elements/spring_laws.hpp"

namespace kresling::python {

void bind_spring_laws(py::module_& m) {
  py::enum_<SpringLawKind>(m, "SpringLawKind")
      .value("linear", SpringLawKind::Linear)
      .value("enhanced_linear", SpringLawKind::EnhancedLinear)
      .value("super_linear_bend", SpringLawKind::SuperLinearBend);
  m.def(
      "spring_law",
      [](int law, double theta, double rest_angle, double stiffness, double theta1, double theta2) {
        const auto r = SpringLaw{spring_law_kind(law, "law"), theta1, theta2}.evaluate(
            theta, rest_angle, stiffness);
        return py::make_tuple(r.moment, r.stiffness, r.energy);
      },
      py::arg("law"), py::arg("theta"), py::arg("rest_angle"), py::arg("stiffness"),
      py::arg("theta1"), py::arg("theta2"));
}

}  // namespace kresling::python
