// kresling._core.solvers: what kresling/solvers/fold.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/fold.hpp"

namespace kresling::python {

void bind_fold(py::module_& m) {
  bind_path_options<FoldOptions>(m, "FoldOptions")
      .def_readwrite("max_bisections", &FoldOptions::max_bisections)
      .def_readwrite("extrapolation", &FoldOptions::extrapolation)
      .def_readwrite("adaptive", &FoldOptions::adaptive)
      .def_readwrite("adaptive_tolerance", &FoldOptions::adaptive_tolerance)
      .def_readwrite("snap", &FoldOptions::snap)
      .def_readwrite("relax", &FoldOptions::relax);

  m.def(
      "fold",
      [](const Model& model, const std::vector<std::pair<std::vector<Index>, VectorX>>& stages,
         int steps, const VectorX& forces, const FoldOptions& options, const VectorX& initial) {
        std::vector<FoldStage> list;
        for (const auto& [hinges, targets] : stages) list.push_back({hinges, targets});
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_fold(model, list, steps, forces, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("stages"), py::arg("steps"), py::arg("forces"),
      py::arg("options"), py::arg("initial"),
      "Fold by crease actuation: stages of (hinge indices, target rest angles [rad])");
}

}  // namespace kresling::python
