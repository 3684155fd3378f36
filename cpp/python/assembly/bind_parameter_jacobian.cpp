// kresling._core.assembly: what kresling/assembly/parameter_jacobian.hpp declares.
#include "assembly/assembly_bindings.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/parameter_jacobian.hpp"

namespace kresling::python {

void bind_parameter_jacobian(py::module_& m) {
  m.def(
      "parameter_jacobian",
      [](const Model& model, const VectorX& u, const std::string& family,
         const std::string& parameter) {
        assembly::ParameterJacobian j;
        {
          py::gil_scoped_release release;
          j = assembly::parameter_jacobian(model, u, family, parameter);
        }
        return py::make_tuple(csc(j.force), j.energy);
      },
      py::arg("model"), py::arg("u"), py::arg("family"), py::arg("parameter"),
      "(csc parts of d f_int/d theta, 3N x m; dE/d theta, m) at fixed positions");
}

}  // namespace kresling::python
