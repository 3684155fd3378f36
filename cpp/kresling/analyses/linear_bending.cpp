#include "kresling/analyses/linear_bending.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include <Eigen/SparseCore>

#include "kresling/analyses/bending_test.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"

namespace kresling::analyses {

namespace {

constexpr double kPi = 3.14159265358979323846;
/// A pin this close to a vertex (in the edge parameter s) is the vertex.
constexpr double kAtVertex = 1e-12;

// Python's float modulo and floor division (the values the former Python implementation
// computed, so that the pins land on the same edges at the same parameters).
double py_mod(double x, double m) {
  double r = std::fmod(x, m);
  if (r != 0.0 && ((m < 0.0) != (r < 0.0))) r += m;
  return r;
}

double py_floordiv(double x, double m) {
  const double mod = std::fmod(x, m);
  double div = (x - mod) / m;
  if (mod != 0.0 && ((m < 0.0) != (mod < 0.0))) div -= 1.0;
  if (div == 0.0) return std::copysign(0.0, x / m);
  double floordiv = std::floor(div);
  if (div - floordiv > 0.5) floordiv += 1.0;
  return floordiv;
}

struct EdgePoint {
  int j, j1;
  double s;  ///< the point (1 - s) x_j + s x_{j1}
};

// The pin line's angle in the end polygon's frame [rad]. Every term is finite, but their
// sum can overflow (angle = pin_offset = 1e308 gives inf, and the edge index computed from
// it would be a cast of NaN, an index far outside the polygon): only then is each term
// reduced modulo 2 pi first, so every sum that is finite keeps its value bit for bit.
double pin_angle(double angle, double pin_offset, double side, double level_angle) {
  const double pin = angle + pin_offset + side - level_angle;
  if (std::isfinite(pin)) return pin;
  return py_mod(angle, 2 * kPi) + py_mod(pin_offset, 2 * kPi) + side -
         py_mod(level_angle, 2 * kPi);
}

// Where the ray at `angle` (finite) from a regular n-gon's centre (vertex 0 at angle 0)
// meets its perimeter.
EdgePoint edge_point(int n, double angle) {
  require_finite("pin angle", angle);
  const double sector = 2 * kPi / n;
  const double phi = py_mod(angle, 2 * kPi);
  const double edge = py_mod(py_floordiv(phi, sector), n);
  // phi in [0, 2 pi] puts edge in [0, n); the check keeps a rounding surprise from becoming
  // an index outside the polygon.
  if (!(edge >= 0 && edge < n)) throw_invalid("pin angle", angle, "a finite angle [rad]");
  const int j = static_cast<int>(edge);
  const double psi = phi - j * sector;
  const double s = std::sin(psi) / (std::sin(psi) + std::sin(sector - psi));
  return {j, (j + 1) % n, std::min(std::max(s, 0.0), 1.0)};
}

std::vector<int> alternating(int cells) {
  std::vector<int> chirality(cells);
  for (int i = 0; i < cells; ++i) chirality[i] = (i % 2 == 0) ? 1 : -1;
  return chirality;
}

int checked_n(int n) {
  if (n < 4 || n % 2 != 0) {
    throw_invalid("n", n,
                  "even and >= 4 for the bending test: each end is pinned along a line through "
                  "two opposite points of its polygon");
  }
  return n;
}

int checked_cells(int cells, int n) {
  check_bending_cells(n, cells);
  return cells;
}

}  // namespace

LinearBendingTest::LinearBendingTest(int n, int cells, model::SpecimenParameters parameters)
    : n_(checked_n(n)),
      cells_(checked_cells(cells, n)),
      builder_(n, alternating(cells), parameters) {}

LinearBendingResult LinearBendingTest::run(const geometry::Design& design, int state,
                                           double angle, double pin_offset) {
  if (design.parameters().n != n_) {
    throw_invalid("design.n", design.parameters().n, "this test's n = " + std::to_string(n_));
  }
  require_finite("angle", angle);
  require_finite("pin_offset", pin_offset);
  check_bending_state(design, state);
  const model::KreslingSpecimen specimen =
      builder_.build(design, std::vector<int>(static_cast<std::size_t>(cells_), state));
  const model::Model& m = specimen.model;
  if (!(workspace_ && workspace_->fits(m))) {
    workspace_ = std::make_unique<assembly::Workspace>(m, assembly::all_dofs(m.num_dofs()),
                                                       /*shift=*/0.0);
  }
  const Index num_nodes = m.num_nodes(), num_dofs = m.num_dofs();

  // u = T q: the pins eliminate nodes (held) or tie one node of an edge to the other.
  std::set<Index> held;
  std::map<Index, std::pair<Index, double>> slaves;  // slave -> (master, coefficient)
  for (int level : {0, cells_}) {
    held.insert(specimen.node(level, n_));
    for (double side : {0.0, kPi}) {
      const double pin = pin_angle(angle, pin_offset, side, specimen.level_angle[level]);
      const EdgePoint p = edge_point(n_, pin);
      const Index a = specimen.node(level, p.j), b = specimen.node(level, p.j1);
      if (p.s <= kAtVertex) {
        held.insert(a);
      } else if (p.s >= 1 - kAtVertex) {
        held.insert(b);
      } else if (p.s >= 0.5) {  // eliminate the node of the larger weight
        slaves[b] = {a, -(1 - p.s) / p.s};
      } else {
        slaves[a] = {b, -p.s / (1 - p.s)};
      }
    }
  }
  std::vector<std::vector<std::pair<Index, double>>> columns(static_cast<std::size_t>(num_dofs));
  std::vector<Index> imposed;
  Index count = 0;
  const Index middle_first = specimen.node(cells_ / 2, 0);
  const Index middle_last = specimen.node(cells_ / 2, n_);
  const double c = std::cos(angle), s = std::sin(angle);
  for (Index node = 0; node < num_nodes; ++node) {
    if (held.count(node) || slaves.count(node)) continue;
    if (node >= middle_first && node <= middle_last) {
      const Index along = count++, across = count++;
      imposed.push_back(along);
      columns[3 * node] = {{along, -s}, {across, c}};
      columns[3 * node + 1] = {{along, c}, {across, s}};
      columns[3 * node + 2] = {{count++, 1.0}};
    } else {
      for (int k = 0; k < 3; ++k) columns[3 * node + k] = {{count++, 1.0}};
    }
  }
  for (const auto& [slave, tie] : slaves) {
    for (int k = 0; k < 3; ++k) {
      auto& target = columns[3 * slave + k];
      target.clear();
      for (const auto& [col, value] : columns[3 * tie.first + k]) {
        target.emplace_back(col, tie.second * value);
      }
    }
  }
  std::vector<Eigen::Triplet<double, int>> t;
  for (Index dof = 0; dof < num_dofs; ++dof) {
    for (const auto& [col, value] : columns[dof]) t.emplace_back(dof, col, value);
  }
  solvers::SparseMatrix T(num_dofs, count);
  T.setFromTriplets(t.begin(), t.end());

  VectorX force;
  assembly::assemble(m, *workspace_, VectorX::Zero(num_dofs), force, /*with_matrix=*/true);
  const solvers::SparseMatrix K = T.transpose() * workspace_->matrix() * T;

  // Split into the free block, K_fp e and e^T K_pp e.
  std::vector<Index> free_index(static_cast<std::size_t>(count), -1);
  std::vector<std::uint8_t> is_imposed(static_cast<std::size_t>(count), 0);
  for (Index q : imposed) is_imposed[q] = 1;
  Index nf = 0;
  for (Index q = 0; q < count; ++q) {
    if (!is_imposed[q]) free_index[q] = nf++;
  }
  std::vector<Eigen::Triplet<double, int>> ff;
  VectorX Kfp_e = VectorX::Zero(nf);
  double ePe = 0.0;
  for (int col = 0; col < K.outerSize(); ++col) {
    for (solvers::SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const Index r = it.row();
      if (free_index[r] >= 0 && free_index[col] >= 0) {
        if (r >= col) ff.emplace_back(free_index[r], free_index[col], it.value());
      } else if (free_index[r] >= 0) {
        Kfp_e[free_index[r]] += it.value();
      } else if (free_index[col] < 0) {
        ePe += it.value();
      }
    }
  }
  solvers::SparseMatrix Kff(nf, nf);
  Kff.setFromTriplets(ff.begin(), ff.end());
  Kff.makeCompressed();
  // A new pattern (the pins moved to other edges) needs a new plan.
  const std::vector<int> outer(Kff.outerIndexPtr(), Kff.outerIndexPtr() + nf + 1);
  const std::vector<int> inner(Kff.innerIndexPtr(), Kff.innerIndexPtr() + Kff.nonZeros());
  if (!solver_ || outer != pattern_outer_ || inner != pattern_inner_) {
    solver_ = std::make_unique<solvers::TangentSolver>();
    pattern_outer_ = outer;
    pattern_inner_ = inner;
  }
  LinearBendingResult result;
  result.module_length = 2.0 * design.height(static_cast<geometry::State>(state));
  const solvers::FactorizeInfo info = solver_->factorize(Kff);
  // At a stress-free state K is positive semi-definite: a free block that is not positive
  // definite (LDL^T finds negative pivots, or only LU factorises it) is a mechanism or
  // singular to working precision, and its Schur complement would be rounding noise.
  if (!info.ok || info.negative_eigenvalues != 0) {
    result.condensed_force = result.stiffness = std::numeric_limits<double>::quiet_NaN();
    return result;
  }
  // F = e^T K_pp e - b^T u cancels: e^T K_pp e is up to ~1e4 F (the bars are 1e5 times
  // stiffer than the hinges) and K_ff's condition number reaches ~1e6, so a plain solve
  // leaves ~1e-10 of F to rounding. One step of iterative refinement brings u to working
  // accuracy and F to ~eps e^T K_pp e (~1e-12 relative).
  VectorX u_free = solver_->solve(Kfp_e);
  const solvers::SparseMatrix Kff_full = Kff.selfadjointView<Eigen::Lower>();
  const VectorX residual = Kfp_e - Kff_full * u_free;
  u_free += solver_->solve(residual);
  result.condensed_force = ePe - Kfp_e.dot(u_free);
  result.cancelled = ePe;
  const double L = result.module_length;
  result.stiffness = result.condensed_force * L * L * 1e-3;
  return result;
}

}  // namespace kresling::analyses
