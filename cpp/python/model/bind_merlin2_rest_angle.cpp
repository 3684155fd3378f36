// kresling._core.model: what kresling/model/merlin2_rest_angle.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/merlin2_rest_angle.hpp"
#include "kresling/model/model.hpp"

namespace kresling::python {

void bind_merlin2_rest_angle(py::module_& m) {
  m.def(
      "merlin2_rest_angles",
      [](const Eigen::Ref<const NodeMatrix>& nodes, const std::vector<std::array<Index, 4>>& hinges) {
        return vector_array(model::merlin2_rest_angles(NodeMatrix(nodes), hinges));
      },
      py::arg("nodes"), py::arg("hinges"));
}

}  // namespace kresling::python
