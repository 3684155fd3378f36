#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "kresling/elements/bar.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"
#include "kresling/elements/spring_laws.hpp"
#include "kresling/model/model.hpp"

namespace py = pybind11;
using namespace kresling::elements;

namespace kresling::python {

void bind_elements(py::module_& m) {
  // The law kinds, named as the Python API names them (kresling.laws derives its tables
  // from these: the names and codes are declared here once).
  py::enum_<BarLawKind>(m, "BarLawKind")
      .value("linear", BarLawKind::Linear)
      .value("ogden", BarLawKind::Ogden);
  py::enum_<SpringLawKind>(m, "SpringLawKind")
      .value("linear", SpringLawKind::Linear)
      .value("enhanced_linear", SpringLawKind::EnhancedLinear)
      .value("super_linear_bend", SpringLawKind::SuperLinearBend);
  m.def("dihedral_angle", &dihedral_angle, py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"));
  m.def(
      "dihedral_angle_derivatives",
      [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d) {
        const auto r = dihedral_angle_derivatives(a, b, c, d, true);
        return py::make_tuple(r.angle, r.gradient, r.hessian);
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"));
  m.def(
      "dihedral_angles",
      [](const Eigen::Ref<const NodeMatrix>& x,
         py::array_t<Index, py::array::c_style | py::array::forcecast> hinges) {
        if (hinges.ndim() != 2 || hinges.shape(1) != 4) {
          throw std::invalid_argument("hinges: expected shape (n, 4)");
        }
        auto h = hinges.unchecked<2>();
        VectorX out(h.shape(0));
        const NodeMatrix X(x);
        const double scale = model::node_extent(X);  // once, not per hinge
        for (py::ssize_t i = 0; i < h.shape(0); ++i) {
          model::check_hinge_geometry_at_scale(X, {h(i, 0), h(i, 1), h(i, 2), h(i, 3)},
                                               static_cast<std::size_t>(i), scale);
          out[i] = dihedral_angle(x.row(h(i, 0)), x.row(h(i, 1)), x.row(h(i, 2)), x.row(h(i, 3)));
        }
        return out;
      },
      py::arg("nodes"), py::arg("hinges"));
  m.def(
      "bar_response",
      [](const Vector3& x1, const Vector3& x2, double area, double rest_length, int law,
         double modulus) {
        const auto r = bar_response(x1, x2, area, rest_length,
                                    BarLaw{bar_law_kind(law, "law"), modulus}, true);
        return py::make_tuple(r.energy, r.force, r.stiffness);
      },
      py::arg("x1"), py::arg("x2"), py::arg("area"), py::arg("rest_length"), py::arg("law"),
      py::arg("modulus"));
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
