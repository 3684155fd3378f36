// kresling._core.assembly: what kresling/assembly/shape_jacobian.hpp declares.
#include "assembly/assembly_bindings.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/shape_jacobian.hpp"

namespace kresling::python {

void bind_shape_jacobian(py::module_& m) {
  m.def(
      "reference_geometry_jacobian",
      [](const Model& model, const std::string& family, const std::string& column) {
        return csc(assembly::reference_geometry_jacobian(model, family, column));
      },
      py::arg("model"), py::arg("family"), py::arg("column"),
      "csc parts of d theta/dX (m x 3N) of the column's entries that hold the reference "
      "geometry");
  m.def(
      "shape_jacobian",
      [](const Model& model, const VectorX& u) {
        assembly::ShapeJacobian j;
        {
          py::gil_scoped_release release;
          j = assembly::shape_jacobian(model, u);
        }
        return py::make_tuple(csc(j.force), j.energy);
      },
      py::arg("model"), py::arg("u"),
      "(csc parts of d f_int/dX, 3N x 3N; dE/dX, 3N) at fixed u, the rest values that hold "
      "the reference geometry following it");
}

}  // namespace kresling::python
