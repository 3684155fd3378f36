// kresling._core.contact: what kresling/contact/contact_ccd.hpp declares.
#include "contact/contact_bindings.hpp"
#include "kresling/contact/contact_ccd.hpp"

namespace kresling::python {

namespace {

CcdOptions ccd_options(double min_distance, double t_max, double conservative_rescaling) {
  CcdOptions o;
  o.min_distance = min_distance;
  o.t_max = t_max;
  o.conservative_rescaling = conservative_rescaling;
  check_ccd_options(o);
  return o;
}

using Rows4 = Eigen::Matrix<double, 4, 3, Eigen::RowMajor>;
using FourNodeCcd = TimeOfImpact (*)(const Vector3&, const Vector3&, const Vector3&,
                                     const Vector3&, const Vector3&, const Vector3&,
                                     const Vector3&, const Vector3&, const CcdOptions&);

// A four-node CCD kernel on the rows of (4, 3) arrays of start and end positions.
py::tuple ccd_tuple(FourNodeCcd kernel, const Rows4& start, const Rows4& end,
                    const CcdOptions& options) {
  if (!start.allFinite() || !end.allFinite()) {
    throw std::invalid_argument("start, end: every coordinate must be finite");
  }
  const Vector3 a0 = start.row(0), a1 = start.row(1), a2 = start.row(2), a3 = start.row(3);
  const Vector3 b0 = end.row(0), b1 = end.row(1), b2 = end.row(2), b3 = end.row(3);
  const auto r = kernel(a0, a1, a2, a3, b0, b1, b2, b3, options);
  return py::make_tuple(r.impact, r.toi);
}

}  // namespace

void bind_contact_ccd(py::module_& m) {
  m.def(
      "point_triangle_ccd",
      [](const Rows4& start, const Rows4& end, double min_distance, double t_max,
         double conservative_rescaling) {
        return ccd_tuple(&point_triangle_ccd, start, end,
                         ccd_options(min_distance, t_max, conservative_rescaling));
      },
      py::arg("start"), py::arg("end"), py::arg("min_distance") = 0.0, py::arg("t_max") = 1.0,
      py::arg("conservative_rescaling") = 0.9);
  m.def(
      "edge_edge_ccd",
      [](const Rows4& start, const Rows4& end, double min_distance, double t_max,
         double conservative_rescaling) {
        return ccd_tuple(&edge_edge_ccd, start, end,
                         ccd_options(min_distance, t_max, conservative_rescaling));
      },
      py::arg("start"), py::arg("end"), py::arg("min_distance") = 0.0, py::arg("t_max") = 1.0,
      py::arg("conservative_rescaling") = 0.9);
}

}  // namespace kresling::python
