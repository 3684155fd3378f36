#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/parameter_jacobian.hpp"
#include "kresling/assembly/shape_jacobian.hpp"
#include "kresling/assembly/workspace.hpp"

namespace py = pybind11;
using kresling::model::Model;

namespace kresling::python {

py::tuple csc(const assembly::SparseMatrix& K) {
  // Copies: the Python side owns its arrays.
  py::array_t<int> indptr(K.outerSize() + 1, K.outerIndexPtr());
  py::array_t<int> indices(K.nonZeros(), K.innerIndexPtr());
  py::array_t<double> data(K.nonZeros(), K.valuePtr());
  return py::make_tuple(data, indices, indptr, py::make_tuple(K.rows(), K.cols()));
}

void bind_assembly(py::module_& m) {
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
  m.def(
      "parameter_jacobian",
      [](const Model& model, const VectorX& u, const std::string& family,
         const std::string& parameter) {
        assembly::ParameterJacobian j;
        {
          py::gil_scoped_release release;
          j = assembly::parameter_jacobian(model, u, family, parameter);
        }
        return py::make_tuple(csc(j.force), j.energy);
      },
      py::arg("model"), py::arg("u"), py::arg("family"), py::arg("parameter"),
      "(csc parts of d f_int/d theta, 3N x m; dE/d theta, m) at fixed positions");
  m.def(
      "reference_geometry_jacobian",
      [](const Model& model, const std::string& family, const std::string& column) {
        return csc(assembly::reference_geometry_jacobian(model, family, column));
      },
      py::arg("model"), py::arg("family"), py::arg("column"),
      "csc parts of d theta/dX (m x 3N) of the column's entries that hold the reference "
      "geometry");
  m.def(
      "shape_jacobian",
      [](const Model& model, const VectorX& u) {
        assembly::ShapeJacobian j;
        {
          py::gil_scoped_release release;
          j = assembly::shape_jacobian(model, u);
        }
        return py::make_tuple(csc(j.force), j.energy);
      },
      py::arg("model"), py::arg("u"),
      "(csc parts of d f_int/dX, 3N x 3N; dE/dX, 3N) at fixed u, the rest values that hold "
      "the reference geometry following it");
}

}  // namespace kresling::python
