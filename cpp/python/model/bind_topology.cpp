// kresling._core.model: what kresling/model/topology.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/model.hpp"
#include "kresling/model/topology.hpp"

namespace kresling::python {

void bind_topology(py::module_& m) {
  using model::Topology;
  py::class_<Topology>(m, "Topology", "The elements a set of panels produces (read-only)")
      .def_property_readonly("nodes", [](const Topology& t) { return t.nodes; },
                             "the input nodes, then N5B8 centre nodes (N, 3) [mm]")
      .def_property_readonly("triangles", [](const Topology& t) { return index_rows(t.triangles); },
                             "triangles in canonical order (T, 3)")
      .def_property_readonly("triangle_panel",
                             [](const Topology& t) { return vector_array(t.triangle_panel); },
                             "the panel each triangle came from (T,)")
      .def_property_readonly("bars", [](const Topology& t) { return index_rows(t.bars); },
                             "end nodes, ascending (B, 2)")
      .def_property_readonly("hinges", [](const Topology& t) { return index_rows(t.hinges); },
                             "(a, b, c, d): axis a < b, wings c, d (H, 4)")
      .def_property_readonly(
          "hinge_is_bend",
          [](const Topology& t) {
            return py::array_t<bool>(static_cast<py::ssize_t>(t.hinge_is_bend.size()),
                                     reinterpret_cast<const bool*>(t.hinge_is_bend.data()));
          },
          "True for an edge added inside a panel (H,)");
  m.def(
      "build_topology",
      [](const Eigen::Ref<const NodeMatrix>& nodes, const std::vector<std::vector<Index>>& panels,
         int split, bool duplicate) {
        if (split != 0 && split != 1) throw std::invalid_argument("split: unknown code");
        return model::build_topology(NodeMatrix(nodes), panels,
                                     static_cast<model::PanelSplit>(split), duplicate);
      },
      py::arg("nodes"), py::arg("panels"), py::arg("split"), py::arg("duplicate_shared_edges"));
}

}  // namespace kresling::python
