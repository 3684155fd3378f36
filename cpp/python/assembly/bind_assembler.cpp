// kresling._core.assembly: what kresling/assembly/assembler.hpp declares.
#include "assembly/assembly_bindings.hpp"
#include "kresling/assembly/assembler.hpp"

namespace kresling::python {

void bind_assembler(py::module_& m) {
  m.def(
      "element_state",
      [](const Model& model, const VectorX& u) {
        // Every family's per-element columns, in the order the families add them.
        py::dict out;
        for (const auto& [name, values] : assembly::element_state(model, u).columns) {
          out[name.c_str()] = values;
        }
        return out;
      },
      py::arg("model"), py::arg("u"),
      "Per-element state at one displacement: {column: (E,) array}, family by family");

  m.def(
      "family_parameters",
      [](const Model& model) {
        py::dict out;
        for (const auto& family : model.families()) out[family->name()] = family->parameters();
        return out;
      },
      py::arg("model"), "{family: [parameter column, ...]} a model's families differentiate by");
}

}  // namespace kresling::python
