// kresling._core.solvers: what kresling/solvers/path.hpp declares.
#include "solvers/solvers_bindings.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/sensitivity.hpp"

namespace kresling::python {

namespace {

// One per-step quantity of a path as a (steps,) or (steps, k) numpy array.
template <typename Get>
VectorX per_step(const PathResult& r, Get&& get) {
  VectorX out(static_cast<Index>(r.steps.size()));
  for (std::size_t k = 0; k < r.steps.size(); ++k) out[static_cast<Index>(k)] = get(r.steps[k]);
  return out;
}

template <typename Get>
RowMatrix per_step_rows(const PathResult& r, Index width, Get&& get) {
  RowMatrix out(static_cast<Index>(r.steps.size()), width);
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    out.row(static_cast<Index>(k)) = get(r.steps[k]).transpose();
  }
  return out;
}

template <typename Get>
RowMatrix knot_rows(const PathResult& r, Get&& get) {
  const Index n = r.knots.empty() ? 0 : r.knots.front().u.size();
  RowMatrix out(static_cast<Index>(r.knots.size()), n);
  for (std::size_t j = 0; j < r.knots.size(); ++j) out.row(static_cast<Index>(j)) = get(r.knots[j]).transpose();
  return out;
}

// The path every solver returns, bound field by field: the Python PathResult reads these
// (kresling/solvers/path.py documents them).
void bind_path_result(py::module_& m) {
  py::class_<PathResult>(m, "PathResult")
      .def_property_readonly("load_factor", [](const PathResult& r) {
        return per_step(r, [](const PathStep& s) { return s.load_factor; });
      })
      .def_property_readonly("displacement", [](const PathResult& r) {
        const Index n = r.steps.empty() ? 0 : r.steps.front().displacement.size();
        return per_step_rows(r, n, [](const PathStep& s) -> const VectorX& { return s.displacement; });
      })
      .def_property_readonly("constraint_dofs", [](const PathResult& r) { return r.constraint_dofs; })
      .def_property_readonly("constraint_force", [](const PathResult& r) {
        return per_step_rows(r, static_cast<Index>(r.constraint_dofs.size()),
                             [](const PathStep& s) -> const VectorX& { return s.constraint_force; });
      })
      .def_readonly("families", &PathResult::families)
      .def_property_readonly("energies", [](const PathResult& r) {
        return per_step_rows(r, static_cast<Index>(r.families.size()),
                             [](const PathStep& s) -> const VectorX& { return s.energies; });
      })
      .def_property_readonly("iterations", [](const PathResult& r) {
        Eigen::VectorXi out(static_cast<Index>(r.steps.size()));
        for (std::size_t k = 0; k < r.steps.size(); ++k) out[k] = r.steps[k].iterations;
        return out;
      })
      .def_property_readonly("negative_eigenvalues", [](const PathResult& r) {
        Eigen::VectorXi out(static_cast<Index>(r.steps.size()));
        for (std::size_t k = 0; k < r.steps.size(); ++k) out[k] = r.steps[k].negative_eigenvalues;
        return out;
      })
      .def_property_readonly("snapped", [](const PathResult& r) {
        Eigen::Matrix<bool, Eigen::Dynamic, 1> out(static_cast<Index>(r.steps.size()));
        for (std::size_t k = 0; k < r.steps.size(); ++k) out[k] = r.steps[k].snapped;
        return out;
      })
      .def_readonly("completed", &PathResult::completed)
      .def_readonly("message", &PathResult::message)
      .def_readonly("failed_increment", &PathResult::failed_increment)
      .def_readonly("attempted_increments", &PathResult::attempted_increments)
      .def_readonly("newton_iterations", &PathResult::newton_iterations)
      // The knots of an adaptive path (empty arrays when none were kept).
      .def_property_readonly("knot_t", [](const PathResult& r) {
        VectorX out(static_cast<Index>(r.knots.size()));
        for (std::size_t j = 0; j < r.knots.size(); ++j) out[static_cast<Index>(j)] = r.knots[j].t;
        return out;
      })
      .def_property_readonly("knot_displacement", [](const PathResult& r) {
        return knot_rows(r, [](const PathKnot& k) -> const VectorX& { return k.u; });
      })
      .def_property_readonly("knot_velocity", [](const PathResult& r) {
        return knot_rows(r, [](const PathKnot& k) -> const VectorX& { return k.velocity; });
      })
      .def_property_readonly("step_knot", [](const PathResult& r) {
        return Eigen::Map<const Eigen::VectorXi>(r.step_knot.data(),
                                                 static_cast<Index>(r.step_knot.size()))
            .eval();
      });
}

}  // namespace

void bind_path(py::module_& m) {
  bind_path_result(m);
}

}  // namespace kresling::python
