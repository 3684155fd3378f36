// kresling._core.solvers: what kresling/solvers/sensitivity.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/sensitivity.hpp"

namespace kresling::python {

namespace {

// An equilibrium's factorised tangent for sensitivities (solvers/sensitivity.hpp).
void bind_equilibrium_sensitivity(py::module_& m) {
  py::class_<solvers::EquilibriumSensitivity>(
      m, "EquilibriumSensitivity",
      "An equilibrium's tangent factorised for sensitivities (solvers/sensitivity.hpp)")
      .def(py::init([](const Model& model, const VectorX& u, const std::vector<Index>& held) {
             py::gil_scoped_release release;
             return std::make_unique<solvers::EquilibriumSensitivity>(model, u, held);
           }),
           py::arg("model"), py::arg("u"), py::arg("held"))
      .def_property_readonly("ok", &solvers::EquilibriumSensitivity::ok)
      .def_property_readonly("negative_eigenvalues",
                             &solvers::EquilibriumSensitivity::negative_eigenvalues)
      .def_property_readonly("held_dofs", &solvers::EquilibriumSensitivity::held_dofs)
      .def("update", &solvers::EquilibriumSensitivity::update, py::arg("u"),
           py::call_guard<py::gil_scoped_release>())
      .def("tangent", [](const solvers::EquilibriumSensitivity& s) { return csc(s.tangent()); })
      .def_property_readonly("internal_force", &solvers::EquilibriumSensitivity::internal_force)
      .def(
          "tangent_times",
          [](const solvers::EquilibriumSensitivity& s, const Eigen::MatrixXd& M) {
            if (M.rows() != s.tangent().cols()) {
              throw std::invalid_argument("M has " + std::to_string(M.rows()) +
                                          " rows: must have " + std::to_string(s.tangent().cols()));
            }
            return Eigen::MatrixXd(s.tangent() * M);
          },
          py::arg("M"), "K M: the tangent times a 3N x P matrix")
      .def("displacement", &solvers::EquilibriumSensitivity::displacement, py::arg("dresidual"),
           py::arg("held_motion") = Eigen::MatrixXd(), py::call_guard<py::gil_scoped_release>())
      .def("held_force", &solvers::EquilibriumSensitivity::held_force, py::arg("dforce"),
           py::arg("du"), py::call_guard<py::gil_scoped_release>())
      .def("adjoint", &solvers::EquilibriumSensitivity::adjoint, py::arg("g"),
           py::call_guard<py::gil_scoped_release>());
}

// The derivatives of a path's states in model parameters (solvers/sensitivity.hpp).
void bind_path_sensitivity(py::module_& m) {
  m.def(
      "path_sensitivity",
      [](const model::Model& model, const std::vector<VectorX>& states,
         const std::vector<double>& fractions, const std::vector<Index>& held,
         const Eigen::MatrixXd& positions, const std::vector<py::tuple>& columns,
         const Eigen::MatrixXd& drive, const py::object& knots) {
        std::vector<solvers::ColumnMotion> motions;
        for (const py::tuple& c : columns) {
          motions.push_back({c[0].cast<std::string>(), c[1].cast<std::string>(),
                             c[2].cast<Eigen::MatrixXd>()});
        }
        // knots: None, or (t, u, velocity, step_knot) of an adaptive path.
        solvers::PathKnots curves;
        const bool interpolated = !knots.is_none();
        if (interpolated) {
          const py::tuple k = knots.cast<py::tuple>();
          curves.t = k[0].cast<std::vector<double>>();
          curves.u = k[1].cast<std::vector<VectorX>>();
          curves.velocity = k[2].cast<std::vector<VectorX>>();
          curves.step_knot = k[3].cast<std::vector<int>>();
        }
        solvers::PathSensitivityResult r;
        {
          py::gil_scoped_release release;
          r = interpolated ? solvers::interpolated_path_sensitivity(model, states, fractions, curves,
                                                                    held, positions, motions, drive)
                           : solvers::path_sensitivity(model, states, fractions, held, positions,
                                                       motions, drive);
        }
        // (S, rows, P) arrays, row-major, from the per-state column-major matrices.
        auto stack = [](const std::vector<Eigen::MatrixXd>& blocks, py::ssize_t rows,
                        py::ssize_t cols) {
          py::array_t<double> out({static_cast<py::ssize_t>(blocks.size()), rows, cols});
          auto a = out.mutable_unchecked<3>();
          for (py::ssize_t k = 0; k < static_cast<py::ssize_t>(blocks.size()); ++k) {
            for (py::ssize_t i = 0; i < rows; ++i) {
              for (py::ssize_t j = 0; j < cols; ++j) a(k, i, j) = blocks[k](i, j);
            }
          }
          return out;
        };
        const py::ssize_t P = r.energy.cols();
        return py::make_tuple(r.held_dofs, stack(r.displacement, model.num_dofs(), P),
                              stack(r.held_force, static_cast<py::ssize_t>(r.held_dofs.size()), P),
                              r.energy);
      },
      py::arg("model"), py::arg("states"), py::arg("fractions"), py::arg("held"),
      py::arg("positions"), py::arg("columns"), py::arg("drive"), py::arg("knots") = py::none(),
      "(held_dofs, du/dp (S, 3N, P), held forces' derivatives (S, H, P), dE/dp (S, P)) of a "
      "path's states; with knots (t, u, velocity, step_knot), of an adaptive path's samples "
      "from its knots");
}

}  // namespace

void bind_sensitivity(py::module_& m) {
  bind_equilibrium_sensitivity(m);
  bind_path_sensitivity(m);
}

}  // namespace kresling::python
