// kresling._core.assembly: what kresling/assembly/workspace.hpp declares.
#include "assembly/assembly_bindings.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/workspace.hpp"

namespace kresling::python {

void bind_workspace(py::module_& m) {
  py::class_<assembly::Workspace>(
      m, "Workspace",
      "What assembling a model needs besides the model: the tangent's sparsity pattern and "
      "slot map for every DOF (whole storage). Serves any model of the connectivity it was "
      "built for and keeps no reference to a model. Not for use by two threads at once.")
      .def(py::init([](const Model& model) {
             return assembly::Workspace(model, assembly::all_dofs(model.num_dofs()), 0.0,
                                        assembly::Storage::Full);
           }),
           py::arg("model"))
      .def("fits", &assembly::Workspace::fits, py::arg("model"),
           "Whether `model` has the connectivity this workspace was built for")
      .def_property_readonly("size", &assembly::Workspace::size, "rows of the tangent (3N)");

  m.def(
      "assemble",
      [](const Model& model, const VectorX& u, double shift, bool with_matrix,
         assembly::Workspace* workspace) {
        VectorX force;
        assembly::Energies e;
        std::optional<assembly::Workspace> own;
        if (workspace == nullptr) {
          // A workspace for this call only: its pattern is built, used once and dropped.
          py::gil_scoped_release release;
          own.emplace(model, assembly::all_dofs(model.num_dofs()), shift, assembly::Storage::Full);
          e = assembly::assemble(model, *own, u, force, with_matrix);
        } else {
          // The caller's workspace: the GIL is kept, so two threads cannot fill it at once.
          workspace->set_shift(shift);
          e = assembly::assemble(model, *workspace, u, force, with_matrix);
        }
        const assembly::Workspace& used = workspace ? *workspace : *own;
        py::object K = with_matrix ? py::object(csc(used.matrix())) : py::none();
        return py::make_tuple(VectorX(e.vector()), force, K);
      },
      py::arg("model"), py::arg("u"), py::arg("shift"), py::arg("with_matrix"),
      py::arg("workspace") = py::none());
}

}  // namespace kresling::python
