// kresling._core.kinematics: what kresling/kinematics/constant_curvature.hpp declares.
#include "kinematics/kinematics_bindings.hpp"
#include "kresling/kinematics/constant_curvature.hpp"

namespace kresling::python {

namespace {

// Apply a (row, suffix) -> row map to every row of an (n, 3) array, without the GIL.
template <typename F>
Rows3 map_rows(const Rows3& in, F f) {
  Rows3 out(in.rows(), 3);
  py::gil_scoped_release release;
  for (Eigen::Index i = 0; i < in.rows(); ++i) {
    const std::string suffix = in.rows() > 1 ? "[" + std::to_string(i) + "]" : "";
    out.row(i) = f(Eigen::Vector3d(in.row(i).transpose()), suffix).transpose();
  }
  return out;
}

// Bind f(row, layout, suffix) -> row as a batch function over (n, 3) arrays.
using RowMap = Eigen::Vector3d (*)(const Eigen::Vector3d&, const kk::TendonLayout&,
                                   const std::string&);
void bind_row_map(py::module_& m, const char* name, RowMap f, const char* input, const char* doc) {
  m.def(
      name,
      [f, input](py::array_t<double, py::array::c_style | py::array::forcecast> rows, double d,
                 int N) {
        const kk::TendonLayout layout{d, N};
        return map_rows(as_rows3(rows, input),
                        [&](const Eigen::Vector3d& row, const std::string& suffix) {
                          return f(row, layout, suffix);
                        });
      },
      py::arg(input), py::arg("d"), py::arg("N"), doc);
}

}  // namespace

void bind_constant_curvature(py::module_& m) {
  m.def("tendon_angle", &kk::tendon_angle, py::arg("i"),
        "Angle of tendon i (0-based) in a module's base frame [rad].");
  bind_row_map(m, "arc_from_tendons", &kk::arc_from_tendons, "lengths",
               "Eqns 27-29: (n, 3) tendon lengths [mm] -> (n, 3) arcs (s [mm], kappa [1/mm], "
               "phi [rad]).");
  bind_row_map(m, "tendons_from_arc", &kk::tendons_from_arc, "arcs",
               "Inverse of arc_from_tendons: (n, 3) arcs -> (n, 3) tendon lengths [mm].");
}

}  // namespace kresling::python
