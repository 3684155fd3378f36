// kresling._core.model: what kresling/model/panel_elements.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/model.hpp"
#include "kresling/model/panel_elements.hpp"

namespace kresling::python {

void bind_panel_elements(py::module_& m) {
  py::class_<model::PanelElements>(m, "PanelElements",
                                   "Bars and hinges of panels by MERLIN2's rules (read-only).")
      .def_property_readonly("nodes", [](const model::PanelElements& e) { return e.nodes; })
      .def_property_readonly("panel_centre",
                             [](const model::PanelElements& e) { return vector_array(e.panel_centre); })
      .def_property_readonly("triangles",
                             [](const model::PanelElements& e) { return index_rows(e.triangles); })
      .def_property_readonly("bends", [](const model::PanelElements& e) { return index_rows(e.bends); })
      .def_property_readonly("bend_panel",
                             [](const model::PanelElements& e) { return vector_array(e.bend_panel); })
      .def_property_readonly("folds", [](const model::PanelElements& e) { return index_rows(e.folds); })
      .def_property_readonly("boundary",
                             [](const model::PanelElements& e) { return index_rows(e.boundary); })
      .def_property_readonly("bars", [](const model::PanelElements& e) { return index_rows(e.bars()); });

  m.def(
      "build_panel_elements",
      [](const Eigen::Ref<const NodeMatrix>& vertices, const std::vector<std::vector<Index>>& panels,
         int split, int centre) {
        if (split != 0 && split != 1) throw std::invalid_argument("split: unknown code");
        if (centre != 0 && centre != 1) throw std::invalid_argument("centre: unknown code");
        return model::build_panel_elements(NodeMatrix(vertices), panels,
                                           static_cast<model::PanelSplit>(split),
                                           static_cast<model::CentreRule>(centre));
      },
      py::arg("vertices"), py::arg("panels"), py::arg("split"), py::arg("centre") = 0);
}

}  // namespace kresling::python
