// kresling._core.model: what kresling/model/model.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/family_registry.hpp"
#include "kresling/model/model.hpp"

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
}

}  // namespace kresling::python
