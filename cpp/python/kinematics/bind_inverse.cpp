// kresling._core.kinematics: what kresling/kinematics/inverse.hpp declares.
#include "kinematics/kinematics_bindings.hpp"
#include "kresling/kinematics/chain.hpp"
#include "kresling/kinematics/inverse.hpp"

namespace kresling::python {

void bind_inverse(py::module_& m) {
  m.def(
      "sample_workspace",
      [](const kk::ChainModel& model, const kk::Configuration& c, double lower, double upper,
         int grid_points) {
        Eigen::MatrixX3d lengths, positions;
        {
          py::gil_scoped_release release;
          kk::sample_workspace(model, c, kk::TendonBounds{lower, upper}, grid_points, lengths,
                               positions);
        }
        return py::make_tuple(Rows3(lengths), Rows3(positions));
      },
      py::arg("model"), py::arg("configuration"), py::arg("lower"), py::arg("upper"),
      py::arg("grid_points"));
  using kk::InverseKinematicsTable;
  py::class_<InverseKinematicsTable>(
      m, "InverseKinematicsTable", "The outcomes of many inverse-kinematics solves (read-only)")
      .def_readonly("tendon_lengths", &InverseKinematicsTable::tendon_lengths,
                    "(n, 3): l1, l2, l3 [mm]")
      .def_readonly("position", &InverseKinematicsTable::position,
                    "(n, 3): the tip at those lengths [mm]")
      .def_readonly("distance", &InverseKinematicsTable::distance,
                    "(n,): distance from the target [mm]")
      .def_readonly("iterations", &InverseKinematicsTable::iterations,
                    "(n,): iterations over all starts")
      .def_readonly("converged", &InverseKinematicsTable::converged,
                    "(n,): the distance is below the tolerance");
  m.def(
      "solve_inverse_kinematics",
      [](const kk::ChainModel& model, const kk::Configuration& c,
         py::array_t<double, py::array::c_style | py::array::forcecast> targets, double lower,
         double upper, double tolerance, int max_iterations, double initial_damping,
         int grid_points, int starts) {
        const Rows3 t = as_rows3(targets, "targets");
        const kk::InverseKinematicsOptions options{tolerance, max_iterations, initial_damping,
                                                   grid_points, starts};
        std::vector<kk::InverseKinematicsResult> results;
        {
          py::gil_scoped_release release;
          results = kk::solve_inverse_kinematics_batch(model, c, t, kk::TendonBounds{lower, upper},
                                                       options);
        }
        return kk::as_table(results);
      },
      py::arg("model"), py::arg("configuration"), py::arg("targets"), py::arg("lower"),
      py::arg("upper"), py::arg("tolerance"), py::arg("max_iterations"),
      py::arg("initial_damping"), py::arg("grid_points"), py::arg("starts"),
      "Damped-least-squares inverse kinematics for (n, 3) targets [mm]; an "
      "InverseKinematicsTable (row i: target i).");
}

}  // namespace kresling::python
