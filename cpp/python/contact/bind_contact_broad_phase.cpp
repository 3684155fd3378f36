// kresling._core.contact: what kresling/contact/contact_broad_phase.hpp declares.
#include "contact/contact_bindings.hpp"
#include "kresling/contact/contact_broad_phase.hpp"

namespace kresling::python {

namespace {

EdgeMatrix pair_rows(const std::vector<std::array<Index, 2>>& pairs) {
  EdgeMatrix rows(static_cast<Index>(pairs.size()), 2);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    rows(static_cast<Index>(k), 0) = pairs[k][0];
    rows(static_cast<Index>(k), 1) = pairs[k][1];
  }
  return rows;
}

}  // namespace

void bind_contact_broad_phase(py::module_& m) {
  m.def("triangle_edges", &triangle_edges, py::arg("triangles"));
  m.def(
      "contact_candidates",
      [](const Eigen::Ref<const NodeMatrix>& nodes,
         const Eigen::Ref<const TriangleMatrix>& triangles,
         double distance, std::optional<NodeMatrix> displacement) {
        const EdgeMatrix edges = triangle_edges(triangles);
        check_contact_mesh(nodes, triangles, edges, distance);
        if (displacement && !displacement->allFinite()) {
          throw std::invalid_argument("displacement: every coordinate must be finite");
        }
        const auto c = displacement
                           ? contact_candidates(nodes, triangles, edges, distance, *displacement)
                           : contact_candidates(nodes, triangles, edges, distance);
        return py::make_tuple(pair_rows(c.point_triangle), pair_rows(c.edge_edge), edges);
      },
      py::arg("nodes"), py::arg("triangles"), py::arg("distance"),
      py::arg("displacement") = py::none());
}

}  // namespace kresling::python
