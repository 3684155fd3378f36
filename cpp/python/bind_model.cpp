#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/model/arm.hpp"
#include "kresling/model/calibration.hpp"
#include "kresling/model/family_registry.hpp"
#include "kresling/model/kresling_design_derivative.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/model/merlin2_rest_angle.hpp"
#include "kresling/model/model.hpp"
#include "kresling/model/panel_centre.hpp"
#include "kresling/model/panel_elements.hpp"
#include "kresling/model/topology.hpp"

namespace py = pybind11;

namespace kresling::python {

namespace {


void require_shape(const char* name, const py::array& a, py::ssize_t rows, py::ssize_t cols) {
  const bool ok = cols < 0 ? (a.ndim() == 1 && a.shape(0) == rows)
                           : (a.ndim() == 2 && a.shape(0) == rows && a.shape(1) == cols);
  if (!ok) {
    throw std::invalid_argument(std::string(name) + ": expected shape (" + std::to_string(rows) +
                                (cols < 0 ? "," : ", " + std::to_string(cols)) + ")");
  }
}

// A family's table from a dict of numpy arrays {column: (E,) or (E, k) array}: integer
// arrays become node-index columns, the others real ones.
model::Table table_from_dict(const std::string& family, const py::dict& columns) {
  model::Table table;
  for (const auto& [key, value] : columns) {
    const std::string name = py::cast<std::string>(key);
    const py::array a = py::array::ensure(value);
    if (!a || a.ndim() > 2) {
      throw std::invalid_argument(family + "." + name + ": must be an array of shape (E,) or (E, k)");
    }
    const Index width = a.ndim() == 2 ? static_cast<Index>(a.shape(1)) : 1;
    const char kind = a.dtype().kind();
    if (kind == 'i' || kind == 'u') {
      const auto v = py::array_t<Index, py::array::c_style | py::array::forcecast>::ensure(a);
      table[name] = model::index_column(std::vector<Index>(v.data(), v.data() + v.size()), width);
    } else if (kind == 'f') {
      const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
      table[name] = model::real_column(std::vector<double>(v.data(), v.data() + v.size()), width);
    } else {
      throw std::invalid_argument(family + "." + name + ": must hold integers or reals");
    }
  }
  return table;
}

py::dict table_to_dict(const model::Table& table) {
  py::dict out;
  for (const auto& [name, c] : table) {
    const py::ssize_t rows = c.width > 0 ? c.size() / c.width : 0;
    std::vector<py::ssize_t> shape = c.width == 1 ? std::vector<py::ssize_t>{rows}
                                                  : std::vector<py::ssize_t>{rows, c.width};
    if (c.integer) {
      out[name.c_str()] = py::array_t<Index>(shape, c.indices.data());
    } else {
      out[name.c_str()] = py::array_t<double>(shape, c.reals.data());
    }
  }
  return out;
}

model::Model make_model(const Eigen::Ref<const NodeMatrix>& nodes,
                        py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> fixed,
                        const py::dict& families) {
  require_shape("fixed", fixed, 3 * nodes.rows(), -1);
  std::vector<model::FamilyPtr> list;
  for (const auto& [key, value] : families) {
    const std::string name = py::cast<std::string>(key);
    if (!py::isinstance<py::dict>(value)) {
      throw std::invalid_argument("families['" + name + "']: must be a dict of columns");
    }
    list.push_back(model::family_kind(name).from_table(table_from_dict(name, value.cast<py::dict>())));
  }
  std::vector<std::uint8_t> mask(fixed.data(), fixed.data() + fixed.size());
  py::gil_scoped_release release;  // validation of a large model takes a while
  return model::Model(NodeMatrix(nodes), std::move(mask), std::move(list));
}

// Rows of fixed-size index arrays as an (n, width) int64 array.
template <std::size_t Width>
py::array_t<Index> index_rows(const std::vector<std::array<Index, Width>>& v) {
  py::array_t<Index> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(Width)});
  auto w = a.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t k = 0; k < Width; ++k) w(i, k) = v[i][k];
  }
  return a;
}

template <typename T>
py::array_t<T> vector_array(const std::vector<T>& v) {
  return py::array_t<T>(static_cast<py::ssize_t>(v.size()), v.data());
}

std::vector<int> families(const std::vector<model::EdgeFamily>& f) {
  std::vector<int> out(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) out[i] = static_cast<int>(f[i]);
  return out;
}

// Kresling specimens (model/kresling_specimen.hpp): their parameters, the built specimen.
void bind_specimen(py::module_& m) {
  using model::SpecimenParameters;
  // The element families of a specimen by their codes: kresling.model.EDGE_FAMILIES reads
  // its names from here.
  py::enum_<model::EdgeFamily>(m, "EdgeFamily", "What an edge of a Kresling specimen is")
      .value("valley", model::EdgeFamily::Valley)
      .value("mountain", model::EdgeFamily::Mountain)
      .value("polygon_edge", model::EdgeFamily::PolygonEdge)
      .value("polygon_spoke", model::EdgeFamily::PolygonSpoke);
  py::class_<SpecimenParameters>(m, "SpecimenParameters")
      .def(py::init<>())
      .def_readwrite("kf", &SpecimenParameters::kf)
      .def_readwrite("valley_factor", &SpecimenParameters::valley_factor)
      .def_readwrite("polygon_edge_factor", &SpecimenParameters::polygon_edge_factor)
      .def_readwrite("spoke_factor", &SpecimenParameters::spoke_factor)
      .def_readwrite("mountain_factor", &SpecimenParameters::mountain_factor)
      .def_readwrite("modulus_factor", &SpecimenParameters::modulus_factor)
      .def_readwrite("material_area", &SpecimenParameters::material_area)
      .def_readwrite("mountain_area", &SpecimenParameters::mountain_area)
      .def_readwrite("theta1", &SpecimenParameters::theta1)
      .def_readwrite("theta2", &SpecimenParameters::theta2)
      .def_property(
          "bar_law", [](const SpecimenParameters& p) { return static_cast<int>(p.bar_law); },
          [](SpecimenParameters& p, int law) { p.bar_law = elements::bar_law_kind(law, "bar_law"); })
      .def_readwrite("duplicate_shared_edges", &SpecimenParameters::duplicate_shared_edges)
      .def_readwrite("hinge_angle", &SpecimenParameters::hinge_angle);

  py::class_<model::KreslingSpecimen>(
      m, "KreslingSpecimen", "A Kresling stack's model with its element families and levels")
      .def_readonly("model", &model::KreslingSpecimen::model)
      .def_property_readonly(
          "bar_family", [](const model::KreslingSpecimen& s) { return families(s.bar_family); },
          "edge family code per bar (B,)")
      .def_property_readonly(
          "hinge_family", [](const model::KreslingSpecimen& s) { return families(s.hinge_family); },
          "edge family code of each hinge's axis (H,)")
      .def_readonly("level_height", &model::KreslingSpecimen::level_height, "z of each level [mm]")
      .def_readonly("level_angle", &model::KreslingSpecimen::level_angle,
                    "theta of each level [rad]")
      .def_readonly("n", &model::KreslingSpecimen::n)
      .def_readonly("cells", &model::KreslingSpecimen::cells);

  m.def(
      "build_kresling_specimen",
      [](const geometry::Design& design, const std::vector<int>& states,
         const std::vector<int>& chirality, const SpecimenParameters& parameters,
         const std::vector<std::uint8_t>& fixed) {
        return model::build_kresling_specimen(design, states, chirality, parameters, fixed);
      },
      py::arg("design"), py::arg("states"), py::arg("chirality"), py::arg("parameters"),
      py::arg("fixed"));
  m.attr("MAX_SPECIMEN_NODES") = model::kMaxSpecimenNodes;
  m.def(
      "specimen_design_derivative",
      [](const model::KreslingSpecimen& specimen, const geometry::Design& design,
         const std::vector<int>& states, const std::vector<int>& chirality,
         const SpecimenParameters& parameters, const std::string& variable) {
        const model::SpecimenDesignDerivative d = model::specimen_design_derivative(
            specimen, design, states, chirality, parameters, variable);
        return py::make_tuple(d.positions, d.bar_area, d.bar_modulus, d.hinge_stiffness);
      },
      py::arg("specimen"), py::arg("design"), py::arg("states"), py::arg("chirality"),
      py::arg("parameters"), py::arg("variable"),
      "(dX/dv (3N), d area/dv (bars), d modulus/dv (bars), d stiffness/dv (hinges)) of a "
      "Kresling specimen by a design variable (lam, Lc, R, thickness, kf)");
  m.attr("FACET_THICKNESS") = model::kFacetThickness;
}

// The manipulator as one structure (model/arm.hpp): modules, guide plates, tendons.
void bind_arm_model(py::module_& m) {
  using model::Arm;
  using model::ArmParameters;
  py::class_<ArmParameters>(m, "ArmParameters")
      .def(py::init<>())
      .def_readwrite("specimen", &ArmParameters::specimen)
      .def_readwrite("tendon_radius", &ArmParameters::tendon_radius)
      .def_readwrite("guide_radius", &ArmParameters::guide_radius)
      .def_readwrite("guide_factor", &ArmParameters::guide_factor)
      .def_readwrite("tendon_stiffness", &ArmParameters::tendon_stiffness)
      .def_readwrite("contact_distance", &ArmParameters::contact_distance)
      .def_readwrite("contact_stiffness", &ArmParameters::contact_stiffness);

  py::class_<Arm>(m, "Arm")
      .def_readonly("model", &Arm::model)
      .def_readonly("n", &Arm::n)
      .def_readonly("modules", &Arm::modules)
      .def_readonly("states", &Arm::states)
      .def_readonly("cell_states", &Arm::cell_states)
      .def_readonly("chirality", &Arm::chirality)
      .def_readonly("level_height", &Arm::level_height)
      .def_readonly("level_angle", &Arm::level_angle)
      .def_readonly("cell_bars", &Arm::cell_bars)
      .def_readonly("cell_hinges", &Arm::cell_hinges)
      .def_readonly("holes", &Arm::holes)
      .def_readonly("slack_length", &Arm::slack_length)
      .def_readonly("cell_extended", &Arm::cell_extended)
      .def_readonly("cell_contracted", &Arm::cell_contracted)
      .def_property_readonly("tip_node", &Arm::tip_node)
      .def("node", &Arm::node, py::arg("level"), py::arg("j"))
      .def("guide_level", &Arm::guide_level, py::arg("guide"));

  m.def("parse_configuration", &model::parse_configuration, py::arg("configuration"),
        py::arg("modules") = 0);
  m.def("build_arm", &model::build_arm, py::arg("design"), py::arg("states"),
        py::arg("parameters"));
}

}  // namespace

void bind_model(py::module_& m) {
  py::class_<model::Model>(m, "Model")
      .def(py::init(&make_model), py::arg("nodes"), py::arg("fixed"), py::arg("families"),
           "A model of nodes (N, 3), supports (3N,) and element families {name: {column: "
           "array}} (see family_kinds())")
      .def_property_readonly("num_nodes", &model::Model::num_nodes)
      .def_property_readonly("num_dofs", &model::Model::num_dofs)
      .def_property_readonly("num_cables", [](const model::Model& m) { return m.cables().size(); })
      .def_property_readonly("num_bars", [](const model::Model& m) { return m.bars().size(); })
      .def_property_readonly("num_hinges", [](const model::Model& m) { return m.hinges().size(); })
      .def_property_readonly(
          "families",
          [](const model::Model& m) {
            std::vector<std::string> names;
            for (const auto& f : m.families()) names.emplace_back(f->name());
            return names;
          },
          "the element families, in assembly order")
      .def("with_cable_rest_lengths", &model::Model::with_cable_rest_lengths,
           py::arg("rest_lengths"))
      .def_property_readonly("nodes", [](const model::Model& m) { return m.nodes(); })
      .def_property_readonly("fixed", [](const model::Model& m) {
        return py::array_t<std::uint8_t>(static_cast<py::ssize_t>(m.fixed().size()), m.fixed().data());
      })
      .def("tables", [](const model::Model& m) {
        // Every family's data as columns (family_table.hpp), for the Python Model's views.
        py::dict out;
        for (const auto& f : m.families()) out[f->name()] = table_to_dict(f->table());
        return out;
      });
  m.def("family_kinds", [] {
    std::vector<std::pair<std::string, std::string>> kinds;
    for (const auto& k : model::family_kinds()) kinds.emplace_back(k.name, k.description);
    return kinds;
  }, "the registered element families: (name, description), in assembly order");

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

  py::class_<model::SheetMaterial>(m, "SheetMaterial")
      .def(py::init<>())
      .def_readwrite("youngs_modulus", &model::SheetMaterial::youngs_modulus)
      .def_readwrite("poisson_ratio", &model::SheetMaterial::poisson_ratio)
      .def_readwrite("thickness", &model::SheetMaterial::thickness)
      .def_readwrite("length_scale", &model::SheetMaterial::length_scale);

  py::class_<model::SheetStiffness>(m, "SheetStiffness")
      .def_property_readonly("bar_area",
                             [](const model::SheetStiffness& s) { return vector_array(s.bar_area); })
      .def_property_readonly("fold_stiffness",
                             [](const model::SheetStiffness& s) { return vector_array(s.fold_stiffness); })
      .def_property_readonly("bend_stiffness",
                             [](const model::SheetStiffness& s) { return vector_array(s.bend_stiffness); })
      .def_readonly("length_scale", &model::SheetStiffness::length_scale);

  m.def("calibrate_sheet", &model::calibrate_sheet, py::arg("elements"), py::arg("panels"),
        py::arg("material"), py::arg("merlin2_compat"));
  m.def(
      "merlin2_rest_angles",
      [](const Eigen::Ref<const NodeMatrix>& nodes, const std::vector<std::array<Index, 4>>& hinges) {
        return vector_array(model::merlin2_rest_angles(NodeMatrix(nodes), hinges));
      },
      py::arg("nodes"), py::arg("hinges"));
  m.def("quad_centre", &model::quad_centre);
  m.def("polygon_optimal_centre", &model::polygon_optimal_centre);
  m.def("polygon_centre_objective", &model::polygon_centre_objective);
  bind_specimen(m);
  bind_arm_model(m);
}

}  // namespace kresling::python
