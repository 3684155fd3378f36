// kresling._core.kinematics: what kresling/kinematics/chain.hpp declares.
#include "kinematics/kinematics_bindings.hpp"
#include "kresling/kinematics/chain.hpp"
#include "kresling/kinematics/constant_curvature.hpp"
#include "kresling/kinematics/module_transform.hpp"

namespace kresling::python {

namespace {

py::array_t<double> frames_array(const std::vector<Eigen::Matrix4d>& frames) {
  py::array_t<double> out({static_cast<py::ssize_t>(frames.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto view = out.mutable_unchecked<3>();
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) view(f, r, c) = frames[f](r, c);
  return out;
}

// Markers (n, m + 1, 3) for n tendon triples, each applied to every flexible module.
py::array_t<double> markers_of_identical_modules(
    const kk::ChainModel& model, const kk::Configuration& c,
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
}

}  // namespace

void bind_chain(py::module_& m) {
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
      &markers_of_identical_modules,
      py::arg("model"), py::arg("configuration"), py::arg("lengths"),
      "Markers (n, m + 1, 3) for n tendon triples, each applied to every flexible module.");
  m.def(
      "tip_jacobian",
      [](const kk::ChainModel& model, const kk::Configuration& c, const Eigen::Vector3d& l) {
        return kk::tip_jacobian(model, c, l);
      },
      py::arg("model"), py::arg("configuration"), py::arg("lengths"));
}

}  // namespace kresling::python
