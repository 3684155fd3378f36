#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "kresling/core/check.hpp"
#include "kresling/elements/bar.hpp"
#include "kresling/elements/contact_barrier.hpp"
#include "kresling/elements/contact_barrier_stiffness.hpp"
#include "kresling/elements/contact_broad_phase.hpp"
#include "kresling/elements/contact_ccd.hpp"
#include "kresling/elements/contact_distance.hpp"
#include "kresling/elements/contact_mollifier.hpp"
#include "kresling/elements/corner_angle.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"
#include "kresling/elements/spring_laws.hpp"
#include "kresling/model/model.hpp"

namespace py = pybind11;
using namespace kresling::elements;

namespace kresling::python {

namespace {

// The contact kernels take positions as they are; from Python, check them first.
void require_finite_points(std::initializer_list<std::pair<const char*, const Vector3*>> points) {
  for (const auto& [name, p] : points) {
    if (!p->allFinite()) {
      throw std::invalid_argument(std::string(name) + ": every coordinate must be finite");
    }
  }
}

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

EdgeMatrix pair_rows(const std::vector<std::array<Index, 2>>& pairs) {
  EdgeMatrix rows(static_cast<Index>(pairs.size()), 2);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    rows(static_cast<Index>(k), 0) = pairs[k][0];
    rows(static_cast<Index>(k), 1) = pairs[k][1];
  }
  return rows;
}

CcdOptions ccd_options(double min_distance, double t_max, double conservative_rescaling) {
  CcdOptions o;
  o.min_distance = min_distance;
  o.t_max = t_max;
  o.conservative_rescaling = conservative_rescaling;
  check_ccd_options(o);
  return o;
}

using Rows4 = Eigen::Matrix<double, 4, 3, Eigen::RowMajor>;
using FourNodeCcd = TimeOfImpact (*)(const Vector3&, const Vector3&, const Vector3&,
                                     const Vector3&, const Vector3&, const Vector3&,
                                     const Vector3&, const Vector3&, const CcdOptions&);

// A four-node CCD kernel on the rows of (4, 3) arrays of start and end positions.
py::tuple ccd_tuple(FourNodeCcd kernel, const Rows4& start, const Rows4& end,
                    const CcdOptions& options) {
  if (!start.allFinite() || !end.allFinite()) {
    throw std::invalid_argument("start, end: every coordinate must be finite");
  }
  const Vector3 a0 = start.row(0), a1 = start.row(1), a2 = start.row(2), a3 = start.row(3);
  const Vector3 b0 = end.row(0), b1 = end.row(1), b2 = end.row(2), b3 = end.row(3);
  const auto r = kernel(a0, a1, a2, a3, b0, b1, b2, b3, options);
  return py::make_tuple(r.impact, r.toi);
}

// Contact kernels: distances, barriers, the initial stiffness, CCD and the broad phase.
void bind_contact(py::module_& m) {
  m.def(
      "point_triangle_distance",
      [](const Vector3& p, const Vector3& t0, const Vector3& t1, const Vector3& t2) {
        require_finite_points({{"p", &p}, {"t0", &t0}, {"t1", &t1}, {"t2", &t2}});
        const auto d = point_triangle_distance(p, t0, t1, t2);
        return py::make_tuple(d.value, d.gradient, d.hessian,
                              static_cast<int>(point_triangle_distance_type(p, t0, t1, t2)));
      },
      py::arg("p"), py::arg("t0"), py::arg("t1"), py::arg("t2"));
  m.def(
      "edge_edge_distance",
      [](const Vector3& ea0, const Vector3& ea1, const Vector3& eb0, const Vector3& eb1) {
        require_finite_points({{"ea0", &ea0}, {"ea1", &ea1}, {"eb0", &eb0}, {"eb1", &eb1}});
        const auto d = edge_edge_distance(ea0, ea1, eb0, eb1);
        return py::make_tuple(d.value, d.gradient, d.hessian,
                              static_cast<int>(edge_edge_distance_type(ea0, ea1, eb0, eb1)));
      },
      py::arg("ea0"), py::arg("ea1"), py::arg("eb0"), py::arg("eb1"));
  m.def("edge_edge_mollifier_threshold", &edge_edge_mollifier_threshold, py::arg("ea0_rest"),
        py::arg("ea1_rest"), py::arg("eb0_rest"), py::arg("eb1_rest"));
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
  m.def(
      "initial_barrier_stiffness",
      [](double bbox_diagonal, double d_hat, double average_mass, const VectorX& energy_gradient,
         const VectorX& barrier_gradient, double min_stiffness_scale) {
        const auto k = initial_barrier_stiffness(bbox_diagonal, d_hat, average_mass,
                                                 energy_gradient, barrier_gradient,
                                                 min_stiffness_scale);
        return py::make_tuple(k.stiffness, k.min_stiffness, k.max_stiffness);
      },
      py::arg("bbox_diagonal"), py::arg("d_hat"), py::arg("average_mass"),
      py::arg("energy_gradient"), py::arg("barrier_gradient"),
      py::arg("min_stiffness_scale") = 1e11);
  m.def(
      "point_triangle_ccd",
      [](const Rows4& start, const Rows4& end, double min_distance, double t_max,
         double conservative_rescaling) {
        return ccd_tuple(&point_triangle_ccd, start, end,
                         ccd_options(min_distance, t_max, conservative_rescaling));
      },
      py::arg("start"), py::arg("end"), py::arg("min_distance") = 0.0, py::arg("t_max") = 1.0,
      py::arg("conservative_rescaling") = 0.9);
  m.def(
      "edge_edge_ccd",
      [](const Rows4& start, const Rows4& end, double min_distance, double t_max,
         double conservative_rescaling) {
        return ccd_tuple(&edge_edge_ccd, start, end,
                         ccd_options(min_distance, t_max, conservative_rescaling));
      },
      py::arg("start"), py::arg("end"), py::arg("min_distance") = 0.0, py::arg("t_max") = 1.0,
      py::arg("conservative_rescaling") = 0.9);
  m.def("triangle_edges", &triangle_edges, py::arg("triangles"));
  m.def(
      "contact_candidates",
      [](const Eigen::Ref<const NodeMatrix>& nodes,
         const Eigen::Ref<const TriangleMatrix>& triangles,
         double distance, std::optional<NodeMatrix> displacement) {
        const EdgeMatrix edges = triangle_edges(triangles);
        check_contact_mesh(nodes, triangles, edges, distance);
        if (displacement && !displacement->allFinite()) {
          throw std::invalid_argument("displacement: every coordinate must be finite");
        }
        const auto c = displacement
                           ? contact_candidates(nodes, triangles, edges, distance, *displacement)
                           : contact_candidates(nodes, triangles, edges, distance);
        return py::make_tuple(pair_rows(c.point_triangle), pair_rows(c.edge_edge), edges);
      },
      py::arg("nodes"), py::arg("triangles"), py::arg("distance"),
      py::arg("displacement") = py::none());
}

}  // namespace

void bind_elements(py::module_& m) {
  // The law kinds, named as the Python API names them (kresling.laws derives its tables
  // from these: the names and codes are declared here once).
  py::enum_<BarLawKind>(m, "BarLawKind")
      .value("linear", BarLawKind::Linear)
      .value("ogden", BarLawKind::Ogden);
  py::enum_<SpringLawKind>(m, "SpringLawKind")
      .value("linear", SpringLawKind::Linear)
      .value("enhanced_linear", SpringLawKind::EnhancedLinear)
      .value("super_linear_bend", SpringLawKind::SuperLinearBend);
  py::enum_<DihedralForm>(m, "DihedralForm")
      .value("exact", DihedralForm::Exact)
      .value("merlin2", DihedralForm::Merlin2);
  m.def(
      "dihedral_angle",
      [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d,
         DihedralForm form) { return dihedral_angle(a, b, c, d, form); },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
      py::arg("form") = DihedralForm::Exact);
  m.def(
      "dihedral_angle_derivatives",
      [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d,
         DihedralForm form) {
        const auto r = dihedral_angle_derivatives(a, b, c, d, true, form);
        return py::make_tuple(r.angle, r.gradient, r.hessian);
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
      py::arg("form") = DihedralForm::Exact);
  m.def(
      "dihedral_angles",
      [](const Eigen::Ref<const NodeMatrix>& x,
         py::array_t<Index, py::array::c_style | py::array::forcecast> hinges,
         DihedralForm form) {
        if (hinges.ndim() != 2 || hinges.shape(1) != 4) {
          throw std::invalid_argument("hinges: expected shape (n, 4)");
        }
        auto h = hinges.unchecked<2>();
        VectorX out(h.shape(0));
        const NodeMatrix X(x);
        const double scale = model::node_extent(X);  // once, not per hinge
        for (py::ssize_t i = 0; i < h.shape(0); ++i) {
          model::check_hinge_geometry_at_scale(X, {h(i, 0), h(i, 1), h(i, 2), h(i, 3)},
                                               static_cast<std::size_t>(i), scale);
          out[i] = dihedral_angle(x.row(h(i, 0)), x.row(h(i, 1)), x.row(h(i, 2)),
                                  x.row(h(i, 3)), form);
        }
        return out;
      },
      py::arg("nodes"), py::arg("hinges"), py::arg("form") = DihedralForm::Exact);
  m.def(
      "triangle_angles",
      [](const Eigen::Ref<const NodeMatrix>& x,
         py::array_t<Index, py::array::c_style | py::array::forcecast> triangles) {
        if (triangles.ndim() != 2 || triangles.shape(1) != 3) {
          throw std::invalid_argument("triangles: expected shape (n, 3)");
        }
        auto t = triangles.unchecked<2>();
        NodeMatrix out(t.shape(0), 3);
        for (py::ssize_t i = 0; i < t.shape(0); ++i) {
          for (int k = 0; k < 3; ++k) {
            if (t(i, k) < 0 || t(i, k) >= x.rows()) {
              throw std::invalid_argument("triangles[" + std::to_string(i) + "]: node " +
                                          std::to_string(t(i, k)) + " is out of range [0, " +
                                          std::to_string(x.rows()) + ")");
            }
          }
          const auto a = corner_angles(x.row(t(i, 0)), x.row(t(i, 1)), x.row(t(i, 2)));
          out.row(i) << a[0], a[1], a[2];
        }
        return out;
      },
      py::arg("nodes"), py::arg("triangles"),
      "Interior angles [rad] of triangles (n, 3) of nodes (N, 3): (n, 3), at each corner");
  m.def(
      "bar_response",
      [](const Vector3& x1, const Vector3& x2, double area, double rest_length, int law,
         double modulus) {
        const auto r = bar_response(x1, x2, area, rest_length,
                                    BarLaw{bar_law_kind(law, "law"), modulus}, true);
        return py::make_tuple(r.energy, r.force, r.stiffness);
      },
      py::arg("x1"), py::arg("x2"), py::arg("area"), py::arg("rest_length"), py::arg("law"),
      py::arg("modulus"));
  m.def(
      "hinge_response",
      [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d, double kp,
         double rest_angle, double length, int law, double theta1, double theta2) {
        const auto r = hinge_response(a, b, c, d, kp, rest_angle, length,
                                      SpringLaw{spring_law_kind(law, "law"), theta1, theta2});
        return py::make_tuple(r.energy, r.force, r.stiffness, r.angle, r.moment);
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::arg("stiffness"),
      py::arg("rest_angle"), py::arg("length"), py::arg("law"), py::arg("theta1"),
      py::arg("theta2"));
  m.def(
      "spring_law",
      [](int law, double theta, double rest_angle, double stiffness, double theta1, double theta2) {
        const auto r = SpringLaw{spring_law_kind(law, "law"), theta1, theta2}.evaluate(
            theta, rest_angle, stiffness);
        return py::make_tuple(r.moment, r.stiffness, r.energy);
      },
      py::arg("law"), py::arg("theta"), py::arg("rest_angle"), py::arg("stiffness"),
      py::arg("theta1"), py::arg("theta2"));
  bind_contact(m);
}

}  // namespace kresling::python
