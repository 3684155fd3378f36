// kresling._core.elements: what kresling/elements/hinge.hpp declares.
#include "elements/elements_bindings.hpp"
#include "kresling/elements/hinge.hpp"
#include "kresling/elements/spring_laws.hpp"

namespace kresling::python {

void bind_hinge(py::module_& m) {
  m.def(
      "hinge_response",
      [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d, double kp,
         double rest_angle, double length, int law, double theta1, double theta2) {
        const auto r = hinge_response(a, b, c, d, kp, rest_angle, length,
                                      SpringLaw{spring_law_kind(law, "law"), theta1, theta2});
        return py::make_tuple(r.energy, r.force, r.stiffness, r.angle, r.moment);
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::arg("stiffness"),
      py::arg("rest_angle"), py::arg("length"), py::arg("law"), py::arg("theta1"),
      py::arg("theta2"));
}

}  // namespace kresling::python
