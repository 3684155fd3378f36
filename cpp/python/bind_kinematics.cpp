// kresling._core.kinematics: the constant-curvature map, module transforms, the chain and
// the inverse kinematics. Arrays cross as row-major float64 (n, 3); batch work releases
// the GIL.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/kinematics/chain.hpp"
#include "kresling/kinematics/constant_curvature.hpp"
#include "kresling/kinematics/inverse.hpp"
#include "kresling/kinematics/module_transform.hpp"

namespace py = pybind11;
namespace kk = kresling::kinematics;

namespace kresling::python {

namespace {

using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

Rows3 as_rows3(const py::array_t<double, py::array::c_style | py::array::forcecast>& a,
               const char* name) {
  if (!((a.ndim() == 2 && a.shape(1) == 3) || (a.ndim() == 1 && a.shape(0) == 3))) {
    throw std::invalid_argument(std::string(name) + " must have shape (3,) or (n, 3)");
  }
  const py::ssize_t rows = a.ndim() == 1 ? 1 : a.shape(0);
  return Eigen::Map<const Rows3>(a.data(), rows, 3);
}

// Apply a (row, suffix) -> row map to every row of an (n, 3) array, without the GIL.
template <typename F>
Rows3 map_rows(const Rows3& in, F f) {
  Rows3 out(in.rows(), 3);
  py::gil_scoped_release release;
  for (Eigen::Index i = 0; i < in.rows(); ++i) {
    const std::string suffix = in.rows() > 1 ? "[" + std::to_string(i) + "]" : "";
    out.row(i) = f(Eigen::Vector3d(in.row(i).transpose()), suffix).transpose();
  }
  return out;
}

// Bind f(row, layout, suffix) -> row as a batch function over (n, 3) arrays.
using RowMap = Eigen::Vector3d (*)(const Eigen::Vector3d&, const kk::TendonLayout&,
                                   const std::string&);
void bind_row_map(py::module_& m, const char* name, RowMap f, const char* input, const char* doc) {
  m.def(
      name,
      [f, input](py::array_t<double, py::array::c_style | py::array::forcecast> rows, double d,
                 int N) {
        const kk::TendonLayout layout{d, N};
        return map_rows(as_rows3(rows, input),
                        [&](const Eigen::Vector3d& row, const std::string& suffix) {
                          return f(row, layout, suffix);
                        });
      },
      py::arg(input), py::arg("d"), py::arg("N"), doc);
}

py::array_t<double> frames_array(const std::vector<Eigen::Matrix4d>& frames) {
  py::array_t<double> out({static_cast<py::ssize_t>(frames.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto view = out.mutable_unchecked<3>();
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) view(f, r, c) = frames[f](r, c);
  return out;
}

}  // namespace

void bind_kinematics(py::module_& m) {
  py::enum_<kk::FrameConvention>(m, "FrameConvention")
      .value("jones", kk::FrameConvention::Jones)
      .value("twist_free", kk::FrameConvention::TwistFree);

  m.def("tendon_angle", &kk::tendon_angle, py::arg("i"),
        "Angle of tendon i (0-based) in a module's base frame [rad].");
  bind_row_map(m, "arc_from_tendons", &kk::arc_from_tendons, "lengths",
               "Eqns 27-29: (n, 3) tendon lengths [mm] -> (n, 3) arcs (s [mm], kappa [1/mm], "
               "phi [rad]).");
  bind_row_map(m, "tendons_from_arc", &kk::tendons_from_arc, "arcs",
               "Inverse of arc_from_tendons: (n, 3) arcs -> (n, 3) tendon lengths [mm].");
  m.def("flexible_module_transform", &kk::flexible_module_transform, py::arg("s"),
        py::arg("kappa"), py::arg("phi"), py::arg("convention"),
        "Eqn 26 (jones) or its twist-free variant: 4x4 homogeneous transform.");
  m.def("rigid_module_transform", &kk::rigid_module_transform, py::arg("length"),
        "Eqn 30: translation by length [mm] along z, 4x4.");

  m.attr("MAX_MODULES") = kk::kMaxModules;
  m.attr("MAX_BACKBONE_POINTS") = kk::kMaxBackbonePoints;
  py::class_<kk::ChainModel>(m, "ChainModel")
      .def(py::init([](int modules, double extended_length, double d, int N,
                       kk::FrameConvention convention) {
             kk::ChainModel model{modules, extended_length, kk::TendonLayout{d, N}, convention};
             kk::validate(model);
             return model;
           }),
           py::arg("modules"), py::arg("extended_length"), py::arg("d"), py::arg("N"),
           py::arg("convention"))
      .def_readonly("modules", &kk::ChainModel::modules)
      .def_readonly("extended_length", &kk::ChainModel::extended_length)
      .def_readonly("convention", &kk::ChainModel::convention);

  m.def(
      "module_arcs",
      [](const kk::ChainModel& model, const kk::Configuration& c,
         py::array_t<double, py::array::c_style | py::array::forcecast> flexible_lengths) {
        Eigen::MatrixX3d l(0, 3);
        if (flexible_lengths.size() > 0) l = as_rows3(flexible_lengths, "tendon lengths");
        return Rows3(kk::module_arcs(model, c, l));
      },
      py::arg("model"), py::arg("configuration"), py::arg("flexible_lengths"));
  m.def(
      "module_end_frames",
      [](const kk::ChainModel& model, const kk::Configuration& c, const Eigen::MatrixX3d& arcs) {
        return frames_array(kk::module_end_frames(model, c, arcs));
      },
      py::arg("model"), py::arg("configuration"), py::arg("arcs"),
      "Frames at the base and every module end, (m + 1, 4, 4).");
  m.def(
      "backbone_points",
      [](const kk::ChainModel& model, const kk::Configuration& c, const Eigen::MatrixX3d& arcs,
         int per_module) { return Rows3(kk::backbone_points(model, c, arcs, per_module)); },
      py::arg("model"), py::arg("configuration"), py::arg("arcs"), py::arg("per_module"));
  m.def(
      "markers_of_identical_modules",
      [](const kk::ChainModel& model, const kk::Configuration& c,
         py::array_t<double, py::array::c_style | py::array::forcecast> lengths) {
        const Rows3 l = as_rows3(lengths, "tendon lengths");
        const int f = kk::flexible_count(c);
        const auto m1 = static_cast<py::ssize_t>(model.modules + 1);
        py::array_t<double> out({static_cast<py::ssize_t>(l.rows()), m1, py::ssize_t{3}});
        double* o = out.mutable_data();
        py::gil_scoped_release release;
        for (Eigen::Index i = 0; i < l.rows(); ++i) {
          Eigen::MatrixX3d rows(f, 3);
          rows.rowwise() = l.row(i);
          const Eigen::MatrixX3d p =
              kk::frame_origins(kk::module_end_frames(model, c, kk::module_arcs(model, c, rows)));
          for (Eigen::Index j = 0; j < m1; ++j)
            for (int k = 0; k < 3; ++k) o[(i * m1 + j) * 3 + k] = p(j, k);
        }
        return out;
      },
      py::arg("model"), py::arg("configuration"), py::arg("lengths"),
      "Markers (n, m + 1, 3) for n tendon triples, each applied to every flexible module.");
  m.def(
      "tip_jacobian",
      [](const kk::ChainModel& model, const kk::Configuration& c, const Eigen::Vector3d& l) {
        return kk::tip_jacobian(model, c, l);
      },
      py::arg("model"), py::arg("configuration"), py::arg("lengths"));
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
