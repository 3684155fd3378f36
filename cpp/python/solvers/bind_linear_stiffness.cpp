// kresling._core.solvers: what kresling/solvers/linear_stiffness.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/linear_stiffness.hpp"

namespace kresling::python {

void bind_linear_stiffness(py::module_& m) {
  m.def(
      "condensed_stiffness",
      [](const Model& model, const VectorX& u, const std::vector<Index>& dofs) {
        bool singular = false;
        Eigen::MatrixXd S;
        {
          py::gil_scoped_release release;
          S = condensed_stiffness(model, u, dofs, &singular);
        }
        return py::make_tuple(S, singular);
      },
      py::arg("model"), py::arg("u"), py::arg("dofs"));
}

}  // namespace kresling::python
