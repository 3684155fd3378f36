// kresling._core.contact: what kresling/contact/contact_barrier.hpp declares.
#include "contact/contact_bindings.hpp"
#include "kresling/contact/contact_barrier.hpp"
#include "kresling/contact/contact_distance.hpp"

namespace kresling::python {

namespace {

void require_plane_normal(const Vector3& normal) {
  if (!normal.allFinite() || !(normal.norm() > 0)) {
    throw std::invalid_argument("normal: must be a finite vector of non-zero length");
  }
}

BarrierHessian barrier_hessian(bool project) {
  return project ? BarrierHessian::Projected : BarrierHessian::Exact;
}

template <int N>
py::tuple derivatives_tuple(const ScalarDerivatives<N>& f) {
  return py::make_tuple(f.value, f.gradient, f.hessian);
}

}  // namespace

void bind_contact_barrier(py::module_& m) {
  m.def(
      "point_triangle_barrier",
      [](const Vector3& p, const Vector3& t0, const Vector3& t1, const Vector3& t2, double d_hat,
         double stiffness, bool project) {
        require_finite_points({{"p", &p}, {"t0", &t0}, {"t1", &t1}, {"t2", &t2}});
        check_barrier_parameters(d_hat, stiffness);
        return derivatives_tuple(
            point_triangle_barrier(p, t0, t1, t2, d_hat, stiffness, barrier_hessian(project)));
      },
      py::arg("p"), py::arg("t0"), py::arg("t1"), py::arg("t2"), py::arg("d_hat"),
      py::arg("stiffness"), py::arg("project") = false);
  m.def(
      "edge_edge_barrier",
      [](const Vector3& ea0, const Vector3& ea1, const Vector3& eb0, const Vector3& eb1,
         double eps_x, double d_hat, double stiffness, bool project) {
        require_finite_points({{"ea0", &ea0}, {"ea1", &ea1}, {"eb0", &eb0}, {"eb1", &eb1}});
        check_barrier_parameters(d_hat, stiffness);
        require_positive("eps_x", eps_x);
        return derivatives_tuple(edge_edge_barrier(ea0, ea1, eb0, eb1, eps_x, d_hat, stiffness,
                                                   barrier_hessian(project)));
      },
      py::arg("ea0"), py::arg("ea1"), py::arg("eb0"), py::arg("eb1"), py::arg("eps_x"),
      py::arg("d_hat"), py::arg("stiffness"), py::arg("project") = false);
  m.def(
      "point_plane_barrier",
      [](const Vector3& p, const Vector3& origin, const Vector3& normal, double d_hat,
         double stiffness, bool project) {
        require_finite_points({{"p", &p}, {"origin", &origin}});
        require_plane_normal(normal);
        check_barrier_parameters(d_hat, stiffness);
        return derivatives_tuple(
            point_plane_barrier(p, origin, normal, d_hat, stiffness, barrier_hessian(project)));
      },
      py::arg("p"), py::arg("origin"), py::arg("normal"), py::arg("d_hat"), py::arg("stiffness"),
      py::arg("project") = false);
}

}  // namespace kresling::python
