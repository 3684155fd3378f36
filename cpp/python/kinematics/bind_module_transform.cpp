// kresling._core.kinematics: what kresling/kinematics/module_transform.hpp declares.
#include "kinematics/kinematics_bindings.hpp"
#include "kresling/kinematics/module_transform.hpp"

namespace kresling::python {

void bind_module_transform(py::module_& m) {
  py::enum_<kk::FrameConvention>(m, "FrameConvention")
      .value("jones", kk::FrameConvention::Jones)
      .value("twist_free", kk::FrameConvention::TwistFree);
  m.def("flexible_module_transform", &kk::flexible_module_transform, py::arg("s"),
        py::arg("kappa"), py::arg("phi"), py::arg("convention"),
        "Eqn 26 (jones) or its twist-free variant: 4x4 homogeneous transform.");
  m.def("rigid_module_transform", &kk::rigid_module_transform, py::arg("length"),
        "Eqn 30: translation by length [mm] along z, 4x4.");
}

}  // namespace kresling::python
