#include "kresling/solvers/path_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "kresling/elements/dihedral.hpp"

namespace kresling::solvers {

std::vector<signed char> law_pieces(const model::Model& model, const VectorX& u) {
  const auto& hinges = model.hinges();
  std::vector<signed char> pieces(hinges.size(), 0);
  const NodeMatrix& X = model.nodes();
  auto at = [&](Index node) -> Vector3 {
    return X.row(node).transpose() + u.segment<3>(3 * node);
  };
  for (std::size_t h = 0; h < hinges.size(); ++h) {
    const model::Hinge& hinge = hinges[h];
    if (hinge.law.kind != elements::SpringLawKind::EnhancedLinear || hinge.stiffness == 0.0) {
      continue;
    }
    const auto& n = hinge.nodes;
    const double theta =
        elements::dihedral_angle(at(n[0]), at(n[1]), at(n[2]), at(n[3]), hinge.form);
    pieces[h] = theta < hinge.law.theta1 ? -1 : theta > hinge.law.theta2 ? 1 : 0;
  }
  // Cables are tension-only: taut or slack, their kink at the rest length.
  for (const model::Cable& cable : model.cables()) {
    double length = 0.0;
    for (std::size_t k = 1; k < cable.nodes.size(); ++k) {
      length += (at(cable.nodes[k]) - at(cable.nodes[k - 1])).norm();
    }
    pieces.push_back(length > cable.rest_length ? 1 : 0);
  }
  return pieces;
}

// For each hinge whose piece differs, a Newton step on theta(t) = limit from each end
// (exact dtheta/dt there: its gradient times the path tangent; the law's M and dM/dtheta
// are continuous at its limits, so theta(t) is smooth to second order across).
double predicted_kink(const model::Model& model, const PathPoint& a, const PathPoint& e) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (a.negative != e.negative || a.pieces.size() != e.pieces.size()) return none;
  const NodeMatrix& X = model.nodes();
  // theta - limit and its rate at p for hinge h.
  auto offset = [&](const PathPoint& p, const model::Hinge& hinge, double limit) {
    auto at = [&](Index node) -> Vector3 {
      return X.row(node).transpose() + p.u.segment<3>(3 * node);
    };
    const auto& n = hinge.nodes;
    const elements::DihedralDerivatives d = elements::dihedral_angle_derivatives(
        at(n[0]), at(n[1]), at(n[2]), at(n[3]), /*with_hessian=*/false, hinge.form);
    double rate = 0.0;
    for (int j = 0; j < 4; ++j) {
      rate += d.gradient.segment<3>(3 * j).dot(p.velocity.segment<3>(3 * n[j]));
    }
    return std::make_pair(d.angle - limit, rate);
  };
  double first = none;
  for (std::size_t h = 0; h < model.hinges().size(); ++h) {  // the cables' are bisected
    const int from = a.pieces[h], to = e.pieces[h];
    if (from == to) continue;
    const model::Hinge& hinge = model.hinges()[h];
    // The limit next to a's piece on e's side.
    const double limit = to > from ? (from < 0 ? hinge.law.theta1 : hinge.law.theta2)
                                   : (from > 0 ? hinge.law.theta2 : hinge.law.theta1);
    const auto [ga, ra] = offset(a, hinge, limit);
    const auto [ge, re] = offset(e, hinge, limit);
    const double from_a = a.t - ga / ra, from_e = e.t - ge / re;
    const bool a_ok = from_a > a.t && from_a < e.t, e_ok = from_e > a.t && from_e < e.t;
    double t = none;
    if (a_ok && e_ok) {
      t = (from_a - a.t <= e.t - from_e) ? from_a : from_e;
    } else if (a_ok) {
      t = from_a;
    } else if (e_ok) {
      t = from_e;
    }
    if (std::isfinite(t) && !(t >= first)) first = t;  // the smallest (first is NaN at first)
  }
  return first;
}

bool path_derivatives(assembly::Assembler& assembler, assembly::Assembler& full,
                      const TangentSolver& solver, PathControl& control,
                      const std::vector<Index>& recorded, double sign, PathPoint& p) {
  VectorX force;
  const assembly::Energies energies = full.assemble(p.u, force, /*with_matrix=*/true);
  p.force.resize(static_cast<Index>(recorded.size()));
  for (std::size_t k = 0; k < recorded.size(); ++k) {
    p.force[static_cast<Index>(k)] = sign * force[recorded[k]];
  }
  p.energy = energies.vector();
  if (!p.force.allFinite() || !p.energy.allFinite()) return false;
  const ControlRates rates = control.rates(p.t, p.u);
  if (!rates.held.allFinite() || !rates.internal.allFinite() || !rates.external.allFinite() ||
      !rates.energies.allFinite()) {
    return false;
  }
  const auto K = full.matrix().selfadjointView<Eigen::Lower>();
  VectorX direction = rates.held;
  VectorX force_rate(static_cast<Index>(recorded.size()));
  for (int round = 0; round < 6; ++round) {
    // df_int/dt along the path: K v, plus the model's own change at fixed u.
    VectorX product = K * direction;
    if (rates.internal.size()) product += rates.internal;
    for (std::size_t k = 0; k < recorded.size(); ++k) {
      force_rate[static_cast<Index>(k)] = sign * product[recorded[k]];
    }
    if (round > 1 && (force_rate - p.force_rate).lpNorm<Eigen::Infinity>() <=
                         1e-10 * force_rate.lpNorm<Eigen::Infinity>()) {
      break;
    }
    p.force_rate = force_rate;
    // The rate of the residual f_int - f_ext, to be cancelled at the free rows.
    if (rates.external.size()) product -= rates.external;
    const VectorX correction = solver.solve(VectorX(-gather_rows(assembler, product)));
    if (!correction.allFinite()) return false;
    scatter_add_rows(assembler, correction, direction);
  }
  p.force_rate = force_rate;
  p.velocity = direction;
  p.energy_rate = assembly::energy_rates(full.model(), p.u, direction);
  if (rates.energies.size()) p.energy_rate += rates.energies;
  return p.force_rate.allFinite() && p.energy_rate.allFinite();
}

}  // namespace kresling::solvers
